#!/usr/bin/env python3
"""A reference answer to the camera exercises, in plain Python (standard library only).

Reads ONE case on standard input (a raycam scene file: JSON, angles in degrees) and prints ONE answer on
standard output: {"ids": [...], "md": [[...], ...]} (see README.md beside this file).

Run it by hand:   python3 camera.py < case_01.json
Check it:         raycam-cli check --student "python3 camera.py"
"""
import json
import math
import sys


# ---- 3x3 / 4x4 homogeneous matrices as lists of rows ------------------------------------------------------
def multiply(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(len(b))) for j in range(len(b[0]))] for i in range(len(a))]


def product(*factors):
    result = factors[0]
    for factor in factors[1:]:
        result = multiply(result, factor)
    return result


def apply(m, p, w):
    """m times (p, w): w = 1 for a point (translated), w = 0 for a vector (not translated)."""
    h = list(p) + [w]
    return [sum(m[i][k] * h[k] for k in range(len(h))) for i in range(len(p))]


def normalise(v):
    length = math.sqrt(sum(x * x for x in v))
    return [x / length for x in v]


def useful_size(res, size):
    """Exercise 1 step 3: n = res*N rounded to the nearest integer (halves up), between 1 and N."""
    return max(1, min(size, math.floor(res * size + 0.5)))


def resolutions(camera):
    """The handout's one or two resolution variables: res, or in 3D [columns' res, rows' res]."""
    res = camera["res"]
    return res if isinstance(res, list) else [res, res]


# ---- exercise 1: the 2D camera, M_d = T(OP) . R(theta - pi/2) . H(1, d_f) ----------------------------------
def placement_2d(camera):
    cx, cy = camera["target"]
    theta = math.radians(camera["theta"])
    px, py = cx + camera["d"] * math.cos(theta), cy + camera["d"] * math.sin(theta)
    # R must turn u0 = (0, -1) towards the target: the angle of CP is theta, so alpha = theta - pi/2.
    alpha = theta - math.pi / 2
    t = [[1, 0, px], [0, 1, py], [0, 0, 1]]
    r = [[math.cos(alpha), -math.sin(alpha), 0], [math.sin(alpha), math.cos(alpha), 0], [0, 0, 1]]
    h = [[1, 0, 0], [0, camera["df"], 0], [0, 0, 1]]
    return product(t, r, h)


# ---- exercise 3: the 3D camera, M_d = T(OP) . Rz(theta) . Ry(phi) . Rz(pi/2) . H(1, 1, d_f) ---------------
def rotation_z(a):
    return [[math.cos(a), -math.sin(a), 0, 0], [math.sin(a), math.cos(a), 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]


def rotation_y(a):
    return [[math.cos(a), 0, math.sin(a), 0], [0, 1, 0, 0], [-math.sin(a), 0, math.cos(a), 0], [0, 0, 0, 1]]


def placement_3d(camera):
    c = camera["target"]
    theta, phi, d = math.radians(camera["theta"]), math.radians(camera["phi"]), camera["d"]
    p = [c[0] + d * math.cos(theta) * math.sin(phi), c[1] + d * math.sin(theta) * math.sin(phi), c[2] + d * math.cos(phi)]
    t = [[1, 0, 0, p[0]], [0, 1, 0, p[1]], [0, 0, 1, p[2]], [0, 0, 0, 1]]
    h = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, camera["df"], 0], [0, 0, 0, 1]]
    # (theta, phi) are the angles of CP; the roll +pi/2 keeps world up (+z) at the top of the image.
    return product(t, rotation_z(theta), rotation_y(phi), rotation_z(math.pi / 2), h)


# ---- exercise 2: primary rays and the nearest hit ----------------------------------------------------------
def nearest_hit(objects, origin, direction):
    """The object hit first with t >= 0 (ties: the lower index), -1 if none. direction is a unit vector."""
    best_id, best_t = -1, math.inf
    for index, obj in enumerate(objects):
        f = [o - c for o, c in zip(origin, obj["center"])]
        b = sum(x * u for x, u in zip(f, direction))
        c = sum(x * x for x in f) - obj["radius"] ** 2
        disc = b * b - c
        if disc < 0:
            continue
        root = math.sqrt(disc)
        t = -b - root if -b - root >= 0 else -b + root  # the near side, or the far side from inside
        if 0 <= t < best_t:
            best_id, best_t = index, t
    return best_id


def ray_id(m, canonical_pixel, canonical_eye, objects):
    origin = apply(m, canonical_pixel, 1)  # P_k = M_d . P_k^0: a point
    direction = normalise(apply(m, [p - e for p, e in zip(canonical_pixel, canonical_eye)], 0))  # a vector
    return nearest_hit(objects, origin, direction)


def answer(case):
    camera, objects = case["camera"], case["objects"]
    if case["dimension"] == 2:
        m = placement_2d(camera)
        n = useful_size(camera["res"], camera["size"])
        ids = [ray_id(m, [-1 + (2 * k + 1) / n, 0], [0, 1], objects) for k in range(n)]
    else:
        m = placement_3d(camera)
        res_columns, res_rows = resolutions(camera)
        columns = useful_size(res_columns, camera["size"][0])
        rows = useful_size(res_rows, camera["size"][1])
        ids = [[ray_id(m, [-1 + (2 * c + 1) / columns, 1 - (2 * r + 1) / rows, 0], [0, 0, 1], objects)
                for c in range(columns)] for r in range(rows)]  # row 0 at the top
    return {"ids": ids, "md": m}


if __name__ == "__main__":
    json.dump(answer(json.load(sys.stdin)), sys.stdout)
    print()
