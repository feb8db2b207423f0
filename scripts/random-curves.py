#!/usr/bin/env python3
# Writes N random straight crease curves (one segment each, 1 to 64 texels long, clipped to the map) over a SIZE x
# SIZE map as a `microbake crease --curves` JSON file: the many-segment case of the crease benchmarks.
#
#   python3 scripts/random-curves.py OUT.json [SIZE] [N]      # defaults 1024 and 10000, seed 1
import json
import math
import random
import sys

out = sys.argv[1]
size = float(sys.argv[2]) if len(sys.argv) > 2 else 1024.0
count = int(sys.argv[3]) if len(sys.argv) > 3 else 10000
random.seed(1)
curves = []
while len(curves) < count:
    x, y = random.uniform(0, size), random.uniform(0, size)
    a, l = random.uniform(0, 2 * math.pi), random.uniform(1, 64)
    u, v = min(max(x + l * math.cos(a), 0), size), min(max(y + l * math.sin(a), 0), size)
    if (u, v) != (x, y):
        curves.append({"points": [[x, y], [u, v]]})
json.dump({"curves": curves}, open(out, "w"))
