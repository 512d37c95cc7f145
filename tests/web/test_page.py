"""Browser tests of the web page (build-web/, scripts/web.sh) in headless Chromium: the page starts with a
clean console; its ids equal `raycam-cli render --ids` for every scene of scenes/ and stress cases; Tab
switches 2D/3D; a picked scene file opens; ?lang=fr gives French; bad files give the desktop's errors and
keep the scene. Usage: test_page.py WEB_FOLDER RAYCAM_CLI SCENES_FOLDER. Exit code 0 when all pass."""
import glob
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_driver import Page  # noqa: E402

from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402

web_folder, cli, scenes_folder = sys.argv[1:4]
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def errors_in(console):
    return [entry["message"] for entry in console if entry["level"] == "SEVERE"]


def wait_for(page, script, expected, seconds=10):
    value = None
    deadline = time.time() + seconds
    while time.time() < deadline:
        value = page.call(script)
        if value == expected or (callable(expected) and expected(value)):
            return value
        time.sleep(0.1)
    return value


def stress_scenes(folder):
    """Cases the demo scenes do not reach: many overlapping objects, the camera inside a sphere, a grazing
    view, tiny and huge radii. Written here; the native CLI and the page read the same files."""
    cases = {}
    spheres = [{"type": "sphere", "center": [0.37 * (i % 7) - 1.1, 0.29 * (i % 5) - 0.6, 0.23 * (i % 3)],
                "radius": 0.05 + 0.01 * (i % 9), "color": [i % 255, 50, 200]} for i in range(300)]
    cases["stress_many3d.json"] = {"dimension": 3, "objects": spheres,
                                   "camera": {"d": 5.0, "theta": 17.0, "phi": 71.0, "df": 1.7, "size": [97, 61]}}
    cases["stress_inside3d.json"] = {"dimension": 3, "objects": [
        {"type": "sphere", "center": [0, 0, 0], "radius": 20.0, "color": [9, 9, 9]},
        {"type": "sphere", "center": [0.5, 0, 0], "radius": 1e-3, "color": [200, 0, 0]}],
                                     "camera": {"d": 3.0, "theta": 0.0, "phi": 90.0, "df": 0.5, "size": [64, 64]}}
    circles = [{"type": "circle", "center": [0.11 * i - 2.0, 0.07 * (i % 11) - 0.3],
                "radius": 0.02 + 0.003 * (i % 13), "color": [40, i % 255, 90]} for i in range(40)]
    cases["stress_many2d.json"] = {"dimension": 2, "objects": circles,
                                   "camera": {"d": 4.0, "theta": 89.9, "df": 1.0, "size": 501}}
    paths = []
    for name, scene in cases.items():
        path = os.path.join(folder, name)
        with open(path, "w") as out:
            json.dump(scene, out)
        paths.append(path)
    return paths


def native_ids(scene, folder):
    out = os.path.join(folder, "native_ids.txt")
    run = subprocess.run([cli, "render", "--scene", scene, "--ids", out], capture_output=True, text=True)
    if run.returncode != 0:
        return "error: " + run.stderr.strip()
    with open(out) as text:
        return text.read()


def page_ids(page, scene):
    with open(scene) as text:
        content = text.read()
    return page.call("""
        const [name, content] = arguments;
        FS.mkdirTree('/test'); FS.writeFile('/test/' + name, content);
        if (Module.ccall('raycam_render_ids', 'number', ['string', 'string'], ['/test/' + name, '/test/ids.txt']))
          return 'error: ' + Module.ccall('raycam_last_error', 'string', [], []);
        return FS.readFile('/test/ids.txt', {encoding: 'utf8'});""", os.path.basename(scene), content)


def open_in_page(page, name, content):
    """The file picker's route: the file written into the page, then opened by the app."""
    page.call("""const [name, content] = arguments; FS.mkdirTree('/picked');
                 FS.writeFile('/picked/' + name, content);
                 Module.ccall('raycam_open_file', null, ['string'], ['/picked/' + name]);""", name, content)


with tempfile.TemporaryDirectory() as scratch:
    downloads = os.path.join(scratch, "downloads")
    os.mkdir(downloads)
    page = Page(web_folder, downloads=downloads)
    try:
        page.open()
        time.sleep(1.0)
        check(errors_in(page.console()) == [], "the page loads with no error in the console")
        title = wait_for(page, "return document.title", lambda t: "3D" in t)
        check("3D" in title and "demo scene" in title, "the page opens on the 3D demo scene (title %r)" % title)

        frames = "return Module.ccall('raycam_frames_drawn', 'number', [], [])"
        time.sleep(1.0)
        idle_start = page.call(frames)
        time.sleep(1.5)
        idle_end = page.call(frames)
        check(idle_start > 0 and idle_end == idle_start,
              "the idle page draws nothing (%s frames, then %s 1.5 s later)" % (idle_start, idle_end))
        ActionChains(page.driver).move_to_element_with_offset(
            page.driver.find_element("id", "canvas"), 10, 10).perform()
        woken = wait_for(page, frames, lambda n: n > idle_end, 5)
        check(woken > idle_end, "a mouse move wakes it (%s frames)" % woken)

        scenes = sorted(glob.glob(os.path.join(scenes_folder, "*.json"))) + stress_scenes(scratch)
        for scene in scenes:
            native = native_ids(scene, scratch)
            in_page = page_ids(page, scene)
            if native != in_page:
                print("  native: %s\n  page: %s" % (native[:200], in_page[:200]))
            check(not native.startswith("error") and native == in_page,
                  "ids in the page equal raycam-cli render --ids: %s (%d lines)" % (os.path.basename(scene),
                                                                                    native.count("\n")))

        def press_tab():  # held 0.2 s, as a hand does: ImGui 1.86 misses a press released within its frame
            ActionChains(page.driver).key_down(Keys.TAB).pause(0.2).key_up(Keys.TAB).perform()

        page.driver.find_element("id", "canvas").click()
        press_tab()
        title = wait_for(page, "return document.title", lambda t: "2D" in t)
        check("2D" in title, "Tab switches to 2D (title %r)" % title)
        press_tab()
        title = wait_for(page, "return document.title", lambda t: "3D" in t)
        check("3D" in title, "Tab switches back to 3D (title %r)" % title)

        ActionChains(page.driver).key_down(Keys.F12).pause(0.2).key_up(Keys.F12).perform()
        shot = os.path.join(downloads, "raycam-screenshot-001.png")
        deadline = time.time() + 10
        while time.time() < deadline and not os.path.exists(shot):
            time.sleep(0.1)
        with open(shot, "rb") if os.path.exists(shot) else open(os.devnull, "rb") as png:
            header = png.read(24)
        size = (int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")) if header else None
        canvas_size = tuple(page.call("return [Module.canvas.width, Module.canvas.height]"))
        check(header[:8] == b"\x89PNG\r\n\x1a\n" and size == canvas_size,
              "F12: the screenshot is a download, a PNG of the canvas's size (%s, canvas %s)" % (size, canvas_size))

        with open(os.path.join(scenes_folder, "symmetric3d.json")) as text:
            open_in_page(page, "picked3d.json", text.read())
        title = wait_for(page, "return document.title", lambda t: "picked3d.json" in t)
        check("picked3d.json" in title, "a picked scene file opens (title %r)" % title)

        status = "return Module.ccall('raycam_status_message', 'string', [], [])"
        open_in_page(page, "notes.json", "this is not a scene")
        message = wait_for(page, status, lambda m: "notes.json" in m)
        check("notes.json" in message and "picked3d.json" in page.call("return document.title"),
              "a file that is not a scene: an error naming it, the scene kept (%r)" % message)
        page.call("""FS.writeFile('/picked/big.json', new Uint8Array(50 * 1024 * 1024).fill(32));
                     Module.ccall('raycam_open_file', null, ['string'], ['/picked/big.json']);""")
        message = wait_for(page, status, lambda m: "big.json" in m)
        check("big.json" in message and "picked3d.json" in page.call("return document.title"),
              "a 50 MB file: an error naming it, the scene kept (%r)" % message)
        over = {"dimension": 3, "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "color": [1, 2, 3]}],
                "camera": {"size": [100000, 100000]}}
        open_in_page(page, "over.json", json.dumps(over))
        message = wait_for(page, status, lambda m: "over.json" in m)
        check("over.json" in message and "picked3d.json" in page.call("return document.title"),
              "a scene over the limits: an error naming it, the scene kept (%r)" % message)
        check("camera.size" in message, "  ... and naming the field over its limit")
        check(errors_in(page.console()) == [], "no error in the console after all that")
    finally:
        page.close()

    french = Page(web_folder)
    try:
        french.open("?lang=fr")
        title = wait_for(french, "return document.title", lambda t: "raycam" in t)
        check("démonstration" in title, "?lang=fr: French texts (title %r)" % title)
    finally:
        french.close()

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
