"""The web page in headless Chromium, for the browser tests and the speed script: serves a built web folder
(build-web/) on a free local port, or opens one of its files from a file:// URL, with Selenium (Debian's
chromium + chromium-driver).
WebGL 2 runs on SwiftShader, Chromium's CPU renderer, so no GPU is needed."""
import functools
import http.server
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
