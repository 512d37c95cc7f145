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

# seconds COMMAND...: the wall time of one run, in seconds.
seconds() {
  local start end
  start=$(date +%s.%N)
  "$@" > /dev/null 2>&1 || true  # check exits 1 when a student fails: that is the point here
  end=$(date +%s.%N)
  calc "$end - $start"
}
calc() { awk "BEGIN {print $1}"; }
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
# timed NAME COMMAND...: the median of REPEATS runs.
timed() {
  local name=$1
  shift
  for _ in $(seq 1 "$repeats"); do seconds "$@"; done | median
}

batch=(check --batch class --student-cmd "{dir}/run.sh")
one_shard() { "$cli" "${batch[@]}" --csv one.csv; }
two_shards() {
  parallel --will-cite -q -j2 "$cli" "${batch[@]}" --threads "$1" --shard {}/2 --csv two{}.csv ::: 1 2
  "$cli" check merge --csv two.csv two1.csv two2.csv
}
one=$(timed one one_shard)
two_half=$(timed two two_shards "$half")
two_full=$(timed two two_shards "$cores")
cmp one.csv two.csv  # the same grades either way

cpp_count=$(find cpp -mindepth 1 -maxdepth 1 -type d | wc -l)
sandboxed=$(timed cpp "$cli" check --batch cpp --student-cmd "{dir}/run.sh" --csv cpp.csv)
bare=$(timed cpp "$cli" check --batch cpp --student-cmd "{dir}/run.sh" --csv cpp.csv --no-sandbox)
python_start=$(timed python bash -c 'for _ in $(seq 20); do python3 -c pass; done')
"$cli" check --write-cases cases > /dev/null
for k in $(seq -w 1 12); do "$mistaken" --mistake mirrored < "cases/case_$k.json" > "cases/answer_$k.json"; done
answers=$(timed answers "$cli" check --answers cases)

per_minute() { awk "BEGIN {printf \"%.0f\", 60 * $students / $1}"; }
printf '%s students (default battery: 12 cases), %s cores, median of %s runs; load average at the end: %s\n' \
  "$students" "$cores" "$repeats" "$(cut -d" " -f1-3 /proc/loadavg)"
printf '| way | seconds | students per minute |\n|---|---|---|\n'
printf '| one shard, --threads %s | %.1f | %s |\n' "$cores" "$one" "$(per_minute "$one")"
printf '| two shards at once, --threads %s each | %.1f | %s |\n' "$half" "$two_half" "$(per_minute "$two_half")"
printf '| two shards at once, --threads %s each | %.1f | %s |\n' "$cores" "$two_full" "$(per_minute "$two_full")"
printf 'where the time goes, per run (%s C++ students x 12 cases = %s runs):\n' "$cpp_count" "$((cpp_count * 12))"
printf '  sandbox start: %.1f ms (%.2f s sandboxed - %.2f s without, over the runs, %s cores)\n' \
  "$(calc "1000 * ($sandboxed - $bare) * $cores / ($cpp_count * 12)")" "$sandboxed" "$bare" "$cores"
printf '  python3 start-up: %.1f ms\n' "$(calc "1000 * $python_start / 20")"
printf '  grading 12 answer files of a mirrored camera, diagnosis included, no program: %.2f s (%.0f ms per case)\n' \
  "$answers" "$(calc "1000 * $answers / 12")"
