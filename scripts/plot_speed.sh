#!/usr/bin/env bash
# Plots a `raycam-cli bench speed --csv` file: median ms against K for the cube family, log-log, 1024² (or the
# largest side in the file) on 2 threads (or the most in the file), one line per variant. Usage:
# plot_speed.sh CSV PNG.
set -euo pipefail
csv="$1" png="$2"
command -v gnuplot >/dev/null || { echo "plot_speed: gnuplot not found, no plot"; exit 0; }
side=$(awk -F, 'NR > 1 && $3 > s { s = $3 } END { print s }' "$csv")
threads=$(awk -F, 'NR > 1 && $4 > t { t = $4 } END { print t }' "$csv")
data=$(mktemp)
trap 'rm -f "$data"' EXIT
for variant in "fill only" "rays only" projection plain footprint binned automatic "embree packet1" "embree packet16" \
  "embree p16 ray table"; do
  echo "\"$variant\""
  awk -F, -v side="$side" -v threads="$threads" -v v="\"$variant\"" \
    '$1 == "\"cube\"" && $3 == side && $4 == threads && $5 == v { print ($2 > 0 ? $2 : 0.5), $6 }' "$csv"
  printf '\n\n'
done > "$data"
gnuplot <<GP
set terminal pngcairo size 900,560 font ",11"
set output "$png"
set logscale xy
set xlabel "spheres K"
set ylabel "median ms per ${side}x${side} image (${threads} threads)"
set key outside right
set grid
set title "raycam's casters against Embree 3 and the floor (lower is better)"
plot for [i=0:9] "$data" index i using 1:2 with linespoints title columnheader(1)
GP
echo "wrote $png"
