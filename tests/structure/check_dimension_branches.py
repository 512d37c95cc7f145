#!/usr/bin/env python3
"""Code that does the same in 2D and 3D is written once: at most MAX_BRANCHES dimension branches in src/.

Usage: check_dimension_branches.py REPOSITORY_ROOT. Counts the lines of src/ that pick a dimension by hand
(`dimension == 2`, `dimension(state) != 3`, `is_2d`, `holds_alternative<View3D>`, `get_if<View2D>`: the
pattern below, the same as docs/architecture.md's grep command) and fails (exit 1, listing them) when there are
more than MAX_BRANCHES. A new difference between the dimensions goes through the view (std::visit,
overloaded{…}, visit_scene, visit_view_setup) or replaces one of the branches left.
"""
import os
import re
import sys

MAX_BRANCHES = 30
# grep -rnE '(dimension|dimension_of\([^)]*\)|dimension\([a-z_.]*\)) *[!=]= *[23]|\bis_2d\b|(holds_alternative|get_if)<View[23]D>' src
BRANCH = re.compile(r"(dimension|dimension_of\([^)]*\)|dimension\([a-z_.]*\)) *[!=]= *[23]|\bis_2d\b"
                    r"|(holds_alternative|get_if)<View[23]D>")


def branches(root):
    found = []
    for folder, _, files in os.walk(os.path.join(root, "src")):
        for name in sorted(files):
            path = os.path.join(folder, name)
            try:
                with open(path, encoding="utf-8") as text:
                    lines = text.readlines()
            except (UnicodeDecodeError, OSError):
                continue
            for number, line in enumerate(lines, 1):
                if BRANCH.search(line):
                    found.append(f"{os.path.relpath(path, root)}:{number}: {line.strip()}")
    return sorted(found)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_dimension_branches.py REPOSITORY_ROOT")
    found = branches(sys.argv[1])
    if len(found) > MAX_BRANCHES:
        print("\n".join(found))
        print(f"{len(found)} dimension branches in src/, more than {MAX_BRANCHES}: write the new one once over "
              "both dimensions (std::visit, visit_scene, visit_view_setup; docs/architecture.md)")
        return 1
    print(f"{len(found)} dimension branches in src/ (at most {MAX_BRANCHES})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
