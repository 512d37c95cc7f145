"""The web page in headless Chromium, for the browser tests and the speed script: serves a built web folder
(build-web/) on a free local port, or opens one of its files from a file:// URL, with Selenium (Debian's
chromium + chromium-driver).
WebGL 2 runs on SwiftShader, Chromium's CPU renderer, so no GPU is needed."""
import functools
import http.server
import os
import pathlib
import threading
import time

from selenium import webdriver
from selenium.webdriver.chrome.service import Service


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args):
        pass


class Page:
    def __init__(self, folder, width=1280, height=800, downloads=None, flags=(), file_name=None):
        """file_name: open folder/file_name from its file:// URL, with no server (the single-file page)."""
        self.server = None
        if file_name:
            self.url = pathlib.Path(folder, file_name).resolve().as_uri()
        else:
            handler = functools.partial(QuietHandler, directory=folder)
            self.server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
            threading.Thread(target=self.server.serve_forever, daemon=True).start()
            self.url = "http://127.0.0.1:%d/index.html" % self.server.server_address[1]
        options = webdriver.ChromeOptions()
        for flag in ("--headless=new", "--no-sandbox", "--use-gl=angle", "--use-angle=swiftshader",
                     "--enable-unsafe-swiftshader", "--ignore-gpu-blocklist", "--disable-dev-shm-usage",
                     "--window-size=%d,%d" % (width, height)) + tuple(flags):
            options.add_argument(flag)
        options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
        if downloads:
            options.add_experimental_option("prefs", {"download.default_directory": downloads,
                                                      "download.prompt_for_download": False})
        self.driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=options)
        if downloads:  # headless Chromium saves downloads only when told where
            self.driver.execute_cdp_cmd("Page.setDownloadBehavior", {"behavior": "allow", "downloadPath": downloads})

    def open(self, query=""):
        self.driver.get(self.url + query)
        deadline = time.time() + 60
        while time.time() < deadline:
            if self.driver.execute_script("return typeof Module !== 'undefined' && !!Module.calledRun"):
                return
            time.sleep(0.1)
        raise RuntimeError("the page did not start within 60 s: %s" % self.console())

    def console(self):
        return self.driver.get_log("browser")

    def call(self, script, *args):
        return self.driver.execute_script(script, *args)

    def close(self):
        self.driver.quit()
        if self.server:
            self.server.shutdown()


# A scene of `count` spheres made in the page (a file too big to hand over through the driver), opened by the
# picker's route (Module.raycamReadFile) while the page records what each frame drawn showed in the status
# line (after each turn of the app's loop that drew one) and how long the page went between animation frames.
# Returns that record once a frame shows the scene opened, "(N objects)" (or after `seconds`):
# {size, total_ms, shown: [[ms, text]], gaps: [[ms, gap_ms]]}.
BIG_SCENE_SCRIPT = """
const [count, seconds, done] = arguments;
let seed = 1;
const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
const radius = 2 * Math.pow(count, -1 / 3);
const parts = ['{"dimension": 3, "background": [20, 20, 30], "camera": {"d": 35, "theta": 30, "phi": 60, ',
               '"df": 2, "size": [256, 256]}, "objects": ['];
for (let i = 0; i < count; ++i) {
  const c = [0, 1, 2].map(() => (20 * random() - 10).toFixed(4));
  parts.push((i ? ',' : '') + '\\n{"type": "sphere", "center": [' + c.join(', ') + '], "radius": ' +
             radius.toFixed(5) + ', "color": [' + (i % 256) + ', 120, 200]}');
}
parts.push(']}');
const file = new File(parts, 'big' + count + '.json');
const record = {size: file.size, shown: [], gaps: []};
const status = () => Module.ccall('raycam_status_message', 'string', [], []);
const frames = () => Module.ccall('raycam_frames_drawn', 'number', [], []);
const start = performance.now();
let last = start, drawn = frames(), finished = false;
const initial = status();
const finish = () => {
  const now = performance.now();
  record.gaps.push([now - start, now - last]);  // the wait before this frame: watch may not have run yet
  finished = true;
  Module.postMainLoop = undefined;
  record.total_ms = performance.now() - start;
  done(record);
};
Module.postMainLoop = () => {
  if (finished || frames() === drawn) return;
  drawn = frames();
  const text = status();
  if (!record.shown.length || record.shown[record.shown.length - 1][1] !== text)
    record.shown.push([performance.now() - start, text]);
  if (text !== initial && /\\(\\d+ obje(c)?ts\\) /.test(text)) finish();  // opened "(N objects)"
};
const watch = () => {
  if (finished) return;
  const now = performance.now();
  record.gaps.push([now - start, now - last]);
  last = now;
  if (now - start > seconds * 1000) finish();
  else requestAnimationFrame(watch);
};
FS.mkdirTree('/picked');
Module.raycamReadFile(file, '/picked/' + file.name);
requestAnimationFrame(watch);
"""


def open_big_scene(page, count, seconds=120):
    page.driver.set_script_timeout(seconds + 30)
    return page.driver.execute_async_script(BIG_SCENE_SCRIPT, count, seconds)


def browser_cpu_seconds(page, renderers_main_thread=False):
    """User + system CPU seconds of the browser's processes (chromedriver's descendants), from /proc; with
    `renderers_main_thread`, only the main thread of each renderer process (the page's WebAssembly runs on one
    of them; any other stays idle)."""
    ticks = os.sysconf("SC_CLK_TCK")
    total, stack = 0.0, [page.driver.service.process.pid]
    while stack:
        pid = stack.pop()
        try:
            counted = True
            if renderers_main_thread:
                with open("/proc/%d/cmdline" % pid, "rb") as text:
                    counted = b"--type=renderer" in text.read()
            if counted:
                stat = "/proc/%d/task/%d/stat" % (pid, pid) if renderers_main_thread else "/proc/%d/stat" % pid
                with open(stat) as text:
                    fields = text.read().rsplit(")", 1)[1].split()
                total += (int(fields[11]) + int(fields[12])) / ticks
            for task in os.listdir("/proc/%d/task" % pid):
                with open("/proc/%d/task/%s/children" % (pid, task)) as text:
                    stack += [int(child) for child in text.read().split()]
        except OSError:
            pass
    return total
