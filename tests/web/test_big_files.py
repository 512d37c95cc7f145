"""Browser test of opening a big scene file in the page (docs/web.md, "Big files"): a file of 10⁵ spheres
(9.7 MB, made in the page) opened by the picker's route shows, frame by frame, the bytes read (8 MiB slices,
rising to the file's size), then a frame announcing the parse and the packing, then the count of objects
opened; the page draws frames while it reads. Usage: test_big_files.py WEB_FOLDER. Exit code 0 when all
pass, 77 (CTest's skip) without a built page."""
import os
import re
import sys

PAGE_FILES = ("index.html", "index.js", "index.wasm", "index.data")
if len(sys.argv) == 2 and any(not os.path.isfile(os.path.join(sys.argv[1], name)) for name in PAGE_FILES):
    print("skipped: %s has no built page: run ./scripts/web.sh --build-only first" % sys.argv[1], flush=True)
    sys.exit(77)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_driver import Page, open_big_scene  # noqa: E402

COUNT = 100000
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


page = Page(sys.argv[1])
try:
    page.open()
    record = open_big_scene(page, COUNT)
    statuses = [text for _, text in record["shown"]]  # what the frames drawn showed
    megabytes = record["size"] / (1024.0 * 1024.0)
    name = "big%d.json" % COUNT
    read = [float(m.group(1)) for m in (re.search(r"read ([0-9.]+) of ([0-9.]+) MB", s) for s in statuses) if m]
    check(len(read) >= 2 and read == sorted(read) and abs(read[-1] - megabytes) < 0.06,
          "the bytes read, slice by slice, up to the file's %.1f MB: %s" % (megabytes, read))
    check(all(("%s: read" % name) in s and ("of %.1f MB" % megabytes) in s for s in statuses if " read " in s),
          "  ... each naming the file and its size")
    announced = [i for i, s in enumerate(statuses) if "reading the objects of %.1f MB, then packing" % megabytes in s]
    opened = [i for i, s in enumerate(statuses) if re.search(r"opened %s \(%d objects\) in [0-9.]+ s" % (name, COUNT), s)]
    check(len(announced) == 1 and len(opened) == 1 and announced[0] < opened[0],
          "a frame announces the parse and the packing, then the count of objects opened: %s" % statuses[-3:])
    reading = [gap for at, gap in record["gaps"] if at <= record["shown"][announced[0]][0]] if announced else []
    check(len(reading) > len(read), "the page draws frames while it reads (%d frames)" % len(reading))
    title = page.call("return document.title")
    check(name in title, "the scene is on screen (title %r)" % title)
finally:
    page.close()

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
