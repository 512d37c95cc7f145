#!/usr/bin/env python3
"""Every place raycam-cli's --help texts send a reader exists.

Usage: check_help_references.py RAYCAM_CLI REPOSITORY_ROOT

Reads `raycam-cli --help` and, through their "Subcommands:" lists and every "`COMMAND --help`" they mention
(`check merge --help` is not a listed subcommand), every command's --help. Fails (exit 1, one line per
problem) when:
- a Markdown file a help names (`docs/check.md`, `figures.md`, README) is not in the repository;
- a heading it names in quotes after the file, as in (docs/check.md, "A large course"), is not a heading of that
  file (the heading's text, or its part before a colon: "Checking a camera" for "Checking a camera: `check`");
- a COMMAND --help it mentions does not exit 0;
- no reference was found at all (the parsing broke, not the texts).
"""
import os
import re
import subprocess
import sys

# A file, then optionally a quoted heading: (README, "Check your own camera"), (docs/check.md, "A large course"),
# docs/cli.md, docs/check.md's table. README alone is the repository's README.md.
REFERENCE = re.compile(r"((?:[\w.-]+/)*[\w.-]+\.md|\bREADME\b)(?:'s)?(?:,\s*\"([^\"]+)\")?")
HELP_MENTION = re.compile(r"`?(?:raycam-cli\s+)?((?:[a-z]+\s+){0,2}[a-z]+)\s+--help\b")
SUBCOMMANDS = re.compile(r"^Subcommands:\n((?:  \S.*\n?)+)", re.M)


def help_text(cli, command):
    done = subprocess.run([cli, *command, "--help"], capture_output=True, text=True, timeout=30)
    return done.returncode, done.stdout + done.stderr


def headings(path):
    """The headings of a Markdown file, outside fenced blocks, as plain text (backticks dropped)."""
    found, fenced = set(), False
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("```"):
                fenced = not fenced
            elif not fenced and re.match(r"^#{1,6}\s", line):
                text = line.lstrip("#").strip().replace("`", "")
                found.add(text)
                found.add(text.split(":", 1)[0].strip())
    return found


def find_md(root, name):
    """The repository's file for a name as a help writes it: from the root, else from docs/ (cli.md)."""
    if name == "README":
        name = "README.md"
    for candidate in (name, os.path.join("docs", name)):
        if os.path.isfile(os.path.join(root, candidate)):
            return candidate
    return None


def main(cli, root):
    problems, references = [], 0
    seen, queue = set(), [()]
    while queue:
        command = queue.pop(0)
        if command in seen:
            continue
        seen.add(command)
        status, text = help_text(cli, command)
        shown = " ".join(("raycam-cli",) + command)
        if status != 0:
            problems.append(f"`{shown} --help` exited {status}")
            continue
        for block in SUBCOMMANDS.findall(text):
            queue += [command + (line.split()[0],) for line in block.splitlines() if line.strip()]
        for mention in HELP_MENTION.findall(text):
            words = tuple(mention.split())
            if words and words[0] not in ("raycam", "a"):
                queue.append(words)
        for name, heading in REFERENCE.findall(text):
            references += 1
            found = find_md(root, name)
            if found is None:
                problems.append(f"`{shown} --help` names {name}, which is not in the repository")
            elif heading and heading not in headings(os.path.join(root, found)):
                problems.append(f"`{shown} --help` names the section \"{heading}\" of {found}, which has no "
                                f"such heading")
    for problem in problems:
        print(f"check_help_references: {problem}")
    print(f"check_help_references: {len(seen)} commands' --help, {references} references to the docs, "
          f"{len(problems)} problems")
    return 1 if problems or references == 0 else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__.split("\n\n")[1], file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
