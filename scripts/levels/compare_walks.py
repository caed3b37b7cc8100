#!/usr/bin/env python3
"""Compares two `lintel walk --json-lines` runs of the same timeline frame by frame: where the
second draws more cells than the first, how many of those frames had a fallback (cap hit: a
cell's region became its rect; polygon overflow: a region with too many polygons merged into
fewer, larger ones) in the second run. Used by docs/levels.md ("Finer lattice, looser result")."""
import json
import sys


def load(path):
    frames = {}
    with open(path) as f:
        for line in f:
            d = json.loads(line)
            if "frame" in d:
                frames[d["frame"]] = d
    return frames


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: compare_walks.py FIRST.jsonl SECOND.jsonl")
    a, b = load(sys.argv[1]), load(sys.argv[2])
    common = sorted(set(a) & set(b))
    cells = lambda d: len(d["visible_cells"])
    looser = [f for f in common if cells(b[f]) > cells(a[f])]
    tighter = [f for f in common if cells(b[f]) < cells(a[f])]
    caps = lambda d: d["stats"]["cap_hits"] > 0
    overflows = lambda d: d["stats"]["polygon_overflows"] > 0
    mean = lambda run: sum(cells(run[f]) for f in common) / max(1, len(common))
    print(f"frames {len(common)}: mean visible cells {mean(a):.2f} (first) vs {mean(b):.2f} (second)")
    print(f"second looser on {len(looser)} frames, tighter on {len(tighter)}")
    print(f"  looser frames with a polygon overflow in the second run: {sum(overflows(b[f]) for f in looser)}")
    print(f"  looser frames with a cap hit in the second run: {sum(caps(b[f]) for f in looser)}")
    print(f"  looser frames with neither: {sum(not caps(b[f]) and not overflows(b[f]) for f in looser)}")
    print(f"cap hits in total: {sum(a[f]['stats']['cap_hits'] for f in common)} (first) vs "
          f"{sum(b[f]['stats']['cap_hits'] for f in common)} (second)")


if __name__ == "__main__":
    main()
