#!/usr/bin/env bash
# Throughput of `check --batch` on this machine (docs/check.md, "A large course"). A class of STUDENTS: a third
# the C++ example (passes), a third the Python example (passes), a third the test's mistaken student with one
# classic mistake each (fails, so the diagnosis runs), on the default battery (12 cases). Each way is timed
# REPEATS times and the median printed, in students per minute:
#   - one shard with every core (--threads = the cores), the way a single machine grades by default;
#   - two shards at once (GNU parallel -j2), each with half the cores, then check merge;
#   - two shards at once, each with every core (twice as many runs as cores);
# and where the time goes, per run: the C++ third alone with and without the sandbox (the sandbox's start),
# python3's start-up alone, and grading answer files with no program at all (references, grading, diagnosis).
#   scripts/check_throughput.sh [STUDENTS] [REPEATS]     (default 24 and 3; about 3 minutes on 2 cores)
set -euo pipefail
students=${1:-24}
repeats=${2:-3}
cd "$(dirname "$0")/.."
. scripts/build-cli.sh > /dev/null
cmake --build "$build" -j2 --target raycam_example_student raycam_mistaken_student > /dev/null
cli=$(realpath "$cli")
cores=$(nproc)
half=$(( cores > 1 ? cores / 2 : 1 ))
work=$(mktemp -d "${TMPDIR:-/tmp}/raycam-throughput.XXXXXX")
trap 'rm -rf "$work"' EXIT
chmod 755 "$work"  # sandboxed runs by root use another uid: the class must be readable by anyone
cd "$work"

# student CLASS NAME PROGRAM COMMAND...: a folder with its program and run.sh.
student() {
  local class=$1 name=$2 program=$3
  shift 3
  mkdir -p "$class/$name"
  cp "$program" "$class/$name/"
  printf '#!/bin/sh\ncd "$(dirname "$0")"\nexec %s\n' "$*" > "$class/$name/run.sh"
  chmod -R a+rX "$class" && chmod a+x "$class/$name/run.sh"
}
example=$(realpath "$OLDPWD/$build/raycam_example_student")
mistaken=$(realpath "$OLDPWD/$build/raycam_mistaken_student")
python=$OLDPWD/examples/student/camera.py
mistakes=(mirrored upside_down no_t_min pixel_edges res_truncated degrees_as_radians theta_phi_swapped eye_origin)
for i in $(seq 1 "$students"); do
  name=$(printf 'student%03d' "$i")
  case $((i % 3)) in
    0) student class "$name" "$example" ./raycam_example_student
       student cpp "$name" "$example" ./raycam_example_student ;;
    1) student class "$name" "$python" python3 camera.py ;;
    2) student class "$name" "$mistaken" ./raycam_mistaken_student --mistake "${mistakes[$((i % ${#mistakes[@]}))]}" ;;
  esac
done

# seconds COMMAND...: the wall time of one run, and the CPU time (user + system) of the processes it waited
# for, in seconds. The CPU time is kept only where every process is a direct child (python3's start-up, the
# answer files): check's runs are grandchildren reparented away from it, whose time no parent collects.
seconds() {
  local TIMEFORMAT='%R %U %S' times
  times=$( { time "$@" > /dev/null 2>&1; } 2>&1 ) || true  # check exits 1 when a student fails: the point here
  awk '{print $1, $2 + $3}' <<< "$times"
}
calc() { awk "BEGIN {print $1}"; }
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
# timed COMMAND...: "WALL CPU", each the median of REPEATS runs.
timed() {
  local runs
  runs=$(for _ in $(seq 1 "$repeats"); do seconds "$@"; done)
  echo "$(cut -d' ' -f1 <<< "$runs" | median) $(cut -d' ' -f2 <<< "$runs" | median)"
}
wall() { echo "${1% *}"; }
cpu() { echo "${1#* }"; }

batch=(check --batch class --student-cmd "{dir}/run.sh")
one_shard() { "$cli" "${batch[@]}" --csv one.csv; }
two_shards() {
  parallel --will-cite -q -j2 "$cli" "${batch[@]}" --threads "$1" --shard {}/2 --csv two{}.csv ::: 1 2
  "$cli" check merge --csv two.csv two1.csv two2.csv
}
one=$(timed one_shard)
two_half=$(timed two_shards "$half")
two_full=$(timed two_shards "$cores")
cmp one.csv two.csv  # the same grades either way
cp one.csv "${THROUGHPUT_CSV:-/dev/null}"

cpp_count=$(find cpp -mindepth 1 -maxdepth 1 -type d | wc -l)
sandboxed=$(timed "$cli" check --batch cpp --student-cmd "{dir}/run.sh" --csv cpp.csv)
bare=$(timed "$cli" check --batch cpp --student-cmd "{dir}/run.sh" --csv cpp.csv --no-sandbox)
python_start=$(timed bash -c 'for _ in $(seq 20); do python3 -c pass; done')
"$cli" check --write-cases cases > /dev/null
for k in $(seq -w 1 12); do "$mistaken" --mistake mirrored < "cases/case_$k.json" > "cases/answer_$k.json"; done
answers=$(timed "$cli" check --answers cases)

per_minute() { awk "BEGIN {printf \"%.0f\", 60 * $students / $1}"; }
printf '%s students (default battery: 12 cases), %s cores, median of %s runs; load average at the end: %s\n' \
  "$students" "$cores" "$repeats" "$(cut -d" " -f1-3 /proc/loadavg)"
printf '| way | seconds | students per minute |\n|---|---|---|\n'
row() { printf '| %s | %.1f | %s |\n' "$1" "$(wall "$2")" "$(per_minute "$(wall "$2")")"; }
row "one shard, --threads $cores" "$one"
row "two shards at once, --threads $half each" "$two_half"
row "two shards at once, --threads $cores each" "$two_full"
runs=$((cpp_count * 12))
printf 'where the time goes, per run:\n'
printf '  the C++ example (%s runs, %s at once): %.1f ms sandboxed, %.1f ms without: the sandbox costs %.1f ms\n' \
  "$runs" "$cores" "$(calc "1000 * $(wall "$sandboxed") * $cores / $runs")" \
  "$(calc "1000 * $(wall "$bare") * $cores / $runs")" "$(calc "1000 * ($(wall "$sandboxed") - $(wall "$bare")) * $cores / $runs")"
printf '  python3 start-up alone: %.1f ms CPU, %.1f ms wall\n' "$(calc "1000 * $(cpu "$python_start") / 20")" \
  "$(calc "1000 * $(wall "$python_start") / 20")"
printf '  grading an answer of a mirrored camera, diagnosis included, no program: %.0f ms CPU per case\n' \
  "$(calc "1000 * $(cpu "$answers") / 12")"
printf '16 cores, if the runs scale as the independent processes they are: about %s students per minute\n' \
  "$(calc "int(16 / $cores * $(per_minute "$(wall "$one")"))")"
