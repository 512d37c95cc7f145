"""The single-file page (scripts/web.sh --single-file, docs/web.md) in headless Chromium, opened from a
file:// URL with no server, copied alone into an empty folder: it starts with a clean console and fetches
nothing; the font and the demo scenes are inside it; a bundled scene's ids equal `raycam-cli render --ids`
of the same file of scenes/; ?scene= opens a bundled scene. Usage: test_single_file.py WEB_FOLDER RAYCAM_CLI
SCENES_FOLDER. Exit code 0 when all pass, 77 when build-web/raycam.html is not built."""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_checks import check, errors_in, failures, skip_unless_built, wait_for  # noqa: E402

skip_unless_built(sys.argv[1] if len(sys.argv) == 4 else "", ("raycam.html",), "./scripts/web.sh --single-file")
from page_driver import Page  # noqa: E402

web_folder, cli, scenes_folder = sys.argv[1:4]
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"

with tempfile.TemporaryDirectory() as scratch:
    alone = os.path.join(scratch, "usb-stick")
    os.mkdir(alone)
    shutil.copy(os.path.join(web_folder, "raycam.html"), alone)
    page = Page(alone, file_name="raycam.html")
    try:
        page.open()
        check(page.call("return location.protocol") == "file:", "the page opens from a file:// URL (%s)" % page.url)
        title = wait_for(page, "return document.title", lambda t: "3D" in t)
        check("3D" in title and "demo scene" in title, "  ... and runs the app: the 3D demo scene (title %r)" % title)
        fetched = page.call("return performance.getEntriesByType('resource').map((entry) => entry.name)")
        check(fetched == [], "  ... fetching nothing beside itself (%s)" % fetched)
        bundled = sorted(name for name in os.listdir(scenes_folder) if name.endswith(".json"))
        inside = page.call("return FS.readdir('/scenes').filter((name) => name.endsWith('.json')).sort()")
        check(inside == bundled, "the demo scenes are inside it (%s)" % inside)
        size = page.call("const [path] = arguments; try { return FS.stat(path).size; } catch (e) { return -1; }", FONT)
        check(size == os.path.getsize(FONT), "the font is inside it (%d bytes, Debian's file %d)" % (size, os.path.getsize(FONT)))
        ids = os.path.join(scratch, "ids.txt")
        run = subprocess.run([cli, "render", "--scene", os.path.join(scenes_folder, "many3d.json"), "--ids", ids],
                             capture_output=True, text=True)
        native = open(ids).read() if run.returncode == 0 else "error: " + run.stderr
        in_page = page.call("""
            if (Module.ccall('raycam_render_ids', 'number', ['string', 'string'], ['/scenes/many3d.json', '/ids.txt']))
              return 'error: ' + Module.ccall('raycam_last_error', 'string', [], []);
            return FS.readFile('/ids.txt', {encoding: 'utf8'});""")
        check(not native.startswith("error") and in_page == native,
              "the bundled many3d.json's ids equal raycam-cli render --ids of scenes/many3d.json (%d lines)"
              % native.count("\n"))
        page.open("?scene=many3d.json")
        title = wait_for(page, "return document.title", lambda t: "many3d.json" in t)
        check("many3d.json" in title, "?scene=many3d.json in the file URL opens it (title %r)" % title)
        check(errors_in(page.console()) == [], "no error in the console")
    finally:
        page.close()

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
