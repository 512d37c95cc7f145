#!/usr/bin/env python3
"""Every command the docs show is run, as a reader would run it, and must do what the docs say.

Usage: run_doc_commands.py SOURCE_ROOT BUILD_DIR [--list] [--only FILE_SUBSTRING]

The ```sh blocks of README.md, docs/*.md and examples/*/README.md are run, block by block, in a scratch
folder: a fresh temporary folder holding a copy of the repository's files (as `git ls-files` lists them, with
the working tree's content) standing for a reader's clone, whose build/ holds links to BUILD_DIR's
executables, and whose build/ is first on PATH (so `raycam-cli` and `build/raycam-cli` are the built ones).
`/tmp/` in a command is the scratch folder's own tmp/, so runs never meet. Each command of a block (lines
joined at a trailing backslash; comments and blank lines left out) must exit 0, in one bash, so a variable
set by one line holds for the next.

HTML comments just before a block (blank lines between are allowed) say how to run it, one per comment:
  <!-- doc-test: skip (REASON) -->          not run: it needs a display, the network, root, a cluster... The
                                            reason is required.
  <!-- doc-test: short (REASON): COMMANDS --> COMMANDS (shell) run instead of the block: its quick form.
  <!-- doc-test: in DIR -->                 the block runs in DIR of the scratch clone (default: its root).
  <!-- doc-test: setup (REASON): COMMANDS --> run first, in the same folder: a file the reader has and the
                                            scratch clone does not (a student's program, a class's folders).
  <!-- doc-test: exit N -->                 every command of the block must exit N (an error example).
  <!-- doc-test: output in the next block -->  each line of the next fenced block must be in the block's output.
  <!-- doc-test: files: NAME... -->         these files must exist after the block (the ones it says it writes).
A marker anywhere else, not before a block:
  <!-- doc-test: stated: COMMAND -->        the next line of text must hold, as a word, the number COMMAND
                                            prints (run in the scratch clone), so a count cannot go stale.

Fails (exit 1, naming the file, the line and the command) when a command's exit status or a check differs, when
a marker is not understood or a skip gives no reason. Prints one line per block run or skipped.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

MARKER = re.compile(r"^\s*<!--\s*doc-test:\s*(.*?)\s*-->\s*$")
FENCE_OPEN = re.compile(r"^(\s*)(```+)\s*(\S*)\s*$")
COMMAND_TIMEOUT = 60  # seconds a block may run: all of them together take about 20 s, the CTest allows 90


def doc_files(root):
    files = ["README.md"]
    files += sorted("docs/" + n for n in os.listdir(os.path.join(root, "docs")) if n.endswith(".md"))
    examples = os.path.join(root, "examples")
    files += sorted(f"examples/{d}/README.md" for d in os.listdir(examples)
                    if os.path.isfile(os.path.join(examples, d, "README.md")))
    return files


class Block:
    def __init__(self, path, line, text, markers, next_block):
        self.path, self.line, self.text, self.markers, self.next_block = path, line, text, markers, next_block


def parse(path, text):
    """The sh blocks with their markers, and the `stated:` markers with the line after each."""
    lines = text.split("\n")
    blocks, stated, fences = [], [], []
    pending = []  # markers seen since the last block or prose line
    i = 0
    while i < len(lines):
        line = lines[i]
        m = MARKER.match(line)
        if m:
            directive = m.group(1)
            if directive.startswith("stated:"):
                j = i + 1
                while j < len(lines) and not lines[j].strip():
                    j += 1
                stated.append((i + 1, directive[len("stated:"):].strip(), lines[j] if j < len(lines) else ""))
            else:
                pending.append((i + 1, directive))
            i += 1
            continue
        f = FENCE_OPEN.match(line)
        if f:
            indent, ticks, lang = f.groups()
            body = []
            j = i + 1
            while j < len(lines) and not re.match(r"^\s*" + ticks + r"\s*$", lines[j]):
                body.append(lines[j][len(indent):] if lines[j].startswith(indent) else lines[j])
                j += 1
            fences.append((i + 1, lang, "\n".join(body), pending))
            pending = []
            i = j + 1
            continue
        if line.strip():
            if pending:  # a marker must sit just before its block
                for number, directive in pending:
                    raise SyntaxError(f"{path}:{number}: doc-test marker '{directive}' is not just before a block")
        i += 1
    if pending:
        raise SyntaxError(f"{path}:{pending[0][0]}: doc-test marker after the last block")
    for index, (number, lang, body, markers) in enumerate(fences):
        following = fences[index + 1][2] if index + 1 < len(fences) else None
        if lang == "sh":
            blocks.append(Block(path, number, body, markers, following))
        elif markers:
            raise SyntaxError(f"{path}:{number}: doc-test marker before a ```{lang} block (only ```sh blocks run)")
    return blocks, stated


def commands_of(text):
    """The block's commands: continuation lines joined, comments and blank lines left out."""
    commands, current = [], ""
    for line in text.split("\n"):
        if not current and (not line.strip() or line.lstrip().startswith("#")):
            continue
        if line.rstrip().endswith("\\"):
            current += line.rstrip()[:-1] + " "
            continue
        commands.append(current + line)
        current = ""
    if current:
        commands.append(current)
    return commands


def scratch_clone(root, build, scratch):
    """The repository's files as a reader's clone has them, plus build/ of links to the built executables."""
    clone = os.path.join(scratch, "repo")
    try:
        listed = subprocess.run(["git", "-C", root, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                                capture_output=True, check=True).stdout.decode().split("\0")
    except (OSError, subprocess.CalledProcessError):  # not a git checkout: every file but builds and .git
        listed = []
        for folder, dirs, names in os.walk(root):
            dirs[:] = [d for d in dirs if d != ".git" and not d.startswith("build")]
            listed += [os.path.relpath(os.path.join(folder, n), root) for n in names]
    for name in filter(None, listed):
        source = os.path.join(root, name)
        if not os.path.isfile(source) or name.startswith("build"):
            continue
        target = os.path.join(clone, name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy2(source, target)
    os.makedirs(os.path.join(clone, "build"))
    for name in os.listdir(build):
        path = os.path.join(build, name)
        if os.path.isfile(path) and os.access(path, os.X_OK):
            os.symlink(os.path.abspath(path), os.path.join(clone, "build", name))
    os.makedirs(os.path.join(scratch, "tmp"))
    return clone


def run_shell(script, cwd, env):
    started = time.monotonic()
    try:
        done = subprocess.run(["bash", "-c", script], cwd=cwd, env=env, capture_output=True, text=True,
                              timeout=COMMAND_TIMEOUT, stdin=subprocess.DEVNULL)
        return done.returncode, done.stdout + done.stderr, time.monotonic() - started
    except subprocess.TimeoutExpired as e:
        out = (e.stdout or b"").decode(errors="replace") + (e.stderr or b"").decode(errors="replace")
        return None, out, time.monotonic() - started


def markers_of(block):
    """The block's directives as a dict; raises on anything not understood."""
    got = {}
    for number, directive in block.markers:
        where = f"{block.path}:{number}"
        m = re.match(r"^(skip|short|setup)\s*\(([^)]*)\)\s*(?::\s*(.*))?$", directive)
        if m:
            kind, reason, commands = m.groups()
            if not reason.strip():
                raise SyntaxError(f"{where}: doc-test {kind} without a reason")
            if kind != "skip" and not commands:
                raise SyntaxError(f"{where}: doc-test {kind} without its commands")
            got[kind] = (reason.strip(), commands)
        elif re.match(r"^skip\b|^short\b|^setup\b", directive):
            raise SyntaxError(f"{where}: doc-test '{directive}': give the reason in parentheses")
        elif re.match(r"^in\s+\S+$", directive):
            got["in"] = directive.split(None, 1)[1]
        elif re.match(r"^exit\s+\d+$", directive):
            got["exit"] = int(directive.split()[1])
        elif directive == "output in the next block":
            got["output"] = True
        elif directive.startswith("files:"):
            got["files"] = directive[len("files:"):].split()
        else:
            raise SyntaxError(f"{where}: doc-test marker not understood: '{directive}'")
    return got


def run_block(block, clone, env):
    """Problems of one block (empty when it did what its doc says), and a line to print."""
    got = markers_of(block)
    where = f"{block.path}:{block.line}"
    if "skip" in got:
        return [], f"skip  {where} ({got['skip'][0]})"
    cwd = os.path.join(clone, got.get("in", "."))
    if not os.path.isdir(cwd):
        return [f"{where}: doc-test in {got['in']}: no such folder in the clone"], f"FAIL  {where}"
    if "setup" in got:
        status, out, _ = run_shell(got["setup"][1], cwd, env)
        if status != 0:
            return [f"{where}: the setup '{got['setup'][1]}' exited {status}:\n{out}"], f"FAIL  {where}"
    commands = [got["short"][1]] if "short" in got else commands_of(block.text)
    want = got.get("exit", 0)
    # One bash for the block: after each command its status is checked, and the first wrong one stops it.
    script = ["set -o pipefail"]
    for index, command in enumerate(commands):
        script.append(command)
        script.append(f'__s=$?; if [ "$__s" -ne {want} ]; then echo "doc-test: command {index + 1} exited $__s"'
                      f' >&2; exit 200; fi')
    script.append("exit 0")
    status, out, seconds = run_shell("\n".join(script), cwd, env)
    problems = []
    if status is None:
        problems.append(f"{where}: still running after {COMMAND_TIMEOUT} s (mark it with a short form)")
    elif status != 0:
        failed = re.search(r"doc-test: command (\d+) exited (\d+)", out)
        if failed:
            command = commands[int(failed.group(1)) - 1]
            problems.append(f"{where}: '{command.strip()}' exited {failed.group(2)}, the doc expects {want}")
        else:
            problems.append(f"{where}: the block exited {status}")
    if got.get("output"):
        if block.next_block is None:
            problems.append(f"{where}: 'output in the next block' but no block follows")
        else:
            for line in filter(None, (l.strip() for l in block.next_block.split("\n"))):
                if line not in out:
                    problems.append(f"{where}: the output has no line '{line}'")
    for name in got.get("files", []):
        if not os.path.exists(os.path.join(cwd, name)):
            problems.append(f"{where}: the block should have written {name}")
    if problems:
        tail = "\n".join(out.strip().split("\n")[-15:])
        problems[-1] += f"\n--- its output (last lines) ---\n{tail}"
    shown = "short " if "short" in got else "run   "
    return problems, f"{'FAIL  ' if problems else shown}{where} ({seconds:.1f} s)"


def check_stated(path, number, command, line, clone, env):
    status, out, _ = run_shell(command, clone, env)
    value = out.strip()
    if status != 0 or not re.fullmatch(r"\d+", value):
        return [f"{path}:{number}: stated: '{command}' exited {status} and printed '{value[:200]}', not a number"]
    if not re.search(r"(?<![\d.])" + value + r"(?![\d.])", line):
        return [f"{path}:{number}: the line after says '{line.strip()}', but '{command}' gives {value}"]
    return []


def main(argv):
    parser = argparse.ArgumentParser(description="Runs the docs' sh blocks in a scratch clone.")
    parser.add_argument("root")
    parser.add_argument("build")
    parser.add_argument("--list", action="store_true", help="list the blocks and their markers, run nothing")
    parser.add_argument("--only", help="only the docs whose path holds this text")
    options = parser.parse_args(argv)
    root, build, only = os.path.abspath(options.root), os.path.abspath(options.build), options.only
    problems, ran, skipped = [], 0, 0
    parsed = []
    for path in doc_files(root):
        if only and only not in path:
            continue
        with open(os.path.join(root, path), encoding="utf-8") as f:
            try:
                parsed.append((path, *parse(path, f.read())))
            except SyntaxError as e:
                problems.append(str(e))
    if options.list:
        for path, blocks, stated in parsed:
            for block in blocks:
                print(f"{path}:{block.line}: {commands_of(block.text)} {[d for _, d in block.markers]}")
        return 0
    with tempfile.TemporaryDirectory(prefix="raycam-doc-test.") as scratch:
        os.chmod(scratch, 0o755)  # as a home folder is: the sandbox runs the student as another user
        clone = scratch_clone(root, build, scratch)
        env = dict(os.environ)
        env["PATH"] = os.path.join(clone, "build") + os.pathsep + env.get("PATH", "")
        env["TMPDIR"] = os.path.join(scratch, "tmp")
        env.pop("LANG", None)  # the docs' outputs are in English unless a command says --lang
        env["LC_ALL"] = "C.UTF-8"
        for path, blocks, stated in parsed:
            for block in blocks:
                block.text = block.text.replace("/tmp/", os.path.join(scratch, "tmp") + "/")
                for i, (n, d) in enumerate(block.markers):
                    block.markers[i] = (n, d.replace("/tmp/", os.path.join(scratch, "tmp") + "/"))
                try:
                    found, line = run_block(block, clone, env)
                except SyntaxError as e:
                    found, line = [str(e)], f"FAIL  {block.path}:{block.line}"
                print(line, flush=True)
                problems += found
                skipped += line.startswith("skip")
                ran += not line.startswith("skip")
            for number, command, line in stated:
                found = check_stated(path, number, command, line, clone, env)
                print(f"{'FAIL  ' if found else 'count '}{path}:{number} ({command})", flush=True)
                problems += found
    for problem in problems:
        print(f"run_doc_commands: {problem}")
    print(f"run_doc_commands: {ran} blocks run, {skipped} skipped (each with its reason), {len(problems)} problems")
    return 1 if problems or ran == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
