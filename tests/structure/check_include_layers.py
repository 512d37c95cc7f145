#!/usr/bin/env python3
"""Every include in src/ names the layer it reaches, and reaches only down (docs/architecture.md).

Usage: check_include_layers.py LINK_GRAPH REPOSITORY_ROOT. A project header is included by its folder under
src/ ("session/app_state.h", "flags/app/app_flags.h") or, for the public headers of core, io and testkit, as
"raycam/…". Fails on a bare "x.h" that is a project header (the include does not say its layer), and on an
include of a folder whose library is at the includer's rank or above in check_layers.py's table (a file may
include its own folder). Ranks come from the targets each folder defines (the link graph CMake writes; the
page's folder, built only by emscripten, is raycam_web_objects).
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_layers import RANK  # noqa: E402

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
PUBLIC = {"include/raycam": "raycam_core", "src/io/include/raycam": "raycam_io",
          "src/testkit/include/raycam": "raycam_testkit"}
HOME = {"raycam_core": "src/core", "raycam_io": "src/io", "raycam_testkit": "src/testkit"}


def folder_ranks(graph_path, root):
    ranks = {"src/web": [RANK["raycam_web_objects"]]}
    with open(graph_path, encoding="utf-8") as f:
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) < 3 or parts[0] not in RANK:
                continue
            folder = os.path.relpath(parts[2], root)
            if folder.startswith(".."):  # a graph written for another checkout of the same tree
                folder = "src/" + parts[2].rsplit("/src/", 1)[1]
            ranks.setdefault(folder, []).append(RANK[parts[0]])
    return ranks


def main(graph_path, root):
    ranks = folder_ranks(graph_path, root)
    src = os.path.join(root, "src")
    bare = {}
    for folder, _, names in os.walk(src):
        for name in names:
            if name.endswith(".h") and "/include" not in folder[len(src):]:
                bare[name] = os.path.relpath(folder, root)
    problems, checked = [], 0
    for folder, _, names in os.walk(src):
        here = os.path.relpath(folder, root)
        owner = next((f for f in sorted(ranks, key=len, reverse=True) if here == f or here.startswith(f + "/")), None)
        for name in names:
            if not name.endswith((".h", ".cpp")):
                continue
            path = os.path.join(here, name)
            for included in INCLUDE.findall(open(os.path.join(root, path), encoding="utf-8").read()):
                checked += 1
                if included.startswith("raycam/"):
                    public = next((f for f in PUBLIC if os.path.exists(os.path.join(root, f, included[7:]))), None)
                    if public is None or owner is None:
                        continue  # a generated header, or a folder outside the table
                    reached = PUBLIC[public]
                    if owner != HOME[reached] and RANK[reached] >= max(ranks[owner]):
                        problems.append(f"{path}: includes \"{included}\" ({reached}) from {owner}: not below it "
                                        "in check_layers.py's table")
                    continue
                if "/" not in included:
                    if included in bare and not os.path.exists(os.path.join(root, here, "generated", included)):
                        problems.append(f"{path}: includes \"{included}\": name its layer (\"{bare[included][4:]}/{included}\")")
                    continue
                reached_folder = os.path.join("src", os.path.dirname(included))
                if not os.path.exists(os.path.join(root, "src", included)) or owner is None:
                    continue
                if reached_folder == here or reached_folder == owner:
                    continue
                if reached_folder not in ranks:
                    # A folder with a CMakeLists.txt defines its library in some configuration, not this one
                    # (the sanitizer build has no app, so no glfw_host, headless or video): it cannot be ranked
                    # here; the main build's run ranks it.
                    if not os.path.exists(os.path.join(root, reached_folder, "CMakeLists.txt")):
                        problems.append(f"{path}: includes \"{included}\", a folder that defines no library")
                    continue
                if min(ranks[reached_folder]) >= max(ranks[owner]):
                    problems.append(f"{path}: includes \"{included}\" ({reached_folder}) from {owner}: not below it "
                                    "in check_layers.py's table")
    for problem in problems:
        print(f"check_include_layers: {problem}")
    print(f"check_include_layers: {checked} includes checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
