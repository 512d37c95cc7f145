#!/bin/sh
# examples/gradescope/run_autograder on three submissions, with a folder standing for /autograder: the Python
# example (full score), the C++ example built by the script (full score), a C++ file that does not compile
# (score 0, the compiler's message shown), and camera.py where bubblewrap cannot start (graded again with
# --no-sandbox), each results.json read back with Python's json module.
#   gradescope_autograder.sh RAYCAM_CLI EXAMPLES_DIR RUN_AUTOGRADER
set -u
cli=$1 examples=$2 run_autograder=$3
fail() { echo "gradescope_autograder: FAIL: $*" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/raycam-gradescope.XXXXXX") || fail "no temporary folder"
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"

# grade NAME FILES...: a fresh /autograder with FILES as the submission; prints "score max_score tests".
grade() {
  name=$1
  shift
  root=$work/$name
  mkdir -p "$root/submission"
  cp "$@" "$root/submission/"
  chmod -R a+rX "$root"
  AUTOGRADER=$root RAYCAM_CLI=${grader:-$cli} RAYCAM_SCALE=10 bash "$run_autograder" > "$root/log" 2>&1 ||
    { cat "$root/log"; fail "$name: run_autograder exited $?"; }
  python3 -c 'import json, sys
r = json.load(open(sys.argv[1]))
print(r["score"], sum(t["max_score"] for t in r["tests"]), len(r["tests"]), r["output"].splitlines()[0])' \
    "$root/results/results.json" || fail "$name: no readable results.json"
}
python=$(grade python "$examples/camera.py")
case "$python" in "10.0 10.0 12 "*) ;; *) fail "camera.py: '$python', expected 10 of 10 over 12 tests" ;; esac
cpp=$(grade cpp "$examples/camera.cpp" "$examples/mini_json.h")
case "$cpp" in "10.0 10.0 12 "*) ;; *) fail "camera.cpp: '$cpp', expected 10 of 10 over 12 tests" ;; esac
printf 'int main() { return undeclared; }\n' > "$work/camera.cpp"
broken=$(grade broken "$work/camera.cpp")
case "$broken" in "0 0 0 camera.cpp does not compile"*) ;; *) fail "a broken camera.cpp: '$broken'" ;; esac
grep -q undeclared "$work/broken/results/results.json" || fail "the compiler's message is not shown to the student"
# A container where bubblewrap cannot start: a raycam-cli that refuses as check does then, unless --no-sandbox.
grader=$work/no_user_namespaces
printf '#!/bin/sh\ncase " $* " in *" --no-sandbox "*) exec "%s" "$@" ;; esac\n%s\nexit 2\n' "$cli" \
  'echo "raycam-cli check: error: the sandbox cannot start (no user namespaces)" >&2' > "$grader"
chmod +x "$grader"
contained=$(grade contained "$examples/camera.py")
case "$contained" in "10.0 10.0 12 "*) ;; *) fail "without a sandbox: '$contained', expected 10 of 10 (--no-sandbox)" ;; esac
grep -q "WITHOUT a sandbox" "$work/contained/log" || fail "the run without a sandbox does not say so"
echo "run_autograder grades camera.py and camera.cpp (10 of 10), reports a build failure, and grades where no sandbox starts"
