#!/usr/bin/env python3
"""Writes scenes/many3d.json: 2000 spheres at seeded random positions in [-10, 10]^3, coloured by position."""
import json
import random

random.seed(1234)
objects = []
for _ in range(2000):
    x, y, z = [random.uniform(-10, 10) for _ in range(3)]
    radius = random.uniform(0.15, 0.45)
    colour = [int(60 + 195 * (c + 10) / 20) for c in (x, y, z)]
    objects.append({"type": "sphere", "center": [round(x, 4), round(y, 4), round(z, 4)],
                    "radius": round(radius, 4), "color": colour})
scene = {"dimension": 3, "background": [20, 20, 30], "objects": objects,
         "camera": {"target": [0, 0, 0], "d": 24, "theta": 35, "phi": 65, "df": 1.8, "res": 1, "size": [512, 512]}}
with open("scenes/many3d.json", "w") as out:
    out.write(json.dumps(scene, separators=(",", ":")).replace("},{", "},\n{"))
