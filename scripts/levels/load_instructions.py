#!/usr/bin/env python3
"""The loader's instruction budget: imports a Freedoom map with the CLI's defaults, counts the
instructions of `lintel validate -q` on it under valgrind (callgrind: exact and repeatable, unlike
a clock on a shared machine) and exits 1 when the count is over the budget. A benchmark check, not
a test: run it by hand after touching the loader (scene/src/read/).

  scripts/levels/load_instructions.py [LINTEL] [--map E1M5] [--budget 0.7e9]

The budget of 0.7 G for E1M5 is the loader of 2026-11-27 (0.57 G: the JSON parsed once, the
accessors and meshes without a DOM) plus about 20 %; the loader that parsed the JSON twice took
2.12 G (docs/levels.md, "Load after parsing the JSON once")."""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument('lintel', nargs='?', default='build/bin/lintel')
ap.add_argument('--map', default='E1M5')
ap.add_argument('--wad', default='/usr/share/games/doom/freedoom1.wad')
ap.add_argument('--budget', type=float, default=0.7e9, help='instructions')
a = ap.parse_args()

with tempfile.TemporaryDirectory() as tmp:
    glb = os.path.join(tmp, a.map.lower() + '.glb')
    subprocess.run([a.lintel, 'import', 'doom', a.wad, a.map, '-o', glb], check=True, capture_output=True)
    run = subprocess.run(['valgrind', '--tool=callgrind', '--callgrind-out-file=' + os.path.join(tmp, 'cg.out'),
                          a.lintel, 'validate', '-q', glb], capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f'validate failed under valgrind:\n{run.stderr}')
    refs = re.search(r'Collected : (\d+)', run.stderr)
    if not refs:
        sys.exit('no instruction count in valgrind\'s output')
    count = int(refs.group(1))

verdict = 'within' if count <= a.budget else 'OVER'
print(f'{a.map}: lintel validate {count / 1e9:.3f} G instructions, {verdict} the budget of {a.budget / 1e9:.3f} G')
sys.exit(0 if count <= a.budget else 1)
