#!/usr/bin/env python3
"""A test student written to the handout's required protocol: one resolution variable. It reads "res" as one
number for both sides of a 3D image, so a case whose res is a pair [res_c, res_l] (asked only by
`raycam-cli check --two-res`) makes it fail (float() of a list raises). Everything else is the reference
example's camera, so it passes every case whose res is one number.

  python3 one_res_camera.py EXAMPLES_DIR < case.json      (EXAMPLES_DIR holds the reference camera.py)
"""
import json
import sys

sys.path.insert(0, sys.argv[1])
import camera as reference  # noqa: E402  (the handout's camera)


def one_resolution(camera):
    res = float(camera["res"])  # the one variable the handout requires: a number
    return [res, res]


reference.resolutions = one_resolution  # answer() looks it up in its module at each call
print(json.dumps(reference.answer(json.load(sys.stdin))))
