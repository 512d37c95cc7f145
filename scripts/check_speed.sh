#!/bin/sh
# The default battery's time for one student program, before/after a change: two raycam-cli binaries run
# alternately (so that the machine's load falls on both alike), N times each; prints the medians and their ratio.
#   scripts/check_speed.sh OLD_RAYCAM_CLI NEW_RAYCAM_CLI "STUDENT COMMAND" [N, default 15]
set -eu
[ $# -ge 3 ] || { echo "usage: $0 OLD_RAYCAM_CLI NEW_RAYCAM_CLI \"STUDENT COMMAND\" [N]" >&2; exit 2; }
old=$1 new=$2 student=$3 n=${4:-15}
times=$(mktemp)
trap 'rm -f "$times"' EXIT
i=0
while [ "$i" -lt "$n" ]; do
  for which in old new; do
    if [ "$which" = old ]; then cli=$old; else cli=$new; fi
    start=$(date +%s.%N)
    "$cli" check --student "$student" > /dev/null 2>&1 || true  # a failing case is still a timed run
    end=$(date +%s.%N)
    echo "$which $(echo "$end - $start" | bc)" >> "$times"
  done
  i=$((i + 1))
done
median() { grep "^$1 " "$times" | awk '{ print $2 }' | sort -n | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
m_old=$(median old) m_new=$(median new)
printf 'runs: %d each, alternately\nold median: %.3f s\nnew median: %.3f s\nratio new/old: %.2f\n' \
  "$n" "$m_old" "$m_new" "$(echo "$m_new / $m_old" | bc -l)"
