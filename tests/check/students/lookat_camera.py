#!/usr/bin/env python3
"""A test student with the camera most students bring: a look-at camera in the style of Ray Tracing in One
Weekend (an orthonormal frame from the eye, the target and a fixed up vector z), whose screen is stretched to
the image's aspect: half-width = (nbc / nbl) x half-height, square pixels. The handout's canonical screen is
the square [-1, 1]^2 whatever nbc and nbl, so every non-square 3D case fails: `raycam-cli check` must name
the mistake square_pixels. 2D cases are answered by the reference example.

  python3 lookat_camera.py EXAMPLES_DIR < case.json      (EXAMPLES_DIR holds the reference camera.py)
"""
import json
import math
import sys

sys.path.insert(0, sys.argv[1])
import camera as reference  # noqa: E402  (the handout's camera, for the 2D cases)


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def add(a, b):
    return [x + y for x, y in zip(a, b)]


def scale(a, s):
    return [x * s for x in a]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def unit(a):
    n = math.sqrt(sum(x * x for x in a))
    return [x / n for x in a]


def look_at_answer(case):
    cam, objects = case["camera"], case["objects"]
    theta, phi = math.radians(cam["theta"]), math.radians(cam["phi"])
    target = cam["target"]
    w = [math.cos(theta) * math.sin(phi), math.sin(theta) * math.sin(phi), math.cos(phi)]  # from C to P
    position = add(target, scale(w, cam["d"]))  # the screen's centre
    right = unit(cross([0.0, 0.0, 1.0], w))     # a fixed up vector: z
    up = cross(w, right)
    eye = add(position, scale(w, cam["df"]))
    res_columns, res_rows = reference.resolutions(cam)
    columns = reference.useful_size(res_columns, cam["size"][0])
    rows = reference.useful_size(res_rows, cam["size"][1])
    aspect = columns / rows  # the look-at habit: square pixels, the screen as wide as the image
    ids = []
    for r in range(rows):
        row = []
        for c in range(columns):
            x = aspect * (-1 + (2 * c + 1) / columns)
            y = 1 - (2 * r + 1) / rows
            point = add(position, add(scale(right, x), scale(up, y)))
            row.append(reference.nearest_hit(objects, point, unit(sub(point, eye))))
        ids.append(row)
    return {"ids": ids}


case = json.load(sys.stdin)
print(json.dumps(reference.answer(case) if case["dimension"] == 2 else look_at_answer(case)))
