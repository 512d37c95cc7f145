#!/usr/bin/env python3
"""`render --ids --ids-order k` writes the ids in the order a student's answer lists them.

Usage: test_ids_order.py RAYCAM_CLI STUDENT_CAMERA_PY. Runs in a temporary folder of its own. Checks, with
expectations that do not come from raycam's own ids file:
1. By hand, from the handout's geometry: a 2D camera at C = (0, 0), d = 6, theta = 90 (P = (0, 6), looking
   down -y, d_f = 1.5), n = 4, and one circle of radius 2.5 at (3, 0), to the world's +x. Pixel k's canonical
   centre is x = -1 + (2k+1)/n = -0.75, -0.25, 0.25, 0.75; with theta = 90 the rotation is the identity, so
   a ray leaves P_k = (x_k, 6) along (x_k, -1.5): k = 2 and 3 pass within 1.2 and 0.6 of (3, 0) and hit,
   k = 0 and 1 pass 4.2 and more away and miss. In k order: -1 -1 0 0. The eye looks along -y, so its left
   is +x: column 0 of the image is k = n-1 and the image's line is 0 0 -1 -1 (k = n-1-column).
2. On every 2D case of the check's battery (`check --write-cases`): the k-order line equals the answer of
   examples/student/camera.py (the handout's exercises written independently, in Python), and the
   image-order line is its reverse.
3. The grader agrees: every case's ids written with --ids-order k (2D and 3D) as answer_NN.json pass
   `check --answers`, and the 2D ones in image order fail.
"""
import json
import os
import subprocess
import sys
import tempfile


def run(*command, stdin=None, expect=0):
    done = subprocess.run(command, capture_output=True, text=True, stdin=stdin)
    if done.returncode != expect:
        sys.exit(f"FAIL: {' '.join(command)} exited {done.returncode}, expected {expect}\n{done.stdout}{done.stderr}")
    return done.stdout


def fail(failures, text):
    print(f"FAIL: {text}", flush=True)  # at once: a later command's failure may end the test
    failures.append(text)


def ids_file(cli, scene, order):
    run(cli, "render", "--scene", scene, "--ids", "ids.txt", *(["--ids-order", order] if order else []))
    with open("ids.txt") as f:
        return [[int(v) for v in line.split()] for line in f.read().splitlines()]


def main(cli, camera_py):
    cli, camera_py = os.path.abspath(cli), os.path.abspath(camera_py)
    with tempfile.TemporaryDirectory(prefix="raycam-ids-order.") as scratch:
        os.chdir(scratch)
        return checks(cli, camera_py)


def checks(cli, camera_py):
    failures = []
    # 1. by hand
    with open("right.json", "w") as f:
        json.dump({"dimension": 2, "objects": [{"type": "circle", "center": [3, 0], "radius": 2.5}],
                   "camera": {"target": [0, 0], "d": 6, "theta": 90, "df": 1.5, "res": 1, "size": 4}}, f)
    if ids_file(cli, "right.json", "k") != [[-1, -1, 0, 0]]:
        fail(failures, f"the circle to the camera's +x: --ids-order k gave {ids_file(cli, 'right.json', 'k')}, "
                        "expected [[-1, -1, 0, 0]]")
    for order in (None, "image"):
        if ids_file(cli, "right.json", order) != [[0, 0, -1, -1]]:
            fail(failures, f"the circle to the camera's +x: --ids-order {order} gave "
                            f"{ids_file(cli, 'right.json', order)}, expected [[0, 0, -1, -1]]")
    # 2. against an independent program, and 3. against the grader
    run(cli, "check", "--write-cases", "cases")
    cases = sorted(n for n in os.listdir("cases") if n.startswith("case_"))
    twod = 0
    os.mkdir("image")
    for name in cases:
        scene = os.path.join("cases", name)
        with open(scene) as f:
            dimension = json.load(f)["dimension"]
        k_order = ids_file(cli, scene, "k")
        answer = {"ids": k_order[0] if dimension == 2 else k_order}
        with open(os.path.join("cases", name.replace("case_", "answer_")), "w") as f:
            json.dump(answer, f)
        if dimension == 3:
            if k_order != ids_file(cli, scene, "image"):
                fail(failures, f"{name}: in 3D, --ids-order k differs from the image's order")
            continue
        twod += 1
        with open(scene) as f:
            expected = json.loads(run("python3", camera_py, stdin=f))["ids"]
        if k_order != [expected]:
            fail(failures, f"{name}: --ids-order k gave {k_order[0]}, examples/student/camera.py {expected}")
        image = ids_file(cli, scene, None)
        if image != [expected[::-1]]:
            fail(failures, f"{name}: the image's order is not the answer reversed")
        if image != [expected]:  # a case whose line is a palindrome cannot tell the orders apart
            with open(os.path.join("image", name.replace("case_", "answer_")), "w") as f:
                json.dump({"ids": image[0]}, f)
    report = run(cli, "check", "--answers", "cases", "--lang", "en")
    if f"score: {len(cases)} / {len(cases)}" not in report:
        fail(failures, f"check --answers did not pass every case written with --ids-order k:\n{report}")
    mirrored = len(os.listdir("image"))
    for name in os.listdir("image"):  # the battery again, its non-symmetric 2D answers in image order
        os.replace(os.path.join("image", name), os.path.join("cases", name))
    report = run(cli, "check", "--answers", "cases", "--lang", "en", expect=1)
    if mirrored == 0 or f"score: {len(cases) - mirrored} / {len(cases)}" not in report:
        fail(failures, f"check --answers should fail the {mirrored} 2D cases in image order:\n{report}")
    print(f"test_ids_order: {len(cases)} cases ({twod} 2D, {mirrored} telling the orders apart), "
          f"{len(failures)} failures")
    return 1 if failures or twod == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
