#!/usr/bin/env bash
# The GPU-cull measurements of docs/perf.md ("GPU clock, not the pass"), run on the device machine
# from a folder holding before/lintel, after/lintel and lib/ (the binaries' shared libraries, from
# the dev machine), with the Vulkan loader and glvnd libraries installed (docs/gpu_cull.md, "To
# rerun there"). Results go to $OUT. The SM clock is logged every 50 ms alongside: the H100's
# governor runs this light load at 345-510 MHz and boosts to 1980 MHz for about 4 s after a
# process creates its Vulkan device, so the per-size runs (one process each) are the fixed-clock
# figures. Never change the card's clocks (no nvidia-smi -lgc).
# Usage: scripts/device/cull-h100.sh DIR
set -u
D=${1:?folder with before/, after/ and lib/}
export LD_LIBRARY_PATH=$D/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv
nvidia-smi --query-gpu=timestamp,clocks.sm,power.draw,utilization.gpu --format=csv,noheader -lms 50 >"$OUT/clocks.csv" &
clock_log=$!
log() { echo "$(date '+%Y/%m/%d %H:%M:%S.%N') $*" >>"$OUT/phases.txt"; }
sizes="1000000 2000000 3000000 4000000 8000000 16000000"
for v in before after; do
  log "$v all sizes"
  timeout 150 "$D/$v/lintel" bench cull --instances "${sizes// /,}" --frames synthetic,indoor --threads 2 \
    --repetitions 15 --out "$OUT/bench-cull-h100-$v.json" >"$OUT/$v.txt" 2>&1
done
for v in before after; do for f in synthetic indoor; do for n in $sizes; do
  log "$v $f $n one process"
  timeout 60 "$D/$v/lintel" bench cull --frames $f --threads 2 --repetitions 15 --instances $n 2>&1 |
    grep "gpu " >>"$OUT/one-size-$v.txt"
done; done; done
log end
kill $clock_log
cat "$OUT"/one-size-*.txt
