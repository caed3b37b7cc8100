#!/usr/bin/env bash
# The GPU cull under a sustained load (docs/perf.md, "Under a sustained load"): gpu_cull_bench's
# GPU pass, its iterations back to back as in a game's frame loop, for every size from 1M to 16M
# instances, with the SM clock, power and utilization logged every 100 ms beside it (the H100's and
# H200's governor runs a light, intermittent load at 345-510 MHz and a busy GPU at 1980 MHz).
# Never change the card's clocks (no nvidia-smi -lgc).
# Usage, on the device machine: scripts/device/cull-sustained.sh DIR
#   DIR holds gpu_cull_bench and lib/ (its shared libraries and libvulkan.so.1 from the dev
#   machine; the glvnd libraries installed, docs/gpu_cull.md "To rerun there").
# Writes $OUT/sustained.json (Google Benchmark's JSON, counter gpu_ms: the pass by GPU
# timestamps), $OUT/clocks.csv and $OUT/phases.txt.
set -u
D=${1:?folder with gpu_cull_bench and lib/}
export LD_LIBRARY_PATH=$D/lib
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv
nvidia-smi --query-gpu=timestamp,clocks.sm,power.draw,utilization.gpu --format=csv,noheader -lms 100 >"$OUT/clocks.csv" &
clock_log=$!
echo "$(date '+%H:%M:%S.%N') start" >"$OUT/phases.txt"
timeout 540 "$D/gpu_cull_bench" --benchmark_filter='BM_GpuCull/[0-9]{7,8}/' --benchmark_min_time=2 \
  --benchmark_repetitions=3 --benchmark_out="$OUT/sustained.json" 2>&1 | grep -E "_median|^Benchmark"
echo "$(date '+%H:%M:%S.%N') end" >>"$OUT/phases.txt"
kill $clock_log
true
