#!/usr/bin/env bash
# A/B of GPU cull builds on the device machine: each binary .rdev/lintel_NAME (NAMEs as
# arguments) culls each "FRAME:INSTANCES" point of $POINTS in its own process, binaries
# alternating within each of $ROUNDS rounds, so every timed run falls inside the boost window the
# H100 gives a process that creates a Vulkan device (docs/perf.md, "GPU clock, not the pass").
# The SM clock is logged to $OUT/clocks.csv to check that, and each run's JSON kept there as
# NAME-FRAME-INSTANCES-rROUND.json. Prints one line per run:
#   round name frame instances: <lintel bench cull's gpu row>
# Usage (from the repository root, libraries in .rdev/lib): scripts/device/cull-ab.sh base new ...
set -u
export LD_LIBRARY_PATH=$PWD/.rdev/lib
POINTS=${POINTS:-"synthetic:1000000 indoor:4000000 indoor:16000000"}
ROUNDS=${ROUNDS:-2}
nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
[ -n "${OUT:-}" ] && { nvidia-smi --query-gpu=timestamp,clocks.sm --format=csv,noheader -lms 100 >"$OUT/clocks.csv" & }
for round in $(seq "$ROUNDS"); do
  for point in $POINTS; do
    for name in "$@"; do
      json=()
      [ -n "${OUT:-}" ] && json=(--out "$OUT/$name-${point%%:*}-${point##*:}-r$round.json")
      row=$(timeout 90 ".rdev/lintel_$name" bench cull --frames "${point%%:*}" --instances "${point##*:}" \
        --threads 2 --repetitions 15 "${json[@]}" 2>&1 | grep -E "^(synthetic|indoor) +gpu" | head -1 | sed 's/  */ /g')
      echo "$round $name ${point%%:*} ${point##*:}: $row"
    done
  done
done
[ -n "${OUT:-}" ] && kill %1 2>/dev/null
true
