#!/usr/bin/python3
"""Speed of the web page against the native program, same machine, same run (docs/web.md; a benchmark,
not a test): a cast at 256² (the automatic caster) of scenes/many3d.json, of every scene of the bench
families (`raycam-cli bench speed --write-family`, K = 10³, 10⁴, 10⁵) and of sparse scenes (the cube family,
K = 50 to 500), in headless Chromium (the page's one thread) and in `raycam-cli bench speed --threads 1`.
The two sides alternate, scene by scene, for --rounds rounds (the machine's load then weighs on both
alike); the table gives each side's median over the rounds and their ratio, with the lowest and highest
ratio of a round, by the wall clock and by CPU time (the page thread's, from /proc, and bench speed's process
time: on a loaded machine the wall clock also counts other programs' turns on the core, one side's more than
the other's in a round). Each round's figures go to stderr. Then the idle page's CPU time over 10 s.
With --big: instead, opening scene files of 10⁵ and 10⁶ spheres in the page by the picker's route (made in
the page): the time to the first image; how long the reading and the parse took, with the longest wait
between two animation frames in each (and the parse's frames); the wait of the step that packs the objects
and draws the first image.
Usage: scripts/bench_web.py [--rounds N] [--quick | --big] [--only TEXT] [WEB_FOLDER] [RAYCAM_CLI]
       (defaults: 3 rounds, build-web, build/raycam-cli; --quick: K = 10³ and the sparse scenes only;
       --only: the scenes whose label holds TEXT)"""
import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(root, "tests", "web"))
from page_driver import Page, browser_cpu_seconds, open_big_scene  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("--rounds", type=int, default=3, help="rounds of the alternation (1 to 20, default 3)")
parser.add_argument("--quick", action="store_true", help="K = 10³ and the sparse scenes only")
parser.add_argument("--only", default="", help="only the scenes whose label holds this text (e.g. 'clumps')")
parser.add_argument("--big", action="store_true", help="time opening 10⁵ and 10⁶ spheres in the page instead")
parser.add_argument("--same-width", metavar="CLI", default="",
                    help="also time this raycam-cli, built with -DRAYCAM_VECTOR_CLONES=OFF (its loops two doubles a "
                         "vector, as WebAssembly's), in the same alternation, and give the page against it")
parser.add_argument("web_folder", nargs="?", default=os.path.join(root, "build-web"))
parser.add_argument("cli", nargs="?", default=os.path.join(root, "build", "raycam-cli"))
arguments = parser.parse_args()
if not 1 <= arguments.rounds <= 20:
    parser.error("--rounds: expected 1 to 20, got %d" % arguments.rounds)
cli = arguments.cli
if arguments.same_width and not os.access(arguments.same_width, os.X_OK):
    parser.error("--same-width: no program at %s (build one: cmake -S . -B build-narrow -DRAYCAM_VECTOR_CLONES=OFF, "
                 "then cmake --build build-narrow --target raycam-cli)" % arguments.same_width)

FAMILY_COUNTS = [1000] if arguments.quick else [1000, 10000, 100000]
SPARSE_COUNTS = [50, 100, 200, 500]
SIDE = 256


def family_names():
    """The families' names, as `bench speed` lists them in its error for an unknown one ("expected A, B or C")."""
    run = subprocess.run([cli, "bench", "speed", "--write-family", "?", "--to", os.devnull],
                         capture_output=True, text=True)
    listed = re.search(r"expected (.*), got", run.stderr)
    if not listed:
        raise RuntimeError("raycam-cli did not list its scene families: %s" % run.stderr)
    return re.split(r", | or ", listed.group(1))


def write_family(name, count, path):
    subprocess.run([cli, "bench", "speed", "--write-family", name, "--family-counts", str(count), "--to", path],
                   capture_output=True, text=True, check=True)


def native_ms(scene, program=None):
    """(wall, CPU) milliseconds of a cast: the medians of `bench speed`'s repetitions (its CPU time is the
    process's: one thread)."""
    run = subprocess.run([program or cli, "bench", "speed", "--scene", scene, "--size", str(SIDE), "--threads", "1",
                          "--repeats", "5", "--benchmark_filter=automatic"], capture_output=True, text=True,
                         check=True)
    median = re.search(r"automatic\S*real_time_median\s+([0-9.]+) ms\s+([0-9.]+) ms", run.stdout)
    return float(median.group(1)), float(median.group(2))


def page_thread_seconds(page):
    """CPU time of the page's thread: the main thread of the browser's renderer processes."""
    return browser_cpu_seconds(page, renderers_main_thread=True)


def page_error(page):
    return page.call("return Module.ccall('raycam_last_error', 'string', [], []);")


def page_ms(page, page_path):
    """(wall, CPU) milliseconds of a cast in the page: prepared (parsed, packed, half a second of warm-up
    casts), then the median of 21 samples of at least 20 ms each by the page's clock (it counts in 0.1 ms),
    and the page thread's CPU time over all the samples divided by their casts (/proc counts in 10 ms)."""
    if page.call("return Module.ccall('raycam_prepare_cast', 'number', ['string', 'number'], [arguments[0], arguments[1]]);",
                 page_path, SIDE) != 0:
        raise RuntimeError("the page could not time %s: %s" % (page_path, page_error(page)))
    before = page_thread_seconds(page)
    wall = page.call("return Module.ccall('raycam_time_prepared_cast', 'number', ['number'], [21]);")
    cpu = page_thread_seconds(page) - before
    casts = page.call("return Module.ccall('raycam_casts_timed', 'number', [], []);")
    return wall, 1000.0 * cpu / casts


def cpu_seconds(pid):
    """User + system CPU time of a process and all its descendants (the browser's every process)."""
    total = 0.0
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open("/proc/%s/stat" % entry) as text:
                fields = text.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        ancestor, probe = int(entry), int(entry)
        while probe > 1 and probe != pid:
            try:
                with open("/proc/%d/stat" % probe) as text:
                    probe = int(text.read().rsplit(")", 1)[1].split()[1])
            except OSError:
                probe = 0
        if probe == pid or ancestor == pid:
            total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    return total


def k_label(count):
    return {1000: "10³", 10000: "10⁴", 100000: "10⁵"}.get(count, str(count))


def big_files():
    """Opening big scene files in the page: the table of docs/web.md's "Big files"."""
    page = Page(arguments.web_folder)
    try:
        page.open()
        print("| spheres | file | first image | reading (longest wait) | parse (longest wait, frames) "
              "| packing and first image (wait) |")
        print("|---|---|---|---|---|---|")
        for count in (100000, 1000000):
            record = open_big_scene(page, count, seconds=300)
            announced = next(at for at, text in record["shown"] if "reading the objects" in text)
            # The parse ends at the frame announcing the packing (a build that parses in one step has none).
            parsed = next((at for at, text in record["shown"] if ": packing " in text), record["total_ms"])
            reading = [gap for at, gap in record["gaps"] if at <= announced]
            parsing = [gap for at, gap in record["gaps"] if announced < at <= parsed]
            last = [gap for at, gap in record["gaps"] if at > parsed]
            print("| %d | %.1f MB | %.1f s | %.2f s (%.0f ms) | %.1f s (%.0f ms, %d) | %s |"
                  % (count, record["size"] / 1048576.0, record["total_ms"] / 1000.0, announced / 1000.0,
                     max(reading), (parsed - announced) / 1000.0, max(parsing), len(parsing),
                     "%.0f ms" % max(last) if last else "in the parse"), flush=True)
    finally:
        page.close()


if arguments.big:
    big_files()
    sys.exit(0)

with tempfile.TemporaryDirectory() as scratch:
    scenes = [("scenes/many3d.json", os.path.join(root, "scenes", "many3d.json"))]
    for count in SPARSE_COUNTS:
        path = os.path.join(scratch, "sparse%d.json" % count)
        write_family("cube", count, path)
        scenes.append(("sparse: cube, K = %d" % count, path))
    for name in family_names():
        for count in FAMILY_COUNTS:
            path = os.path.join(scratch, "family%d-%d.json" % (len(scenes), count))
            write_family(name, count, path)
            scenes.append(("%s, K = %s" % (name, k_label(count)), path))
    scenes = [scene for scene in scenes if arguments.only in scene[0]]
    if not scenes:
        parser.error("--only: no scene's label holds '%s'" % arguments.only)
    page = Page(arguments.web_folder)
    try:
        page.open()
        page_paths = []
        for index, (_, path) in enumerate(scenes):  # into the page's file system once
            with open(path) as text:
                page_paths.append("/bench%d.json" % index)
                page.call("FS.writeFile(arguments[0], arguments[1]);", page_paths[-1], text.read())
        native = [[] for _ in scenes]  # (wall, CPU) a round
        web = [[] for _ in scenes]
        narrow = [[] for _ in scenes]  # --same-width's program
        sides = (0, 1, 2) if arguments.same_width else (0, 1)
        for round_index in range(arguments.rounds):
            for index, (label, path) in enumerate(scenes):
                # Alternately: native first in even rounds, the page first in odd ones.
                for side in (sides if round_index % 2 == 0 else sides[::-1]):
                    if side == 0:
                        native[index].append(native_ms(path))
                    elif side == 1:
                        web[index].append(page_ms(page, page_paths[index]))
                    else:
                        narrow[index].append(native_ms(path, arguments.same_width))
                print("round %d, %s: native %.3f ms (CPU %.3f), page %.3f ms (CPU %.3f)"
                      % ((round_index + 1, label) + native[index][-1] + web[index][-1])
                      + (", native at two doubles a vector %.3f ms (CPU %.3f)" % narrow[index][-1]
                         if narrow[index] else ""), file=sys.stderr)
        print("%d rounds, native and page alternating, %d² pixels; medians over the rounds\n"
              % (arguments.rounds, SIDE))
        same_width_heading = ("| CPU: native, two doubles a vector | page / it " if arguments.same_width else "")
        print("| scene | native, 1 thread | page (Chromium, WebAssembly) | page / native | rounds' ratios "
              "| CPU: native | page | page / native | rounds' ratios " + same_width_heading + "|")
        print("|---" * (9 + (2 if arguments.same_width else 0)) + "|")
        ratios = {0: [], 1: [], 2: []}
        for index, (label, _) in enumerate(scenes):
            row = "| %s " % label
            for clock in (0, 1):  # wall, then CPU
                n = statistics.median(sample[clock] for sample in native[index])
                w = statistics.median(sample[clock] for sample in web[index])
                per_round = [b[clock] / a[clock] for a, b in zip(native[index], web[index])]
                ratios[clock].append(w / n)
                row += "| %.3f ms | %.3f ms | %.2f× | %.2f–%.2f× " % (n, w, w / n, min(per_round), max(per_round))
            if arguments.same_width:
                n = statistics.median(sample[1] for sample in narrow[index])
                w = statistics.median(sample[1] for sample in web[index])
                ratios[2].append(w / n)
                row += "| %.3f ms | %.2f× " % (n, w / n)
            print(row + "|")
        for clock, name in ((0, "wall time"), (1, "CPU time")):
            print("\npage / native (%s): %.2f× to %.2f× (median %.2f×) over %d scenes"
                  % (name, min(ratios[clock]), max(ratios[clock]), statistics.median(ratios[clock]),
                     len(ratios[clock])))
        if arguments.same_width:
            print("\npage / native at two doubles a vector (CPU time): %.2f× to %.2f× (median %.2f×) over %d scenes"
                  % (min(ratios[2]), max(ratios[2]), statistics.median(ratios[2]), len(ratios[2])))
        time.sleep(3)  # the page settles, then sleeps
        browser = page.driver.service.process.pid
        before = cpu_seconds(browser)
        time.sleep(10)
        idle = cpu_seconds(browser) - before
        print("\nidle page: %.2f s of CPU in 10 s (%.1f %% of a core), every browser process counted"
              % (idle, 10.0 * idle))
    finally:
        page.close()
