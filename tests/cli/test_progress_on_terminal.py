#!/usr/bin/env python3
"""On a terminal, a long command's progress line is rewritten in place and fits the terminal's width.

Usage: test_progress_on_terminal.py RAYCAM_CLI. Runs `bench accuracy --quick` (a few settings) with stderr on a
pseudo-terminal 60 columns wide (stdout, the table, sent away) in a temporary folder of its own, and checks
what the terminal receives: every step drawn after a carriage return, one newline only (the closing line's),
no drawn line wider than 59 columns (one that wraps could not be rewritten from its start), a long step's
name shortened from its beginning ("...") while the count, the share and the time left stay, and the first
and last steps there.
"""
import fcntl
import os
import pty
import re
import struct
import subprocess
import sys
import tempfile
import termios

COLUMNS = 60


def main(cli):
    master, slave = pty.openpty()
    fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, COLUMNS, 0, 0))
    with tempfile.TemporaryDirectory(prefix="raycam-progress-") as folder:
        process = subprocess.Popen([os.path.abspath(cli), "bench", "accuracy", "--quick", "--repeats", "1", "--precision", "double",
                                    "--intersect", "stable", "--spp", "1", "--csv", "a.csv"],
                                   cwd=folder, stdout=subprocess.DEVNULL, stderr=slave, stdin=subprocess.DEVNULL)
        os.close(slave)
        received = b""
        while True:
            try:
                chunk = os.read(master, 65536)
            except OSError:  # the other end closed: Linux reports EIO
                break
            if not chunk:
                break
            received += chunk
        status = process.wait()
        os.close(master)
    text = received.decode("utf-8", "replace").replace("\r\n", "\n")  # the terminal's own newline translation
    problems = []
    if status != 0:
        problems.append("exit status %d" % status)
    if text.count("\n") != 1 or not text.endswith("\n"):
        problems.append("%d newlines: the steps should share one line" % text.count("\n"))
    drawn = [line.rstrip(" ") for line in re.split(r"[\r\n]", text) if line.strip()]
    steps = [line for line in drawn if re.match(r"bench accuracy: [0-9]+/[0-9]+ ", line)]
    if not steps or not steps[0].startswith("bench accuracy: 1/"):
        problems.append("no first step drawn")
    if not any(re.match(r"bench accuracy: ([0-9]+)/\1 ", line) for line in steps):
        problems.append("no last step drawn")
    problems += ["wider than %d columns: %r" % (COLUMNS - 1, line)
                 for line in re.split(r"[\r\n]", text) if len(line) > COLUMNS - 1]
    shortened = [line for line in steps if "(..." in line]
    if not shortened:
        problems.append("no step's name was shortened to fit (expected for '2d-translated reference' at %d columns)"
                        % COLUMNS)
    problems += ["shortened without its share or time left: %r" % line for line in shortened
                 if not re.search(r"\), [0-9]+ %(, about [0-9][0-9 a-z]* left)?$", line)]
    if not re.search(r"bench accuracy: [0-9]+ steps in [0-9]+ s *\n$", text):
        problems.append("no closing line")
    for problem in problems:
        print("FAIL: " + problem)
    if problems:
        print("received: %r" % text[:2000])
        return 1
    print("%d steps drawn in place, the widest %d columns" % (len(steps), max(len(line) for line in drawn)))
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
