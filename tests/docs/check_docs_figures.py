#!/usr/bin/python3
"""The example figures in docs/figures/ are what scripts/docs_figures.sh makes now from the scenes they name.

    check_docs_figures.py REPOSITORY RAYCAM_CLI

Runs the script into a temporary folder and compares every file with the committed one: the same names; SVG
and TikZ byte for byte (both are deterministic: two runs give the same bytes); PDF byte for byte but for
cairo's /CreationDate, the time of the run; PNG by decoded pixels (Debian's python3-pil), as another zlib may
compress the same pixels differently. A stale figure fails, named, with the command that remakes them.

Fonts: the text is DejaVu Sans through fontconfig, rasterised by cairo and FreeType (PNG) and written as glyph
outlines (SVG), so the files depend on the font's and those libraries' versions. The comparison is exact: the
committed files and this test both come from scripts/install-deps.sh's Debian 12 packages, where two
runs give the same pixels, and a tolerance loose enough for another FreeType would also pass a moved label.
Where fontconfig does not give DejaVu Sans the figures cannot match: the test is skipped (exit 77) and says so.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

from PIL import Image

SKIP = 77


def uses_dejavu():
    try:
        family = subprocess.run(["fc-match", "-f", "%{family}", "DejaVu Sans"], capture_output=True, text=True,
                                check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return False
    return family.split(",")[0] == "DejaVu Sans"


def without_creation_date(data):
    # The same length whatever the date, so the cross-reference table's offsets still agree.
    return re.sub(rb"/CreationDate \(D:[0-9]{14}[^)]*\)", lambda m: b"?" * len(m.group(0)), data)


def difference(committed, made):
    """What differs between two files of one name, or "" when they are the same figure."""
    if committed.endswith(".png"):
        old, new = Image.open(committed).convert("RGBA"), Image.open(made).convert("RGBA")
        if old.size != new.size:
            return "another size"
        differing = sum(a != b for a, b in zip(old.getdata(), new.getdata()))
        return "" if differing == 0 else "%d pixels differ" % differing
    with open(committed, "rb") as a, open(made, "rb") as b:
        old, new = a.read(), b.read()
    if committed.endswith(".pdf"):
        old, new = without_creation_date(old), without_creation_date(new)
    return "" if old == new else "the bytes differ"


def main(repository, cli):
    if not uses_dejavu():
        print("check_docs_figures: skipped: fontconfig gives no DejaVu Sans (fonts-dejavu-core), the figures' font")
        return SKIP
    committed_dir = os.path.join(repository, "docs", "figures")
    made_dir = tempfile.mkdtemp(prefix="raycam-docs-figures-")
    try:
        script = os.path.join(repository, "scripts", "docs_figures.sh")
        run = subprocess.run(["bash", script, cli, "--out", made_dir], capture_output=True, text=True)
        if run.returncode != 0:
            print("check_docs_figures: scripts/docs_figures.sh failed (exit %d):\n%s%s" % (run.returncode, run.stdout,
                                                                                           run.stderr))
            return 1
        committed, made = set(os.listdir(committed_dir)), set(os.listdir(made_dir))
        problems = ["%s: committed, but the script does not make it" % name for name in sorted(committed - made)]
        problems += ["%s: made by the script, but not committed" % name for name in sorted(made - committed)]
        for name in sorted(committed & made):
            what = difference(os.path.join(committed_dir, name), os.path.join(made_dir, name))
            if what:
                problems.append("%s: stale (%s)" % (name, what))
        for problem in problems:
            print("docs/figures/" + problem)
        if problems:
            print("check_docs_figures: remake them with scripts/docs_figures.sh and commit the result")
            return 1
        print("check_docs_figures: the %d files of docs/figures/ are current" % len(committed))
        return 0
    finally:
        shutil.rmtree(made_dir)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        print(__doc__.strip(), file=sys.stderr)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))
