#!/usr/bin/env python3
"""A/B of the scene loader's time on imported Doom maps between two lintel binaries, run
alternately (so both see the same machine load): each round runs `lintel bench levels --maps
MAPS --views 1 --resolution 8` once per binary and reads every map's `load_ms` (the time of
load_world_from_memory on the imported GLB; the scoring is cut to the minimum, it is not timed).
Prints, per map and binary, the median and range over the rounds, and the load average.

  scripts/levels/load_ab.py BEFORE AFTER [--rounds N] [--maps E1M5 E4M7] [--sectors convex]

Used by docs/levels.md ("Load after parsing the JSON once")."""
import argparse
import json
import os
import statistics
import subprocess
import tempfile

ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument('before')
ap.add_argument('after')
ap.add_argument('--rounds', type=int, default=11)
ap.add_argument('--maps', nargs='+', default=['E1M5', 'E4M7'])
ap.add_argument('--sectors', default='convex', choices=['convex', 'whole'])
ap.add_argument('--wad', default='/usr/share/games/doom/freedoom1.wad')
a = ap.parse_args()

binaries = {'before': os.path.abspath(a.before), 'after': os.path.abspath(a.after)}
load_ms = {}  # (map, label) -> [ms per round]
loads = []
with tempfile.TemporaryDirectory() as tmp:
    for r in range(a.rounds):
        # Alternate which binary goes first, so neither always runs after the other.
        order = list(binaries.items()) if r % 2 == 0 else list(reversed(binaries.items()))
        for label, binary in order:
            out = os.path.join(tmp, f'{label}-{r}')
            subprocess.run([binary, 'bench', 'levels', '--wad', a.wad, '--maps', *a.maps, '--views', '1',
                            '--resolution', '8', '--sectors', a.sectors, '--out', out],
                           check=True, capture_output=True)
            with open(os.path.join(out, 'levels.json')) as f:
                for row in json.load(f)['maps']:
                    load_ms.setdefault((row['map'], label), []).append(row['load_ms'])
        loads.append(os.getloadavg()[0])

print(f'{a.rounds} rounds, load average (1 min) {min(loads):.2f}..{max(loads):.2f}, '
      f'median {statistics.median(loads):.2f}')
for m in a.maps:
    for label in binaries:
        v = load_ms[(m, label)]
        print(f'{m:6s} {label:6s} load median {statistics.median(v):6.1f} ms  ({min(v):.1f}..{max(v):.1f})')
