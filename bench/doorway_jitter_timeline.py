# Writes a 3 s, 60 fps timeline of an eye at rest in the cottage's hall->living doorway with
# +-1..3 um jitter per frame (along the walk direction, i.e. across the door plane), for
# measuring flaps with `lintel walk --timeline-file`. The plane point is found by bisecting
# the viewer cell that `lintel vis` picks by containment between two frames of the doorway walk.
import json, os, subprocess, random, sys
# Usage: python3 bench/doorway_jitter_timeline.py build/bin/lintel OUT.json
lintel = sys.argv[1]
out_path = sys.argv[2]
scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scenes', 'cottage.gltf')
a = [7.497108459472656, 1.6000001430511475, -1.0220977067947388]
b = [7.4524946212768555, 1.600000023841858, -1.0084577798843384]
def cell(p):
    d = [b[i] - a[i] for i in range(3)]
    t = [p[i] + d[i] * 20 for i in range(3)]
    out = subprocess.run([lintel, 'vis', '--json', '--eye', ','.join(map(repr, p)), '--target', ','.join(map(repr, t)),
                          scene], capture_output=True, text=True).stdout
    return json.loads(out)['viewer_cell']
ca = cell(a)
lo, hi = 0.0, 1.0
for _ in range(30):
    mid = 0.5 * (lo + hi)
    p = [a[i] + (b[i] - a[i]) * mid for i in range(3)]
    if cell(p) == ca: lo = mid
    else: hi = mid
s = 0.5 * (lo + hi)
p = [a[i] + (b[i] - a[i]) * s for i in range(3)]
d = [b[i] - a[i] for i in range(3)]
n = sum(x * x for x in d) ** 0.5
d = [x / n for x in d]
random.seed(11)
keys = []
for f in range(181):
    j = random.choice([-1, 1]) * random.uniform(1e-6, 3e-6)
    eye = [p[i] + d[i] * j for i in range(3)]
    keys.append({'t': f / 60.0, 'eye': eye, 'target': [eye[i] + d[i] * 2.0 for i in range(3)]})
json.dump({'name': 'doorway_jitter', 'fps': 60, 'keys': keys}, open(out_path, 'w'))
print('plane point', p, 'containment flips at s =', s, 'from', ca)
