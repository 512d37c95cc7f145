#!/bin/sh
# The soak's figures as docs/cli.md gives them ("The last run ..."): raycam-cli shot --soak N in 3D, then in
# 2D, with the date, the machine and its load, printed as the paragraph to paste. Usage:
#   scripts/soak_table.sh [RAYCAM_CLI] [FRAMES]     (defaults: build/raycam-cli, 1000)
set -eu
cli=${1:-build/raycam-cli}
frames=${2:-1000}
[ -x "$cli" ] || { echo "soak_table.sh: no raycam-cli at $cli (build it first, or give its path)" >&2; exit 2; }
load=$(cut -d' ' -f1 /proc/loadavg)
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
figures() {  # dimension -> "median frame ms, CPU ms, +growth MB"
  out=$("$cli" shot --soak "$frames" --view "$1")
  bad=$(printf '%s\n' "$out" | sed -n 's/^soak: \([0-9]*\) frames with an inconsistent colour map$/\1/p')
  [ "$bad" = 0 ] || { printf '%s\n' "$out" >&2; echo "soak_table.sh: $1: inconsistent colour maps" >&2; exit 1; }
  printf '%s\n' "$out" | awk '
    /frame ms: median/ { for (i = 1; i <= NF; ++i) { if ($i == "median" && !f) { f = $(i + 1) } else if ($i == "median") { c = $(i + 1) } } }
    /^soak: RSS/ { gsub(/[(+]/, "", $14); g = $14 / 1024 }
    END { gsub(/,/, "", f); printf "%.1f ms median frame, %.1f ms of CPU, %+.1f MB", f, c, g }'
}
three=$(figures 3d)
two=$(figures 2d)
echo "The last run, on $(date -u '+%-d %B %Y at %H:%M UTC') ($(nproc) cores of $cpu, load average $load, $frames"
echo "frames): 3D $three; 2D $two (\`scripts/soak_table.sh\`: \`raycam-cli shot --soak $frames --view 3d\`, then \`--view 2d\`)."
