#!/usr/bin/env python3
"""The CMake graph has no upward link (docs/architecture.md, "The CMake graph").

Reads the link graph CMake wrote (one line per target under src/: "target<TAB>lib;lib;...<TAB>folder") and
fails when a raycam target links a raycam target at its own rank or above in LAYERS, or when a raycam target is
missing from LAYERS (a new target must be given its place). Libraries that are not raycam's (GLM, ImGui,
OSMesa...) are ignored.
"""
import sys

# Lowest first. A target may link only targets of a lower rank.
LAYERS = [
    ["raycam_core"],
    ["raycam_io", "raycam_testkit", "raycam_embree", "raycam_figure_tikz"],
    ["raycam_check", "raycam_figure", "raycam_video"],  # raycam_video: FFmpeg, `record`'s files
    ["raycam_session"],
    ["raycam_flags"],
    ["raycam_app_flags"],
    ["raycam_gl"],
    ["raycam_ui"],
    ["raycam_headless", "raycam_bench", "raycam_glfw_host"],  # raycam_bench: `raycam-cli bench`'s two benchmarks
    ["raycam", "raycam-cli", "raycam_web_objects"],  # raycam_web_objects: the page's code, emscripten only
    ["raycam_web", "raycam_web_single"],  # the page linked twice: index.html and the one-file raycam.html
]
# Targets that link nothing of raycam's and that nothing links: outside the chain.
ALONE = {"raycam-exec"}  # the sandbox's exec checkpoint (src/check/exec_checkpoint.cpp): libc only
RANK = {target: rank for rank, layer in enumerate(LAYERS) for target in layer}


def is_raycams(name):
    return name == "raycam" or name.startswith("raycam_") or name.startswith("raycam-")


def linked_names(field):
    """The target names in a LINK_LIBRARIES list, generator expressions such as $<LINK_ONLY:x> unwrapped."""
    names = []
    for item in field.split(";"):
        item = item.strip()
        while item.startswith("$<") and ":" in item and item.endswith(">"):
            item = item[item.index(":") + 1:-1]
        if item:
            names.append(item)
    return names


def main(path):
    problems = []
    checked = 0
    with open(path, encoding="utf-8") as graph:
        for line in graph:
            if not line.strip():
                continue
            target, field = (line.rstrip("\n").split("\t") + [""])[:2]
            if not is_raycams(target) or target.endswith("_tests"):
                continue
            if target in ALONE:
                if any(is_raycams(name) for name in linked_names(field)):
                    problems.append(f"{target}: listed as linking nothing of raycam's, but links {field}")
                continue
            if target not in RANK:
                problems.append(f"{target}: not in the layer table of {__file__}: give it its place")
                continue
            checked += 1
            for name in linked_names(field):
                if not is_raycams(name) or name not in RANK:
                    continue  # an outside library, or an inside helper such as raycam_imgui_opengl3
                if RANK[name] >= RANK[target]:
                    problems.append(f"{target} links {name}: upward (or sideways) in the graph "
                                    f"{' -> '.join('/'.join(layer) for layer in LAYERS)}")
    if checked == 0:
        problems.append(f"{path}: no raycam target found (the graph was not written?)")
    for problem in problems:
        print(f"check_layers: {problem}")
    print(f"check_layers: {checked} targets checked, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
