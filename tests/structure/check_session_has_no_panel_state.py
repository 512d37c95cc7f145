#!/usr/bin/env python3
"""The session never reads the panels' widget state: it lives in raycam::ui (src/ui/panel_state.h), owned by
the frame beside the session's AppState.

Usage: check_session_has_no_panel_state.py REPOSITORY_ROOT. Fails (exit 1, listing the lines) when a file
of src/session names `PanelState` (anywhere, comments included) or one of PanelState's fields in its code
(string literals and comments left out: the text table's ImGui ids such as "###save_path" are texts).
A session function that needs a choice the panel made takes it as a parameter (a path, a FigureContent)
or says what happened (SaveAsOutcome, scene_opens) for the panel to keep.
"""
import os
import re
import sys

# PanelState's fields (src/ui/panel_state.h).
PANEL_FIELDS = ["shown_matrix", "font_scale_editing", "font_scale_seen", "font_scale_scroll_frames",
                "widget_rects", "check_command", "check_waiting", "path_input", "scene_opens_seen", "save_path",
                "overwrite_pending", "export_path", "figure_path", "figure_format", "figure_rays", "figure_matrix",
                "figure_replace_pending", "figure_replace_files", "export_default", "figure_default",
                "colour_map_replace_files"]
FIELD = re.compile(r"\b(" + "|".join(PANEL_FIELDS) + r")\b")
# Options that share a name with a field and are not panel state: --check CMD is AppOptions' (the command
# line's); the panels take it from there (ui::panel_state_for).
ALLOWED = {("app_options.h", "check_command")}
STRING = re.compile(r'"(?:[^"\\]|\\.)*"')


def code_of(line):
    """The line without its string literals and its // comment."""
    line = STRING.sub('""', line)
    return line.split("//", 1)[0]


def findings(root):
    found = []
    folder = os.path.join(root, "src", "session")
    for name in sorted(os.listdir(folder)):
        path = os.path.join(folder, name)
        if not os.path.isfile(path):
            continue
        with open(path, encoding="utf-8") as text:
            for number, line in enumerate(text, 1):
                where = f"src/session/{name}:{number}: {line.strip()}"
                if "PanelState" in line:
                    found.append(where)
                    continue
                names = {m.group(1) for m in FIELD.finditer(code_of(line))}
                if any((name, field) not in ALLOWED for field in names):
                    found.append(where)
    return found


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: check_session_has_no_panel_state.py REPOSITORY_ROOT")
    found = findings(sys.argv[1])
    if found:
        print("\n".join(found))
        print(f"{len(found)} line(s) of src/session name the panels' state: it is raycam::ui's "
              "(src/ui/panel_state.h); pass the panel's choice as a parameter or return what happened")
        return 1
    print("src/session names no panel state")
    return 0


if __name__ == "__main__":
    sys.exit(main())
