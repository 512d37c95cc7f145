#!/usr/bin/env python3
"""Writes a scene of K spheres at seeded random positions in [-10, 10]^3, coloured by position.

With no argument: scenes/many3d.json (K = 2000). `make_many3d.py K OUT` writes K spheres to OUT, radii scaled
by (2000 / K)^(1/3) so that the cube is as full as with 2000 (the 10^5-sphere soak in docs/speed.md).
"""
import json
import random
import sys

count = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
path = sys.argv[2] if len(sys.argv) > 2 else "scenes/many3d.json"
shrink = (2000 / count) ** (1 / 3)
random.seed(1234)
objects = []
for _ in range(count):
    x, y, z = [random.uniform(-10, 10) for _ in range(3)]
    radius = random.uniform(0.15, 0.45) * shrink
    colour = [int(60 + 195 * (c + 10) / 20) for c in (x, y, z)]
    objects.append({"type": "sphere", "center": [round(x, 4), round(y, 4), round(z, 4)],
                    "radius": round(radius, 4), "color": colour})
scene = {"dimension": 3, "background": [20, 20, 30], "objects": objects,
         "camera": {"target": [0, 0, 0], "d": 24, "theta": 35, "phi": 65, "df": 1.8, "res": 1, "size": [512, 512]}}
with open(path, "w") as out:
    out.write(json.dumps(scene, separators=(",", ":")).replace("},{", "},\n{"))
