#!/bin/sh
# The "A large course" recipe of docs/check.md run here: a class of 15 students graded once by a single
# `check --batch` and once by GNU parallel in 3 shards, then `check merge`: the merged CSV (and its battery
# record) must equal the single run's byte for byte. Then the refusals: a missing shard, a shard given twice,
# a shard graded with another seed (exit 2, naming the students or the field), and a student added later
# moves nobody else.
#   shards_parallel.sh RAYCAM_CLI EXAMPLE_STUDENT MISTAKEN_STUDENT EXAMPLE_PY
set -u
cli=$1 example=$2 mistaken=$3 example_py=$4
fail() { echo "shards_parallel: FAIL: $*" >&2; exit 1; }
command -v parallel > /dev/null || fail "GNU parallel is not installed (Debian package 'parallel')"
# Sandboxed runs (as root: an unprivileged uid) must reach the students' folders: a world-readable folder.
work=$(mktemp -d "${TMPDIR:-/tmp}/raycam-shards.XXXXXX") || fail "no temporary folder"
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"
cd "$work" || fail "cannot enter $work"

# student NAME PROGRAM ARGS...: a folder holding its program and run.sh, readable by anyone (as an unzipped
# submission is).
student() {
  name=$1 program=$2
  shift 2
  mkdir -p "class/$name"
  cp "$program" "class/$name/"
  printf '#!/bin/sh\ncd "$(dirname "$0")"\nexec %s "$@"\n' "$*" > "class/$name/run.sh"
  chmod -R a+rX "class/$name"
  chmod a+x "class/$name/run.sh"
}
prog=./$(basename "$example") wrong=./$(basename "$mistaken")
for name in ada bea chloe dan eli; do student "$name" "$example" "$prog"; done
student fay "$example_py" python3 camera.py
student gus "$mistaken" "$wrong" --mistake mirrored
student hal "$mistaken" "$wrong" --mistake upside_down
student ivy "$mistaken" "$wrong" --mistake no_t_min
student jon "$mistaken" "$wrong" --mistake pixel_edges
student kim "$mistaken" "$wrong" --mistake mirrored,no_t_min
student leo "$mistaken" "$wrong" --mistake res_truncated
student "o,brien" "$mistaken" "$wrong" --mistake degrees_as_radians  # a comma: a quoted key in the CSV
student "mo \"q\"" "$example" "$prog"                                 # quotes: doubled inside the key
student zoe "$mistaken" "$wrong" --mistake theta_phi_swapped

battery="--cases 4 --seed 914273 --threads 1"
# shellcheck disable=SC2086 # $battery is words on purpose
"$cli" check --batch class --student-cmd "{dir}/run.sh" $battery --csv single.csv > single.log 2>&1
status=$?
[ "$status" -eq 1 ] || { cat single.log; fail "the single run exited $status (1 expected: some students fail)"; }
# Real grading, not a class of crashes: the example passes, a mistaken student is diagnosed.
grep -q '^ada,4,4,100.0,' single.csv || { cat single.csv; fail "ada (the example) does not pass"; }
grep -q '^gus,0,4,0.0,mirrored,' single.csv || { cat single.csv; fail "gus is not diagnosed 'mirrored'"; }
grep -q '^fay,4,4,100.0,' single.csv || { cat single.csv; fail "fay (the Python example) does not pass"; }

# The recipe, as docs/check.md gives it (-q: the template's space stays inside one argument).
# shellcheck disable=SC2086
parallel --will-cite -q --joblog shards.log --resume-failed \
  "$cli" check --batch class --student-cmd "{dir}/run.sh" $battery --shard {}/3 --csv shard{}.csv ::: 1 2 3 \
  > parallel.log 2>&1 || { cat parallel.log shards.log; fail "parallel: a shard failed"; }
for i in 1 2 3; do
  [ "$(wc -l < shard$i.csv)" -ge 3 ] || fail "shard $i/3 holds fewer than 2 students: the test would not merge much"
done
"$cli" check merge --csv merged.csv shard1.csv shard2.csv shard3.csv || fail "check merge exited $?"
cmp merged.csv.battery.json single.csv.battery.json || fail "the merged battery record differs from the single run's"
[ "$(wc -l < merged.csv)" -eq 16 ] || fail "the merged CSV has not 15 rows"
# Byte for byte, but for a column that two single runs of the same class already disagree on (a measured
# time, say): a second single run tells which columns those are. Without any, the files must be identical.
# shellcheck disable=SC2086
"$cli" check --batch class --student-cmd "{dir}/run.sh" $battery --csv again.csv > /dev/null 2>&1
python3 - single.csv again.csv merged.csv <<'PY' || fail "the merged CSV differs from the single run's"
import csv, sys
single, again, merged = ([row for row in csv.reader(open(name, newline=""))] for name in sys.argv[1:])
measured = {c for a, b in zip(single, again) for c, (x, y) in enumerate(zip(a, b)) if x != y}
names = [single[0][c] for c in sorted(measured)]
if len(merged) != len(single) or merged[0] != single[0]:
    sys.exit("merged: %d rows, header %s; single run: %d rows, header %s" % (len(merged), merged[0], len(single), single[0]))
for m, s in zip(merged, single):
    kept = [c for c in range(len(s)) if c not in measured]
    if len(m) != len(s) or [m[c] for c in kept] != [s[c] for c in kept]:
        sys.exit("merged row %s differs from the single run's %s (measured columns: %s)" % (m, s, names))
if not measured and open(sys.argv[3], "rb").read() != open(sys.argv[1], "rb").read():
    sys.exit("the files differ byte for byte")
print("the merged CSV equals the single run's (%d lines, 3 shards%s)"
      % (len(merged), ", but for the measured columns " + ", ".join(names) if names else ", byte for byte"))
PY

# expect_refusal PATTERN ARGS...: check merge exits 2 naming PATTERN, and writes nothing.
expect_refusal() {
  pattern=$1
  shift
  out=$("$cli" check merge --csv refused.csv "$@" 2>&1)
  status=$?
  [ "$status" -eq 2 ] || fail "merge $* exited $status, 2 expected: $out"
  printf '%s\n' "$out" | grep -q -- "$pattern" || fail "merge $*: the message does not name '$pattern': $out"
  [ ! -e refused.csv ] || fail "merge $* wrote refused.csv"
}
missing=$(sed -n '2,$p' shard3.csv | cut -d, -f1 | tr '\n' ' ')
for key in $missing; do expect_refusal "missing students:.*$key" shard1.csv shard2.csv; done
expect_refusal "shards not given: 3/3" shard1.csv shard2.csv
expect_refusal "overlap: .* is in shard2.csv and shard2.csv" shard1.csv shard2.csv shard2.csv shard3.csv
# shellcheck disable=SC2086
"$cli" check --batch class --student-cmd "{dir}/run.sh" --cases 4 --seed 1 --threads 1 --shard 2/3 \
  --csv other_seed.csv > /dev/null 2>&1 || fail "shard 2/3 with seed 1 failed"
expect_refusal "seed 1 vs 914273" shard1.csv other_seed.csv shard3.csv
expect_refusal "graded differently" shard1.csv other_seed.csv shard3.csv
echo "merge refuses a missing shard, an overlap and another seed"

# Stable slices: two students more, and every earlier student of shard 1 is still there (and nobody else).
student newcomer "$example" "$prog"
student "zz top" "$example" "$prog"
# shellcheck disable=SC2086
"$cli" check --batch class --student-cmd "{dir}/run.sh" $battery --shard 1/3 --csv later.csv > /dev/null 2>&1 \
  || fail "shard 1/3 of the larger class failed"
grep -v -e '^newcomer,' -e '^zz top,' later.csv > later_without_new.csv
# The same students with the same results; the measured columns (CPU time, peak memory) differ between runs.
python3 - later_without_new.csv shard1.csv <<'PY' || fail "adding two students changed shard 1/3's other students"
import csv, sys
def unmeasured(path):
    rows = list(csv.reader(open(path, newline="")))
    measured = [c for c, name in enumerate(rows[0]) if name in ("cpu_seconds", "peak_memory_mb")]
    return [[v for c, v in enumerate(row) if c not in measured] for row in rows]
sys.exit(0 if unmeasured(sys.argv[1]) == unmeasured(sys.argv[2]) else "the slice's rows differ")
PY
echo "adding students moves nobody"
