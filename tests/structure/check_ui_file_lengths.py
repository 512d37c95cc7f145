#!/usr/bin/env python3
"""No file in src/ui is longer than MAX_LINES lines (docs/architecture.md, "Where the files are").

Usage: check_ui_file_lengths.py REPOSITORY_ROOT MAX_LINES (tests/structure/CMakeLists.txt gives the bound).
The control panel is a file a section (camera_section.cpp, status_line.cpp, …) over the shared widgets of
panel_widgets.h: a file that grows past the bound is a part of the window that wants a file of its own.
"""
import os
import sys

FOLDER = "src/ui"


def main(root, max_lines):
    folder = os.path.join(root, FOLDER)
    lengths = {}
    for name in sorted(os.listdir(folder)):
        if name.endswith((".h", ".cpp")):
            with open(os.path.join(folder, name), encoding="utf-8") as f:
                lengths[name] = sum(1 for _ in f)
    if not lengths:
        print(f"no .h or .cpp file in {FOLDER}: wrong repository root?")
        return 1
    too_long = [f"{FOLDER}/{name}: {count} lines, more than {max_lines}" for name, count in lengths.items()
                if count > max_lines]
    for problem in too_long:
        print(problem)
    longest = max(lengths, key=lengths.get)
    print(f"{len(lengths)} files in {FOLDER}, the longest {longest} ({lengths[longest]} lines; at most {max_lines})")
    return 1 if too_long else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], int(sys.argv[2])))
