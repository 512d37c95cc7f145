"""What the browser tests of the page share: the verdict lines, waiting for a value, the console's errors and
the skip when the page is not built."""
import os
import sys
import time

# CTest's skip code (SKIP_RETURN_CODE 77 in tests/web/CMakeLists.txt): a native build alone has no page.
SKIPPED = 77
failures = []


def skip_unless_built(folder, files, how="./scripts/web.sh --build-only"):
    missing = [name for name in files if not os.path.isfile(os.path.join(folder, name))]
    if missing:
        print("skipped: %s has no built page (%s missing): run %s first" % (folder, ", ".join(missing), how),
              flush=True)
        sys.exit(SKIPPED)


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def errors_in(console):
    return [entry["message"] for entry in console if entry["level"] == "SEVERE"]


def wait_for(page, probe, expected, seconds=10):
    """Polls `probe` (a script returning a value, or a function) until it equals `expected` (or `expected`,
    a function, says yes); returns the last value."""
    value = None
    deadline = time.time() + seconds
    while time.time() < deadline:
        value = probe() if callable(probe) else page.call(probe)
        if value == expected or (callable(expected) and expected(value)):
            return value
        time.sleep(0.1)
    return value


def wait_for_file(path, seconds=10):
    """A download: True once `path` exists (and has had time to be written whole)."""
    deadline = time.time() + seconds
    while time.time() < deadline and not os.path.exists(path):
        time.sleep(0.1)
    time.sleep(0.3)  # written whole
    return os.path.exists(path)
