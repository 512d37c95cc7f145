#!/usr/bin/env python3
"""The README a newcomer reads, and the guide it points to, hold only what exists.

Usage: check_doc_links.py REPOSITORY_ROOT. Fails (exit 1, one line per problem) when:
- README.md is longer than 250 lines, or does not give the run and test commands (./scripts/run.sh,
  ./scripts/test.sh) in a code block, or those scripts are missing or not executable;
- a relative link or image in README.md or docs/*.md ([text](path), ![alt](path), <img src="path">) points
  to no file or folder (resolved from the Markdown file's folder; web addresses and #anchors are skipped);
- a Markdown file named anywhere in them (`NAME.md`) is not in the repository.
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


def markdown_files(root):
    files = [os.path.join(root, "README.md")]
    docs = os.path.join(root, "docs")
    for folder, _, names in os.walk(docs):
        files += [os.path.join(folder, n) for n in sorted(names) if n.endswith(".md")]
    return files


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
    links = 0
    files = markdown_files(root)
    for path in files:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        found, count = link_problems(path, text)
        problems += found
        links += count
        for name in sorted(set(MD_NAME.findall(text))):
            if os.path.basename(name) not in known_md:
                problems.append(f"{path}: names {name}, which is not in the repository")

    for problem in problems:
        print(f"check_doc_links: {problem}")
    print(f"check_doc_links: {len(files)} Markdown files, {links} links, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
