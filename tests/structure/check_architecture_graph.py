#!/usr/bin/env python3
"""docs/architecture.md's CMake graph is the one CMake builds.

Usage: check_architecture_graph.py LINK_GRAPH REPOSITORY_ROOT. LINK_GRAPH is the file CMake writes when it
configures (one line per target under src/: "target<TAB>lib;lib;...<TAB>source folder"). Fails (exit 1, one
line per problem) when, in the section "The CMake graph" of docs/architecture.md:
- a raycam target CMake defines has no row in the table, or a row names a target CMake does not define (a
  target of a build not configured here, such as the web page's, is read from its folder's CMakeLists.txt);
- a row's first folder is not the folder whose CMakeLists.txt defines the target;
- a row's "links" column names other raycam targets than the target's direct links (words such as `io` stand
  for raycam_io; outside libraries, GLM or OSMesa, are not compared);
- the one-line chain (**core → io / … → app / cli**) differs from the layers check_layers.py enforces.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from check_layers import LAYERS, RANK, is_raycams, linked_names  # noqa: E402

SECTION = re.compile(r"^## The CMake graph\n(.*?)(?=^## )", re.S | re.M)
CHAIN = re.compile(r"^\*\*(core →[^*]*)\*\*$", re.M)
ROW = re.compile(r"^\| `([^`]+)` \| ([^|]*) \| [^|]* \| ([^|]*) \|$", re.M)
TARGET_DEFINITION = r"add_(?:executable|library)\(\s*{}[\s)]"
TARGET_LINKS = r"target_link_libraries\(\s*{}\s+((?:[^)])*)\)"


def short_name(target):
    """raycam_io -> io; the two executables as the chain names them (raycam -> app, raycam-cli -> cli)."""
    return {"raycam": "app", "raycam-cli": "cli"}.get(target, re.sub(r"^raycam[_-]", "", target))


def read_cmake_graph(path, root):
    """{target: (set of raycam targets it links, its folder relative to root)} for raycam's own targets (inside
    helpers such as raycam_imgui_opengl3, which have no layer, are left out as check_layers.py leaves them)."""
    graph = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.strip():
                continue
            target, links, folder = (line.rstrip("\n").split("\t") + ["", ""])[:3]
            if is_raycams(target) and not target.endswith("_tests"):
                graph[target] = ({n for n in linked_names(links) if n in RANK},
                                 os.path.relpath(folder, root) if folder else "")
    return graph


def unconfigured_target(root, target, folder):
    """(links, folder) of a target this configuration does not define, from its folder's CMakeLists.txt."""
    cmake_file = os.path.join(root, folder, "CMakeLists.txt")
    if not os.path.isfile(cmake_file):
        return None
    with open(cmake_file, encoding="utf-8") as f:
        text = f.read()
    if not re.search(TARGET_DEFINITION.format(re.escape(target)), text):
        return None
    links = set()
    for field in re.findall(TARGET_LINKS.format(re.escape(target)), text):
        links.update(w for w in field.split() if w in RANK)
    return links, folder


def documented_links(column, known):
    """The raycam targets a "links" column names: each word w that is a target's short name."""
    by_short = {short_name(t): t for t in known}
    words = re.findall(r"[\w-]+", column.replace("`", ""))
    return {by_short[w] for w in words if w in by_short}


def main(graph_path, root):
    problems = []
    doc_path = os.path.join(root, "docs", "architecture.md")
    with open(doc_path, encoding="utf-8") as f:
        section = SECTION.search(f.read())
    if not section:
        print(f"check_architecture_graph: {doc_path}: no section '## The CMake graph'")
        return 1
    text = section.group(1)
    graph = read_cmake_graph(graph_path, root)
    if not graph:
        problems.append(f"{graph_path}: no raycam target found (the graph was not written?)")

    rows = {target: (folders, links) for target, folders, links in ROW.findall(text)}
    for target in sorted(set(graph) - set(rows)):
        problems.append(f"{doc_path}: CMake defines {target} ({graph[target][1]}), which has no row in the table")
    known = set(graph) | set(rows)
    for target, (folders, links_column) in sorted(rows.items()):
        named_folders = re.findall(r"`([^`]+)`", folders)
        first_folder = named_folders[0].rstrip("/") if named_folders else ""
        actual = graph.get(target) or unconfigured_target(root, target, first_folder)
        if actual is None:
            problems.append(f"{doc_path}: the row {target}: no such target in CMake (nor in "
                            f"{first_folder or '?'}/CMakeLists.txt)")
            continue
        links, folder = actual
        if first_folder != folder:
            problems.append(f"{doc_path}: the row {target}: its folder is {folder}, the table says "
                            f"'{first_folder}'")
        written = documented_links(links_column, known)
        # A configuration without some of the app's targets (the sanitizer build has no app, no OSMesa, no
        # Embree) links fewer: the row names the full build's links, so there only missing links count.
        partial = target in graph and any(t not in graph for t in rows if t != "raycam_web")
        if (links - written) if partial else (written != links):
            missing = ", ".join(sorted(short_name(t) for t in links - written)) or "none"
            extra = ", ".join(sorted(short_name(t) for t in written - links)) or "none"
            problems.append(f"{doc_path}: the row {target}: links column misses [{missing}], names too many "
                            f"[{extra}] (CMake: {', '.join(sorted(short_name(t) for t in links)) or 'none'})")

    chain = CHAIN.search(text)
    layers = " → ".join(" / ".join(short_name(t) for t in layer) for layer in LAYERS)
    if not chain:
        problems.append(f"{doc_path}: no chain line **core → …** in the section")
    elif re.sub(r"\s+", " ", chain.group(1)).strip() != layers:
        problems.append(f"{doc_path}: the chain '{chain.group(1)}' is not check_layers.py's '{layers}'")

    for problem in problems:
        print(f"check_architecture_graph: {problem}")
    print(f"check_architecture_graph: {len(rows)} rows, {len(graph)} CMake targets, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
