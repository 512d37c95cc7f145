#!/usr/bin/python3
"""Speed of the web page against the native program, same machine, same run (docs/web.md; a benchmark,
not a test): the median cast of scenes/many3d.json at 256² and of 10⁵ random spheres, in headless Chromium
(the page's one thread) and in `raycam-cli bench speed --threads 1`; then the idle page's CPU time over 10 s.
Usage: scripts/bench_web.py [WEB_FOLDER] [RAYCAM_CLI]   (defaults: build-web, build/raycam-cli)"""
import json
import os
import random
import re
import subprocess
import sys
import tempfile
import time

root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(root, "tests", "web"))
from page_driver import Page  # noqa: E402

web_folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "build-web")
cli = sys.argv[2] if len(sys.argv) > 2 else os.path.join(root, "build", "raycam-cli")


def many_spheres(path, count):
    """count spheres uniform in [-10,10]^3 with radius 2*count^(-1/3), as `bench speed` draws them."""
    rng = random.Random(1)
    radius = 2.0 * count ** (-1.0 / 3.0)
    objects = [{"type": "sphere", "center": [rng.uniform(-10, 10) for _ in range(3)], "radius": radius,
                "color": [200, 100, 50]} for _ in range(count)]
    with open(path, "w") as out:
        json.dump({"dimension": 3, "objects": objects,
                   "camera": {"d": 30, "theta": 30, "phi": 60, "df": 2, "size": [256, 256]}}, out)


def native_ms(scene):
    run = subprocess.run([cli, "bench", "speed", "--scene", scene, "--size", "256", "--threads", "1",
                          "--repeats", "5"], capture_output=True, text=True, check=True)
    return float(re.search(r"automatic ([0-9.]+) ms median", run.stdout).group(1))


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


with tempfile.TemporaryDirectory() as scratch:
    scenes = [("scenes/many3d.json at 256²", os.path.join(root, "scenes", "many3d.json"))]
    big = os.path.join(scratch, "spheres100000.json")
    many_spheres(big, 100000)
    scenes.append(("10⁵ spheres at 256²", big))
    page = Page(web_folder)
    try:
        page.open()
        print("| scene | native, 1 thread | page (Chromium, WebAssembly) | page / native |")
        print("|---|---|---|---|")
        for label, path in scenes:
            with open(path) as text:
                content = text.read()
            page_time = page.call("""const [content] = arguments; FS.writeFile('/bench.json', content);
                return Module.ccall('raycam_time_cast', 'number', ['string', 'number', 'number'],
                                                    ['/bench.json', 256, 21]);""",
                                  content)
            native = native_ms(path)
            print("| %s | %.2f ms | %.2f ms | %.2f× |" % (label, native, page_time, page_time / native))
        time.sleep(3)  # the page settles, then sleeps
        browser = page.driver.service.process.pid
        before = cpu_seconds(browser)
        time.sleep(10)
        idle = cpu_seconds(browser) - before
        print("\nidle page: %.2f s of CPU in 10 s (%.1f %% of a core), every browser process counted"
              % (idle, 10.0 * idle))
    finally:
        page.close()
