#!/usr/bin/env python3
"""What the docs say about the code's shape is what the code is.

Usage: check_doc_facts.py REPOSITORY_ROOT. Each fact below is read from the doc that states it and compared
with the tree; a fact that drifted fails with the doc's words and the tree's answer (fix the doc, or the code).
Counts the docs state are checked by the docs test's `stated:` markers instead (docs/testing.md).
"""
import os
import re
import sys

ROOT = sys.argv[1] if len(sys.argv) > 1 else "."
SOURCES = ("src", "include")


def source_files():
    for top in SOURCES:
        for folder, _, names in os.walk(os.path.join(ROOT, top)):
            for name in names:
                if name.endswith((".h", ".hpp", ".cpp")):
                    path = os.path.join(folder, name)
                    yield os.path.relpath(path, ROOT), open(path, encoding="utf-8", errors="replace").read()


def files_with(pattern):
    return {path for path, text in source_files() if re.search(pattern, text)}


def folders_with(pattern):
    return {os.path.dirname(path) for path in files_with(pattern)}


def line_with(doc, anchor):
    with open(os.path.join(ROOT, doc), encoding="utf-8") as f:
        for line in f:
            if anchor in line:
                return line
    return None


def backticked(line):
    return set(re.findall(r"`([^`]+)`", line))


problems = []


def same(doc, anchor, said, found, what):
    if said != found:
        problems.append(f"{doc}, the line with '{anchor}': says {sorted(said)}, but {what} are {sorted(found)}")


def fact(doc, anchor):
    line = line_with(doc, anchor)
    if line is None:
        problems.append(f"{doc}: no line holds '{anchor}' (the fact moved: update check_doc_facts.py)")
    return line


# The files that test the page's compiler: architecture.md names each, in backticks, on one line.
doc, anchor = "docs/architecture.md", "files test `__EMSCRIPTEN__`:"
if (line := fact(doc, anchor)) is not None:
    said = {w for w in backticked(line) if w.startswith(SOURCES)}
    same(doc, anchor, said, files_with(r"__EMSCRIPTEN__"), "the files under src/ and include/ that test it")

# The folders that include a library's headers, as third_party/README.md's table gives them in its last column
# ("(only in `src/x`, `src/y`)").
for anchor, pattern in (("| nlohmann/json", r"#include <nlohmann/"), ("| GLFW 3.3", r"#include <GLFW/")):
    doc = "third_party/README.md"
    if (line := fact(doc, anchor)) is not None:
        said = {w.rstrip("/") for w in backticked(line) if w.startswith("src/")}
        same(doc, anchor, said, folders_with(pattern), "the folders that include it")

# Nothing vendored but the page's Dear ImGui: the only folder of sources in third_party/ is imgui/v1.86.
vendored = set()
for folder, _, names in os.walk(os.path.join(ROOT, "third_party")):
    if any(n.endswith((".c", ".cpp", ".h")) for n in names):
        vendored.add("/".join(os.path.relpath(folder, ROOT).split(os.sep)[:3]))  # third_party/NAME/VERSION
doc, anchor = "docs/architecture.md", "third_party/      "
if (line := fact(doc, anchor)) is not None:
    said = {w.rstrip("/") for w in backticked(line) if w.startswith("third_party/")}
    same(doc, anchor, said, vendored, "the folders of vendored sources")

# The core's public headers: architecture.md's file tree names each one in its include/raycam/ entry (the
# lines from that entry to the next folder's).
doc, anchor = "docs/architecture.md", "include/raycam/   public headers of raycam_core:"
if fact(doc, anchor) is not None:
    with open(os.path.join(ROOT, doc), encoding="utf-8") as f:
        lines = f.read().split(anchor, 1)[1].split("\n")
    entry = [lines[0]]
    for line in lines[1:]:
        if not line.startswith(" "):
            break
        entry.append(line)
    said = set(re.findall(r"\b([a-z0-9_]+\.h)\b", " ".join(entry)))
    found = {n for n in os.listdir(os.path.join(ROOT, "include/raycam")) if n.endswith(".h")}
    same(doc, anchor, said, found, "the headers in include/raycam/")

for problem in problems:
    print(f"check_doc_facts: {problem}")
print(f"check_doc_facts: {len(problems)} problems")
sys.exit(1 if problems else 0)
