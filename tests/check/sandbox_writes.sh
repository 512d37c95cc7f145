#!/bin/sh
# The sandbox shows a student's own folder, and the folders of the files its command names, read-only: even
# where the run's uid could write them (world-writable folders, as an unzipped submission may be), the
# program writes only in its own temporary folder. Without the sandbox the same writes land, so the checks
# can fail. Usage: sandbox_writes.sh RAYCAM_CLI MISBEHAVING_PY. Exit 0 when the writes are stopped, 1 when one
# lands, 77 (the CTest entry's SKIP_RETURN_CODE) when no sandbox can start here or no folder can be set up.
set -u
cli=$1 student=$2
skip() {
  echo "skipped: $*"
  exit 77
}
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}

# Under /var/tmp: the sandbox's own empty /tmp would hide a folder under /tmp whatever it shows.
base=$(mktemp -d /var/tmp/raycam-sandbox-writes-XXXXXX 2> /dev/null) || skip "cannot make a folder under /var/tmp"
trap 'rm -rf "$base"' EXIT
chmod 755 "$base"
mkdir "$base/alice" "$base/data" "$base/out" || skip "cannot make folders in $base"
cp "$student" "$base/alice/camera.py"
echo "class data" > "$base/data/input.txt"
chmod 777 "$base/alice" "$base/data"  # anyone may write here: the run's own uid too
chmod 644 "$base/alice/camera.py"
chmod 666 "$base/data/input.txt"

# The paths the student tries: beside its program, in a folder its command names, over a file it was given,
# and its own working folder (the one place it may write: the control that the mode writes at all).
targets="$base/alice/beside.txt $base/data/beside.txt $base/data/input.txt $base/alice/camera.py"
# shellcheck disable=SC2086  # the targets are words
"$cli" check --student "python3 $base/alice/camera.py write $targets own.txt" --cases 1 --mode 2d \
  --require-sandbox --report "$base/out/report.json" > "$base/out/output.txt" 2>&1
status=$?
if [ $status -eq 2 ] && grep -q -- "--require-sandbox" "$base/out/output.txt"; then
  skip "no sandbox can start here: $(head -n 1 "$base/out/output.txt")"
fi
[ -f "$base/out/report.json" ] || { cat "$base/out/output.txt"; echo "FAIL no report (exit $status)"; exit 1; }
grep -q '"sandbox": *true' "$base/out/report.json" || fail "the report does not say the run was sandboxed"
grep -q 'wrote own.txt' "$base/out/report.json" || fail "the student could not write in its own folder"
for target in $targets; do
  grep -q "stopped $target" "$base/out/report.json" || fail "the student was not stopped writing $target"
done
[ -e "$base/alice/beside.txt" ] && fail "a file appeared beside the student's program"
[ -e "$base/data/beside.txt" ] && fail "a file appeared in the folder its command names"
[ "$(cat "$base/data/input.txt")" = "class data" ] || fail "the file it was given was changed"
cmp -s "$student" "$base/alice/camera.py" || fail "the student's program was changed"

# Without the sandbox the same program writes there: the checks above can fail.
"$cli" check --student "python3 $base/alice/camera.py write $base/alice/beside.txt" --cases 1 --mode 2d \
  --no-sandbox --report "$base/out/open.json" > "$base/out/open.txt" 2>&1
[ -e "$base/alice/beside.txt" ] || fail "without the sandbox the write did not land either: the test proves nothing"

if [ $failures -gt 0 ]; then
  echo "report: $(cat "$base/out/report.json")"
  exit 1
fi
echo "ok: every write outside the run's own folder was stopped"
