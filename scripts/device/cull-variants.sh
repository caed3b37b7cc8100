#!/usr/bin/env bash
# The GPU cull pass variants on the device machine (docs/perf.md, "Append mode on the H100"), one
# process each (the H100 boosts for a few seconds after a process creates its device: docs/perf.md,
# "GPU clock, not the pass"), two rounds: at 1M instances every append mode, cell order and
# straddler path on the synthetic frame; then each append mode (straddlers inline, cells by
# group) on both frames at 1M, 4M and 16M. Run from the repository root with the binary at
# .rdev/lintel_new and its libraries in .rdev/lib (docs/gpu_cull.md, "To rerun there").
set -u
export LD_LIBRARY_PATH=$PWD/.rdev/lib
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
run() {  # frame instances append order straddlers
  timeout 60 .rdev/lintel_new bench cull --frames "$1" --instances "$2" --threads 2 --repetitions 15 --append "$3" \
    --cell-order "$4" --straddlers "$5" 2>&1 | grep -E "^(synthetic|indoor) +gpu" | head -1 | sed 's/  */ /g'
}
for round in 1 2; do
  for a in workgroup subgroup atomic; do for o in group id; do for s in inline deferred; do
    echo "$round synthetic 1000000 $a $o $s: $(run synthetic 1000000 $a $o $s)"
  done; done; done
done
for round in 1 2; do
  for f in synthetic indoor; do for n in 1000000 4000000 16000000; do for a in workgroup subgroup atomic; do
    echo "$round $f $n $a group inline: $(run $f $n $a group inline)"
  done; done; done
done
