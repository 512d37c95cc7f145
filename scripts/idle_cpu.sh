#!/bin/sh
# CPU used by the raycam window while nobody touches it (docs/speed.md): starts a private Xvfb, runs
# the app with no input, waits for it to settle, then reads its utime + stime from /proc/PID/stat at the
# start and end of each second and prints a table (per second and overall, as % of one core).
# usage: scripts/idle_cpu.sh [APP] [SECONDS]   (default build/raycam, 10 s)
set -eu
app=${1:-build/raycam}
seconds=${2:-10}
display=:$((90 + $$ % 100))
Xvfb "$display" -screen 0 1280x800x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $app_pid 2>/dev/null; kill $xvfb 2>/dev/null' EXIT
sleep 1
DISPLAY=$display "$app" --width 1280 --height 720 >/tmp/idle_cpu_$$.out 2>&1 &
app_pid=$!
sleep 3  # start-up: first cast, fonts, shaders
ticks=$(getconf CLK_TCK)
cpu_ticks() { awk '{print $14 + $15}' "/proc/$app_pid/stat"; }  # utime + stime, in clock ticks
echo "| second | CPU ms | % of a core |"
echo "|---|---|---|"
first=$(cpu_ticks)
previous=$first
i=1
while [ "$i" -le "$seconds" ]; do
  sleep 1
  now=$(cpu_ticks)
  echo "| $i | $(( (now - previous) * 1000 / ticks )) | $(awk -v t="$((now - previous))" -v hz="$ticks" 'BEGIN {printf "%.1f", 100 * t / hz}') |"
  previous=$now
  i=$((i + 1))
done
total=$((previous - first))
echo "| all | $((total * 1000 / ticks)) | $(awk -v t="$total" -v hz="$ticks" -v s="$seconds" 'BEGIN {printf "%.2f", 100 * t / hz / s}') |"
kill -TERM "$app_pid" 2>/dev/null || true
wait "$app_pid" 2>/dev/null || true
cat /tmp/idle_cpu_$$.out | grep -i "frames" || true
rm -f /tmp/idle_cpu_$$.out
