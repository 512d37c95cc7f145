"""Browser test of opening big scene files in the page (docs/web.md, "Big files"): files of 10⁵ and 10⁶ spheres
(9.7 and 97 MB, made in the page) opened by the picker's route show, frame by frame, the bytes read (8 MiB
slices, rising to the file's size), a frame announcing the parse, the objects read rising to the file's count
(the parse cut into slices of one frame each), a frame announcing the packing, then the count of objects
opened; the page never waits longer than MAX_GAP_MS between two animation frames while it opens them; the
scene on screen casts the ids `raycam-cli render --ids` casts from the same file.
Usage: test_big_files.py WEB_FOLDER RAYCAM_CLI. Exit code 0 when all pass, 77 (CTest's skip) without a built
page."""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_checks import check, failures, skip_unless_built  # noqa: E402

web_folder, cli = sys.argv[1:3]
skip_unless_built(web_folder, ("index.html", "index.js", "index.wasm", "index.data"))
from page_driver import Page, open_big_scene  # noqa: E402

COUNTS = (100000, 1000000)
# The longest wait allowed between two animation frames while a file opens: a parse slice (50 ms,
# scene_loading.cpp) plus the frame drawn after it (30-80 ms in software WebGL), or an 8 MiB slice of the
# reading (a copy). Measured 83-112 ms with the shared 2-core machine lightly loaded, and up to 460 ms when
# other builds and browsers held it (a load of 7-8, 2026-11-26). The parse in one step waited 1.0-1.8 s at 10⁵
# and 7-13 s at 10⁶ (the same loads): 2 and 14 times the bound at the least. At 10⁵ the bound holds to the
# first image; at 10⁶ the frame that packs and draws 10⁶ objects (0.7-1.4 s) is one step, printed, not
# bounded (docs/web.md).
MAX_GAP_MS = 500


def ids_match_the_cli(page, name, scratch):
    """The ids of the scene on screen against raycam-cli render --ids on the file the page opened."""
    page.call("Module.ccall('raycam_shown_ids', 'number', ['string'], ['/picked/shown_ids.txt'])")
    shown = page.call("return FS.readFile('/picked/shown_ids.txt', {encoding: 'utf8'})")
    scene = os.path.join(scratch, name)
    with open(scene, "w") as out:
        out.write(page.call("return FS.readFile('/picked/' + arguments[0], {encoding: 'utf8'})", name))
    native = os.path.join(scratch, "native_ids.txt")
    run = subprocess.run([cli, "render", "--scene", scene, "--ids", native], capture_output=True, text=True)
    if run.returncode != 0:
        return False, "raycam-cli failed: " + run.stderr.strip()
    with open(native) as text:
        expected = text.read()
    return shown == expected and expected != "", "%d lines" % expected.count("\n")


page = Page(web_folder)
try:
    page.open()
    with tempfile.TemporaryDirectory() as scratch:
        for count in COUNTS:
            record = open_big_scene(page, count, seconds=200)
            print("%d spheres: opened in %.1f s" % (count, record["total_ms"] / 1000.0), flush=True)
            statuses = [text for _, text in record["shown"]]  # what the frames drawn showed
            megabytes = record["size"] / (1024.0 * 1024.0)
            name = "big%d.json" % count
            read = [float(m.group(1)) for m in (re.search(r"read ([0-9.]+) of ([0-9.]+) MB", s) for s in statuses) if m]
            check(len(read) >= 2 and read == sorted(read) and abs(read[-1] - megabytes) < 0.06,
                  "the bytes read, slice by slice, up to the file's %.1f MB: %s" % (megabytes, read))
            check(all(("%s: read" % name) in s and ("of %.1f MB" % megabytes) in s
                      for s in statuses if re.search(r": read [0-9.]+ of", s)),
                  "  ... each naming the file and its size")
            announced = [i for i, s in enumerate(statuses) if "reading the objects of %.1f MB, then packing" % megabytes in s]
            parsed = [(int(m.group(1)), int(m.group(2))) for m in
                      (re.search(r"%s: objects read (\d+) of (\d+)" % name, s) for s in statuses) if m]
            packing = [i for i, s in enumerate(statuses) if "%s: packing %d objects" % (name, count) in s]
            opened = [i for i, s in enumerate(statuses) if re.search(r"opened %s \(%d objects\) in [0-9.]+ s" % (name, count), s)]
            check(len(announced) == 1 and len(packing) == 1 and len(opened) == 1 and announced[0] < packing[0] < opened[0],
                  "frames announce the parse, then the packing, then the count of objects opened: %s" % statuses[-3:])
            check(len(parsed) >= 3 and all(total == count for _, total in parsed) and
                  [n for n, _ in parsed] == sorted(n for n, _ in parsed) and parsed[0][0] < parsed[-1][0] < count,
                  "the objects read, frame by frame, rising towards %d (%d frames: %s ...)" % (count, len(parsed), parsed[:3]))
            at_packing = record["shown"][packing[0]][0] if packing else 0
            at_announce = record["shown"][announced[0]][0] if announced else 0
            reading = [gap for at, gap in record["gaps"] if at <= at_announce]
            check(len(reading) > len(read), "the page draws frames while it reads (%d frames)" % len(reading))
            parsing = [gap for at, gap in record["gaps"] if at_announce < at <= at_packing]
            last = [gap for at, gap in record["gaps"] if at > at_packing]
            print("  longest waits between frames: reading %.0f ms, parsing %.0f ms (%d frames); then the packing "
                  "and the first image: %s ms" % (max(reading or [0]), max(parsing or [0]), len(parsing),
                                                   [round(gap) for gap in last]), flush=True)
            # 10⁶: the packing (0.2-0.3 s) and the first frame drawing 10⁶ objects are one step: not bounded.
            bounded = record["gaps"] if count == COUNTS[0] else [(at, gap) for at, gap in record["gaps"] if at <= at_packing]
            longest = max(gap for _, gap in bounded)
            check(packing and longest < MAX_GAP_MS,
                  "no wait between two frames longer than %d ms %s: %.0f ms"
                  % (MAX_GAP_MS, "while it opens" if count == COUNTS[0] else "until the packing", longest))
            title = page.call("return document.title")
            check(name in title, "the scene is on screen (title %r)" % title)
            if count == COUNTS[0]:  # 9.7 MB through the driver; 97 MB would take longer than the rest
                same, what = ids_match_the_cli(page, name, scratch)
                check(same, "the scene on screen casts raycam-cli render's ids from the same file (%s)" % what)
finally:
    page.close()

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
