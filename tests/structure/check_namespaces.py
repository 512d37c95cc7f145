#!/usr/bin/env python3
"""Every folder's code is in its own namespace (docs/architecture.md, "Layers").

Usage: check_namespaces.py REPOSITORY_ROOT. A file under src/FOLDER/ opens `namespace raycam::FOLDER` (the
first folder under src/: src/flags/app is raycam::flags). The core, io and testkit, whose public headers are
"raycam/…", open `raycam` (or a namespace inside it). Two kinds of block are allowed elsewhere: a forward
declaration (`namespace raycam::gl { class ObserverRenderer; }`), and the page's stand-ins (src/web/*_web.cpp),
which define, for emscripten's build, functions that another folder declares.
"""
import os
import re
import sys

OPEN = re.compile(r"^namespace (raycam(?:::[a-z_]+)*) \{(.*?)^\}", re.M | re.S)
PUBLIC = {"core", "io", "testkit"}
DECLARATION = re.compile(r"^\s*(class|struct) \w+;\s*$")


def main(root):
    src = os.path.join(root, "src")
    problems, blocks = [], 0
    for folder, _, names in os.walk(src):
        layer = os.path.relpath(folder, src).split(os.sep)[0]
        for name in sorted(names):
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.relpath(os.path.join(folder, name), root)
            text = open(os.path.join(folder, name), encoding="utf-8").read()
            for namespace, body in OPEN.findall(text):
                blocks += 1
                if namespace == f"raycam::{layer}" or namespace.startswith(f"raycam::{layer}::"):
                    continue
                if layer in PUBLIC:
                    continue
                lines = [l for l in body.splitlines() if l.strip() and not l.strip().startswith("//")]
                if lines and all(DECLARATION.match(l) for l in lines):
                    continue
                if layer == "web" and name.endswith("_web.cpp"):
                    continue
                problems.append(f"{path}: opens namespace {namespace}, not raycam::{layer}")
    for problem in problems:
        print(f"check_namespaces: {problem}")
    print(f"check_namespaces: {blocks} namespace blocks checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
