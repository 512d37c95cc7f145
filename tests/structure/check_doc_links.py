#!/usr/bin/env python3
"""The README a newcomer reads, and the guide it points to, hold only what exists.

Usage: check_doc_links.py REPOSITORY_ROOT. Fails (exit 1, one line per problem) when:
- README.md is longer than 250 lines, or does not give the run and test commands (./scripts/run.sh,
  ./scripts/test.sh) in a code block, or those scripts are missing or not executable;
- a relative link or image in README.md or docs/*.md ([text](path), ![alt](path), <img src="path">) points
  to no file or folder (resolved from the Markdown file's folder; web addresses and #anchors are skipped);
- a Markdown file named anywhere in them (`NAME.md`) is not in the repository;
- a path written in backticks (`src/core/scene.cpp`, or a word of `raycam-cli render --scene scenes/x.json`)
  whose first folder is one of the repository's own (src/, tests/, docs/...) names no file or folder, resolved
  from the repository's root; or a source file named alone (`view_setup.h`, `band_kernels.cpp`) is nowhere in it.
  Words with wildcards, braces or an ellipsis (`index.{html,js}`, `*.md`, `src/…`) are patterns, not paths, and are
  skipped.
"""
import os
import re
import sys

MAX_README_LINES = 250
COMMANDS = ["./scripts/run.sh", "./scripts/test.sh"]

FENCE = re.compile(r"^```.*?^```[^\n]*$", re.S | re.M)
INLINE_CODE = re.compile(r"`[^`\n]*`")
LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HTML_LINK = re.compile(r"""<(?:img|a)\b[^>]*?\b(?:src|href)\s*=\s*["']([^"']+)["']""", re.I)
MD_NAME = re.compile(r"(?<![\w./-])((?:[\w.-]+/)*[\w.-]+\.md)\b")
SCHEME = re.compile(r"^[a-zA-Z][a-zA-Z0-9+.-]*:")
CODE_SPAN = re.compile(r"`([^`\n]+)`")
# A file named alone with one of these endings is the repository's own source, so it must exist somewhere in it;
# other endings (map.png, scene.json, my_camera.py) are as often a user's file as one of ours.
SOURCE_ENDINGS = (".h", ".cpp", ".cmake", ".glsl", ".vert", ".frag")
PATH_WORD_TRIM = "\"'.,;:()[]<>"


def markdown_files(root):
    files = [os.path.join(root, "README.md")]
    docs = os.path.join(root, "docs")
    for folder, _, names in os.walk(docs):
        files += [os.path.join(folder, n) for n in sorted(names) if n.endswith(".md")]
    return files


def repository_file_names(root):
    """Every file's name (no folder) in the repository, build folders and .git left out."""
    names = set()
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d != ".git" and not d.startswith("build")]
        names.update(files)
    return names


def top_level_folders(root):
    return {d for d in os.listdir(root)
            if os.path.isdir(os.path.join(root, d)) and d != ".git" and not d.startswith("build")}


def path_words(text):
    """The words of every inline code span outside fenced blocks, trimmed of surrounding punctuation."""
    for span in CODE_SPAN.findall(FENCE.sub("", text)):
        for word in span.split():
            word = word.strip(PATH_WORD_TRIM)
            if "=" in word:  # --scene=scenes/x.json
                word = word.split("=", 1)[1]
            word = re.sub(r"(:\d+|'s)$", "", word.split("#", 1)[0])  # file.cpp:120, file.md#anchor, x.md's
            if word and not any(c in word for c in "*?{}$%…"):
                yield word


def backtick_path_problems(root, path, text, folders, file_names):
    problems = []
    checked = 0
    for word in sorted(set(path_words(text))):
        first = word.split("/", 1)[0]
        if "/" in word and first in folders:
            checked += 1
            if not os.path.exists(os.path.join(root, word)):
                problems.append(f"{path}: names `{word}`, which is not in the repository")
        elif "/" not in word and word.endswith(SOURCE_ENDINGS):
            checked += 1
            if word not in file_names:
                problems.append(f"{path}: names the file `{word}`, which is nowhere in the repository")
    return problems, checked


def repository_md_names(root):
    names = set()
    for folder, dirs, files in os.walk(root):
        dirs[:] = [d for d in dirs if d != ".git" and not d.startswith("build")]
        names.update(f for f in files if f.endswith(".md"))
    return names


def link_problems(path, text):
    problems = []
    prose = INLINE_CODE.sub("", FENCE.sub("", text))
    targets = LINK.findall(prose) + HTML_LINK.findall(prose)
    for target in targets:
        if SCHEME.match(target) or target.startswith("#"):
            continue
        file_part = target.split("#", 1)[0].split("?", 1)[0]
        resolved = os.path.normpath(os.path.join(os.path.dirname(path), file_part))
        if not os.path.exists(resolved):
            problems.append(f"{path}: link to '{target}': no such file")
    return problems, len(targets)


def main(root):
    problems = []
    readme = os.path.join(root, "README.md")
    with open(readme, encoding="utf-8") as f:
        readme_text = f.read()
    lines = readme_text.count("\n") + (0 if readme_text.endswith("\n") else 1)
    if lines > MAX_README_LINES:
        problems.append(f"{readme}: {lines} lines, more than {MAX_README_LINES}: move detail to docs/")
    code = "\n".join(FENCE.findall(readme_text))
    for command in COMMANDS:
        if command not in code:
            problems.append(f"{readme}: the command {command} is not in a code block")
        script = os.path.join(root, command)
        if not (os.path.isfile(script) and os.access(script, os.X_OK)):
            problems.append(f"{readme}: the command {command} is not an executable file")

    known_md = repository_md_names(root)
    file_names = repository_file_names(root)
    folders = top_level_folders(root)
    links = 0
    paths = 0
    files = markdown_files(root)
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        found, count = link_problems(path, text)
        problems += found
        links += count
        found, count = backtick_path_problems(root, path, text, folders, file_names)
        problems += found
        paths += count
        for name in sorted(set(MD_NAME.findall(text))):
            if os.path.basename(name) not in known_md:
                problems.append(f"{path}: names {name}, which is not in the repository")

    for problem in problems:
        print(f"check_doc_links: {problem}")
    print(f"check_doc_links: {len(files)} Markdown files, {links} links, {paths} paths in backticks, "
          f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
