"""Browser tests of the page's verdicts, files and figures (build-web/, headless Chromium), issue 34:
- Check my camera says what it grades: no answer yet; graded for the camera shown; an earlier camera's once
  the camera or the scene changed (never re-graded into a red fail by a move, Tab or another scene); an
  answer given after a move is graded for the case it answers; a clear button empties it.
- Files as a student knows them: the panel's Open is the browser's file picker, a file dropped on the canvas
  opens, Save as and the exports are downloads named after the scene, a second download of the same name
  asks nothing, and no message shows the page's own folders.
- Figures: Export figure offers TikZ (no format choice: SVG, PDF and PNG need cairo) and downloads the .tex
  that raycam-cli figure writes for the same camera; in French, French.
Usage: test_page_files.py WEB_FOLDER RAYCAM_CLI SCENES_FOLDER. Exit code 0 when all pass (77: no built page)."""
import json
import os
import subprocess
import sys
import tempfile
import time

PAGE_FILES = ("index.html", "index.js", "index.wasm", "index.data")
if len(sys.argv) == 4:
    missing = [name for name in PAGE_FILES if not os.path.isfile(os.path.join(sys.argv[1], name))]
    if missing:
        print("skipped: %s has no built page (%s missing): run ./scripts/web.sh --build-only first"
              % (sys.argv[1], ", ".join(missing)), flush=True)
        sys.exit(77)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from page_checks import check, failures, wait_for, wait_for_file  # noqa: E402
from page_driver import Page  # noqa: E402

from selenium.webdriver.common.action_chains import ActionChains  # noqa: E402
from selenium.webdriver.common.keys import Keys  # noqa: E402

web_folder, cli, scenes_folder = sys.argv[1:4]
# The page's own folders: its working folder, the picker's, the bundled scenes', the answers', GLFW's drops.
INTERNAL = ("/home/web_user", "/picked", "/dropped", "/scenes/", "/answers", ".glfw_dropped_files")
messages_seen = []


def shown_frame(page):
    return json.loads(page.call("return Module.ccall('raycam_shown_frame', 'string', [], [])"))


def status(page):
    message = page.call("return Module.ccall('raycam_status_message', 'string', [], [])")
    messages_seen.append(message)
    return message


# Every message a drawn frame showed, recorded by the page itself: a confirmation goes after 5 s, which a
# loaded machine can let pass between two polls.
RECORD_MESSAGES = """window.raycam_messages = []; const before = Module.postMainLoop;
Module.postMainLoop = function() {
  if (before) before();
  const m = Module.ccall('raycam_status_message', 'string', [], []);
  const seen = window.raycam_messages;
  if (m && seen[seen.length - 1] !== m) seen.push(m);
};"""


def wait_for_status(page, wanted):
    """The first message shown since the last call that `wanted` accepts (else the status line's now)."""
    deadline = time.time() + 10
    while time.time() < deadline:
        recorded = page.call("const seen = window.raycam_messages || []; window.raycam_messages = []; return seen;")
        for message in recorded:
            messages_seen.append(message)
            if wanted(message):
                return message
        message = status(page)
        if wanted(message):
            return message
        time.sleep(0.1)
    return message


FRAMES = "return Module.ccall('raycam_frames_drawn', 'number', [], [])"


def frames_after(page, drawn, count=2):
    """Waits until `count` frames are drawn after the `drawn`-th (read before the event that wakes the page)."""
    wait_for(page, FRAMES, lambda n: n >= drawn + count)


def click_widget(page, widget_id):
    """A click in the middle of a widget the panel recorded (its rectangle in the last frame)."""
    widgets = wait_for(page, "return JSON.parse(Module.ccall('raycam_shown_frame', 'string', [], [])).widgets",
                       lambda w: w and widget_id in w)
    if not widgets or widget_id not in widgets:
        return False
    x, y, w, h = widgets[widget_id]
    canvas = page.driver.find_element("id", "canvas")
    size = page.call("return [Module.canvas.width, Module.canvas.height]")
    drawn = page.call(FRAMES)
    ActionChains(page.driver).move_to_element_with_offset(canvas, x + w / 2 - size[0] / 2, y + h / 2 - size[1] / 2) \
        .pause(0.2).click_and_hold().pause(0.2).release().perform()
    frames_after(page, drawn, 4)  # the move, the press, the release
    return True


def press(page, key):  # held 0.2 s, as a hand does
    ActionChains(page.driver).key_down(key).pause(0.2).key_up(key).perform()


def native_case_ids(case_path, folder):
    out = os.path.join(folder, "case_ids.txt")
    run = subprocess.run([cli, "render", "--scene", case_path, "--ids", out], capture_output=True, text=True)
    if run.returncode != 0:
        return []
    with open(out) as text:
        return [[int(v) for v in line.split()] for line in text if line.strip()]


def give_answer(page, name, rows):
    drawn = page.call(FRAMES)
    page.call("""const [name, content] = arguments; FS.mkdirTree('/answers');
                 FS.writeFile('/answers/' + name, content);
                 Module.ccall('raycam_check_answer', null, ['string'], ['/answers/' + name]);""",
              name, json.dumps({"ids": rows}))
    frames_after(page, drawn)
    return shown_frame(page)


def verdict_states(page, downloads, scratch):
    """Item 2: what the verdict grades, in every state the page has."""
    frame = shown_frame(page)
    check(frame["check_state"] == "no-answer" and frame["check_status"] == "",
          "Check my camera: no answer yet (%s)" % frame["check_state"])
    page.call("Module.ccall('raycam_download_case', null, [], [])")
    case_path = os.path.join(downloads, "raycam-case.json")
    check(wait_for_file(case_path), "  ... the camera's case is a download")
    rows = native_case_ids(case_path, scratch) if os.path.exists(case_path) else []
    check(len(rows) > 0, "  ... which raycam-cli renders (%d rows)" % len(rows))
    if not rows:
        return
    frame = give_answer(page, "right.json", rows)
    check(frame["check_status"] == "pass" and frame["check_state"] == "camera-shown",
          "  ... the right answer: pass, graded for the camera shown (%s, %s)"
          % (frame["check_status"], frame["check_state"]))
    wrong = [list(row) for row in rows]
    wrong[len(wrong) // 2][len(wrong[0]) // 2] = 4 if wrong[len(wrong) // 2][len(wrong[0]) // 2] != 4 else 3
    frame = give_answer(page, "one_wrong.json", wrong)
    check(frame["check_status"] == "fail" and frame["check_wrong_pixels"] == 1 and
          frame["check_state"] == "camera-shown" and "CHECK" in frame["check_header"],
          "  ... one pixel wrong: a fail for the camera shown, named in the image's header (%s, %s, %r)"
          % (frame["check_status"], frame["check_wrong_pixels"], frame["check_header"]))
    # One arrow key: the verdict is now an earlier camera's, kept as it was (not re-graded into 890 pixels
    # wrong), with no header over the new image.
    page.driver.find_element("id", "canvas").click()
    theta = frame["theta"]
    press(page, Keys.ARROW_RIGHT)
    wait_for(page, "return JSON.parse(Module.ccall('raycam_shown_frame', 'string', [], [])).theta",
             lambda t: t != theta)
    time.sleep(1.0)  # well past the desktop's quiet time before a re-check
    frame = shown_frame(page)
    check(frame["check_state"] == "earlier-camera" and frame["check_status"] == "fail" and
          frame["check_wrong_pixels"] == 1 and frame["check_header"] == "",
          "  ... after an arrow key: the verdict is an earlier camera's, not re-graded, no header (%s, %s, %s, %r)"
          % (frame["check_state"], frame["check_status"], frame["check_wrong_pixels"], frame["check_header"]))
    # The right answer for the downloaded case, given after the move: graded for that case (a pass), shown as
    # an earlier camera's, never a red fail for the camera on screen.
    frame = give_answer(page, "right_after_move.json", rows)
    check(frame["check_status"] == "pass" and frame["check_state"] == "earlier-camera",
          "  ... an answer for the downloaded case given after the move: graded for that case (%s, %s)"
          % (frame["check_status"], frame["check_state"]))
    press(page, Keys.ARROW_LEFT)  # back to the case's camera: the verdict is this image's again
    state = wait_for(page, "return JSON.parse(Module.ccall('raycam_shown_frame', 'string', [], [])).check_state",
                     lambda s: s == "camera-shown")
    check(state == "camera-shown", "  ... back at the case's camera: graded for the camera shown again (%s)" % state)
    press(page, Keys.TAB)  # the other dimension: a bad-output before, when an answer was graded on any camera
    wait_for(page, "return document.title", lambda t: "2D" in t)
    time.sleep(1.0)
    frame = shown_frame(page)
    check(frame["check_state"] == "earlier-camera" and frame["check_status"] == "pass",
          "  ... after Tab: still that case's verdict, an earlier camera's (%s, %s)"
          % (frame["check_state"], frame["check_status"]))
    press(page, Keys.TAB)
    wait_for(page, "return document.title", lambda t: "3D" in t)
    # Issue 45: Tab back to the case's camera brings its verdict back, as the arrow keys do.
    state = wait_for(page, "return JSON.parse(Module.ccall('raycam_shown_frame', 'string', [], [])).check_state",
                     lambda s: s == "camera-shown")
    check(state == "camera-shown", "  ... Tab back to the case's camera: graded for the camera shown again (%s)" % state)
    drawn = page.call(FRAMES)
    page.call("Module.ccall('raycam_clear_check', null, [], [])")
    frames_after(page, drawn)
    frame = shown_frame(page)
    check(frame["check_state"] == "no-answer" and frame["check_status"] == "",
          "  ... the clear button: no answer again (%s)" % frame["check_state"])


def files_and_figures(page, downloads, scratch, language):
    """Items 4 and 5 through the panel's own buttons, on the bundled many3d.json."""
    page.call(RECORD_MESSAGES)
    check(click_widget(page, "###files"), "%s: the Scene file section opens" % language)
    # A click's release reaches ImGui a frame after its press (the host's event queue): wait for the open section.
    widgets = wait_for(page, "return JSON.parse(Module.ccall('raycam_shown_frame', 'string', [], [])).widgets",
                       lambda w: w and "###files_open" in w)
    check("###files_open" in widgets and "###open_path" not in widgets and "###save_path" not in widgets,
          "  ... Open is a button for the browser's file picker, with no path box (%s)"
          % sorted(k for k in widgets if "open" in k or "save" in k))
    page.call("""window.raycam_picker_clicks = 0;
                 document.getElementById('picker').addEventListener('click', (e) => {
                     window.raycam_picker_clicks += 1; e.preventDefault(); });""")
    click_widget(page, "###files_open")
    check(wait_for(page, "return window.raycam_picker_clicks", lambda n: n > 0) == 1,
          "  ... and a click on it opens the browser's file picker")

    # The downloads the page hands the browser (headless Chromium saves a second file of the same name over
    # the first, where a desktop browser keeps both as "many3d (1).json").
    page.call("""window.raycam_downloads = []; const click = HTMLAnchorElement.prototype.click;
                 HTMLAnchorElement.prototype.click = function() {
                     if (this.download) window.raycam_downloads.push(this.download);
                     return click.call(this); };""")
    for attempt in (1, 2):
        check(click_widget(page, "###save_download"), "  ... Save as (%d)" % attempt)
        message = wait_for_status(page, lambda m: "many3d" in m)
        # The download offered before the next click, and the clicks further apart than a double-click (0.3 s,
        # which ImGui would read as one double-click), as a student's two Save as are.
        wait_for(page, "return window.raycam_downloads", lambda d, n=attempt: len(d) >= n, 5)
        time.sleep(0.5)
    first = os.path.join(downloads, "many3d.json")
    offered = wait_for(page, "return window.raycam_downloads", lambda d: len(d) >= 2, 5)
    check(wait_for_file(first) and offered == ["many3d.json", "many3d.json"],
          "  ... Save as twice: two downloads named after the scene, no question asked (%s)" % offered)
    asked = "téléchargement de la caméra sous many3d.json" if language == "fr" else "asked the browser to save"
    check("many3d.json" in message and "?" not in message and message.startswith(asked),
          "  ... and the message names the download, as asked of the browser (%r)" % message)
    with open(first) if os.path.exists(first) else open(os.devnull) as text:
        saved = text.read()

    check(click_widget(page, "###export_png"), "  ... Export colour map PNG")
    png = os.path.join(downloads, "many3d-colour-map.png")
    check(wait_for_file(png) and open(png, "rb").read(8) == b"\x89PNG\r\n\x1a\n",
          "  ... a PNG download named after the scene (%s)" % sorted(os.listdir(downloads)))

    widgets = shown_frame(page)["widgets"]
    check("###figure_format" not in widgets and "###figure_path" not in widgets,
          "  ... Export figure: no format choice (TikZ only, without cairo) and no path box")
    # The PNG's message (two lines: "asked the browser to save …") goes at the next click, and the panel under
    # the pointer moves up between the press and the release: wait for it to go by itself first.
    wait_for_status(page, lambda m: m == "")
    check(click_widget(page, "###figure_export"), "  ... Export figure…")
    tex = os.path.join(downloads, "many3d-figure.tex")
    check(wait_for_file(tex), "  ... a TikZ download named after the scene (%s)" % sorted(os.listdir(downloads)))
    message = wait_for_status(page, lambda m: "many3d-figure.tex" in m)
    check("many3d-figure.tex" in message and not [p for p in INTERNAL if p in message],
          "  ... and the message names it alone (%r)" % message)
    # The same figure from raycam-cli, for the camera the page saved: the drawing is the same, line for line;
    # a label may sit elsewhere where cairo's hinting rounds a glyph's width the other way (1 % of words).
    preset = os.path.join(scratch, "preset-%s.json" % language)
    with open(preset, "w") as out:
        out.write(saved)
    native = os.path.join(scratch, "native-%s.tex" % language)
    run = subprocess.run([cli, "figure", "--scene", preset, "--format", "tikz", "--frames", "5", "--lang", language,
                          "--out", native], capture_output=True, text=True)
    ours = open(tex).read().splitlines() if os.path.exists(tex) else []
    theirs = open(native).read().splitlines() if run.returncode == 0 else ["error: " + run.stderr]
    drawing = [line for line in theirs if not line.startswith("\\node")]
    ours_drawing = [line for line in ours if not line.startswith("\\node")]
    same = sum(1 for a, b in zip(ours, theirs) if a == b)
    check(len(ours) == len(theirs) and ours_drawing == drawing and same >= 0.9 * len(theirs),
          "  ... the TikZ raycam-cli figure writes for that camera: every drawing line, %d of %d lines in all"
          % (same, len(theirs)))
    word = "étape" if language == "fr" else "step"
    check(any(word in line for line in ours), "  ... in the page's language (%r)" % word)
    every_step(page, downloads, language, len(ours))
    return message


def every_step(page, downloads, language, figure_lines):
    """Issue 45 item 1: every step's figure is ONE download, a zip archive that unzip tests and gives back, and
    the message says what the browser was asked to save (the page cannot know what arrived)."""
    offered = len(page.call("return window.raycam_downloads"))
    check(click_widget(page, "###figure_export_all"), "  ... Export every step")
    archive = os.path.join(downloads, "many3d-steps.zip")
    check(wait_for_file(archive), "  ... one download, a zip archive (%s)" % sorted(os.listdir(downloads)))
    time.sleep(0.5)  # anything else the page would offer
    new = page.call("return window.raycam_downloads")[offered:]
    check(new == ["many3d-steps.zip"], "  ... and nothing else offered (%s)" % new)
    names = []
    if os.path.exists(archive):
        test = subprocess.run(["unzip", "-t", archive], capture_output=True, text=True)
        check(test.returncode == 0 and "No errors detected" in test.stdout,
              "  ... which unzip -t passes (%s)" % test.stdout.strip().splitlines()[-1:])
        listing = subprocess.run(["unzip", "-Z1", archive], capture_output=True, text=True).stdout.split()
        names = sorted(listing)
        out = os.path.join(downloads, "steps-" + language)
        subprocess.run(["unzip", "-q", "-o", archive, "-d", out])
        tex = [open(os.path.join(out, n)).read() for n in names if n.endswith(".tex")]
        check(len(names) >= 2 and len(tex) == len(names) and all("tikzpicture" in t for t in tex),
              "  ... holding every step's TikZ figure (%s)" % names)
    message = wait_for_status(page, lambda m: "many3d-steps.zip" in m)
    asked = ("téléchargement de many3d-steps.zip demandé au navigateur (%d figures)" if language == "fr"
             else "asked the browser to save many3d-steps.zip (%d figures)") % len(names)
    check(message == asked and "écrit" not in message and "wrote" not in message,
          "  ... and the message says what the browser was asked to save (%r)" % message)


with tempfile.TemporaryDirectory() as scratch:
    downloads = os.path.join(scratch, "downloads")
    os.mkdir(downloads)
    page = Page(web_folder, width=1400, height=1800, downloads=downloads)  # tall: every button in sight
    try:
        page.open("?scene=many3d.json")
        wait_for(page, "return document.title", lambda t: "many3d.json" in t)
        verdict_states(page, downloads, scratch)
        files_and_figures(page, downloads, scratch, "en")

        # A picked file through the page's own <input type=file>, as the browser's picker fills it.
        picked = os.path.join(scratch, "symmetric3d.json")
        with open(os.path.join(scenes_folder, "symmetric3d.json")) as source, open(picked, "w") as out:
            out.write(source.read())
        page.call("document.getElementById('picker').hidden = false;")
        page.driver.find_element("id", "picker").send_keys(picked)
        # Opened in steps (reading, then packing): the last message says it opened, naming the file alone.
        message = wait_for_status(page, lambda m: "symmetric3d.json" in m and m.startswith("opened"))
        title = wait_for(page, "return document.title", lambda t: "symmetric3d.json" in t)
        check(message.startswith("opened symmetric3d.json") and "/" not in message and "symmetric3d.json" in title,
              "a file from the browser's picker opens, named alone (%r)" % message)
        not_a_scene = os.path.join(scratch, "notes.json")
        with open(not_a_scene, "w") as out:
            out.write("this is not a scene")
        page.driver.find_element("id", "picker").send_keys(not_a_scene)
        message = wait_for_status(page, lambda m: "notes.json" in m)
        check("notes.json" in message, "  ... a file that is not a scene: its error names it (%r)" % message)
        # Dropped on the canvas, as a file manager's drag does (GLFW's drop listener reads it).
        with open(os.path.join(scenes_folder, "classic3d.json")) as source:
            content = source.read()
        page.call("""const [name, content] = arguments; const data = new DataTransfer();
                     data.items.add(new File([content], name, {type: 'application/json'}));
                     Module.canvas.dispatchEvent(new DragEvent('dragover', {dataTransfer: data, bubbles: true}));
                     Module.canvas.dispatchEvent(new DragEvent('drop', {dataTransfer: data, bubbles: true}));""",
                  "dropped3d.json", content)
        message = wait_for_status(page, lambda m: "dropped3d.json" in m)
        title = wait_for(page, "return document.title", lambda t: "dropped3d.json" in t)
        check("dropped3d.json" in title and "dropped3d.json" in message,
              "a file dropped on the canvas opens (%r)" % message)
        screenshot = os.path.join(downloads, "raycam-screenshot-001.png")
        press(page, Keys.F12)
        check(wait_for_file(screenshot), "F12: the screenshot is a download")
        wait_for_status(page, lambda m: "raycam-screenshot" in m)
        page.open("?scene=nope.json")
        message = wait_for_status(page, lambda m: "nope.json" in m)
        check("nope.json" in message, "?scene=nope.json: the error names the scene as asked (%r)" % message)
        leaked = sorted(set(m for m in messages_seen if [p for p in INTERNAL if p in m]))
        check(leaked == [], "no message names the page's own folders (%d messages read; %s)"
              % (len(set(messages_seen)), leaked))
    finally:
        page.close()

    french_downloads = os.path.join(scratch, "downloads-fr")
    os.mkdir(french_downloads)
    french = Page(web_folder, width=1400, height=1800, downloads=french_downloads)
    try:
        french.open("?lang=fr&scene=many3d.json")
        wait_for(french, "return document.title", lambda t: "many3d.json" in t)
        message = files_and_figures(french, french_downloads, scratch, "fr")
        check(message.startswith("téléchargement de many3d-figure.tex demandé"),
              "French: the export's message is French, what the browser was asked to save (%r)" % message)
    finally:
        french.close()

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
