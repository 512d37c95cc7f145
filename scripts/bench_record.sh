#!/usr/bin/env bash
# How fast `raycam-cli record` writes each format: 1280x720 at 30 fps, a 4 s orbit (121 frames) of the 3D demo,
# the whole window rendered headless. Prints a Markdown table (frames per second achieved, and whether that
# keeps up with the 30 fps of the video) and the machine's load, which on a shared machine moves the figures
# more than the code does. Usage: scripts/bench_record.sh [BUILD_DIR] [SECONDS]
set -euo pipefail
build=${1:-build}
seconds=${2:-4}
cli="$build/raycam-cli"
[ -x "$cli" ] || { echo "bench_record: no $cli (cmake --build $build --target raycam-cli)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "bench_record: $(nproc) cores, load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| format | frames | wall s | frames/s | real time (30 fps)? | render ms/frame | size |"
echo "|---|---|---|---|---|---|---|"
for target in clip.mp4 clip.webm clip.gif frames/; do
  start=$(date +%s.%N)
  report=$("$cli" record --sweep theta=0:360 --seconds "$seconds" --fps 30 --width 1280 --height 720 --out "$out/$target")
  end=$(date +%s.%N)
  frames=$(sed -n 's/.*(\(.*\), \([0-9]*\) frames of.*/\2/p' <<<"$report" | head -1)
  format=$(sed -n 's/^wrote [^(]*(\([^,]*\),.*/\1/p' <<<"$report")
  render=$(sed -n 's/^per frame: \([0-9.]*\) ms rendering.*/\1/p' <<<"$report")
  size=$(du -sh "$out/$target" | cut -f1)
  awk -v f="$format" -v n="$frames" -v a="$start" -v b="$end" -v r="$render" -v s="$size" 'BEGIN {
    wall = b - a; rate = n / wall;
    printf "| %s | %d | %.2f | %.1f | %s | %s | %s |\n", f, n, wall, rate, (rate >= 30 ? "yes" : "no"), r, s }'
done
echo
echo "bench_record: load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
