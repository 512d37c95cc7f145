#!/usr/bin/env bash
# Time against error: builds raycam-cli, sweeps the caster's knobs on the standard scenes (bench accuracy,
# timed by Google Benchmark) and writes docs/accuracy.csv and docs/accuracy_table.md, then plots from the CSV
# with gnuplot: docs/accuracy.png (colour error) and docs/accuracy_ids.png (id error, 1-spp settings), one
# panel per scene, the Pareto front as a line. Extra arguments go to the bench (e.g. --quick, --repeats 9).
#   scripts/accuracy_plot.sh --plot-only CSV PNG   plots an existing CSV (no build, no sweep)
# Needs gnuplot (Debian: gnuplot-nox). Takes about a minute on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ "${1:-}" = "--plot-only" ]; then
  csv=$2 png=$3
else
  . scripts/build-cli.sh
  csv=docs/accuracy.csv png=docs/accuracy.png
  "$cli" bench accuracy --csv "$csv" "$@" | tee docs/accuracy_table.md
fi
command -v gnuplot >/dev/null || { echo "accuracy_plot: gnuplot not found (Debian: gnuplot-nox)" >&2; exit 1; }
ids_png=${png%.png}_ids.png
# CSV columns: scene,label,precision,intersect,frame,placement,spp,median_ms,id_error,colour_error,pareto_colour,
# pareto_id. Rows of a scene are sorted by time, so the front's points join left to right. Errors of exactly 0
# cannot go on a log axis: they are drawn at the floors below (stated on the plot).
scenes=$(tail -n +2 "$csv" | cut -d, -f1 | awk '!seen[$0]++')
count=$(echo "$scenes" | wc -l)
per_row=$((count < 3 ? count : 3))
rows=$(((count + per_row - 1) / per_row))
plot() {  # $1 output, $2 error column, $3 front column, $4 floor, $5 what, $6 y label, $7 1-spp only (0/1)
  {
    echo "set terminal pngcairo size $((700 * per_row)),$((520 * rows + 40)) font 'DejaVu Sans,11'"
    echo "set output '$1'"
    echo "set datafile separator ','"
    echo "set multiplot layout $rows,$per_row title 'raycam: median time per frame against $5 (labels: precision f/d/l, intersect n/s, frame w/r, spp; line: Pareto front; 0 drawn at $4)'"
    echo "set logscale xy; set grid; set key top right; set xlabel 'median time per frame (ms)'; set ylabel '$6'"
    [ "$7" = 1 ] && echo "set yrange [5e-6:2]"
    for scene in $scenes; do
      keep="strcol(1) eq '$scene' && ($7 == 0 || \$7 == 1)"
      err="(\$$2 > $4 ? \$$2 : $4)"
      echo "set title '$scene'"
      echo "plot '$csv' skip 1 using (($keep) ? \$8 : 1/0):$err with points pt 7 ps 0.7 title 'setting', \\"
      echo "     '' skip 1 using (($keep) ? \$8 : 1/0):$err:2 with labels font ',7' offset 0.2,0.5 left notitle, \\"
      # The front from its own rows only (an undefined point would break the line).
      echo "     \"< awk -F, '\\\$1 == \\\"$scene\\\" && \\\$$3 == 1' $csv\" using 8:$err with linespoints lw 2 pt 6 ps 1.5 title 'Pareto front'"
    done
    echo "unset multiplot"
  } | gnuplot
}
plot "$png" 10 11 1e-3 "mean colour error vs exact coverage" "mean colour error (8-bit units)" 0
plot "$ids_png" 9 12 1e-5 "fraction of pixel ids differing from the exact reference (1 spp)" "fraction of ids wrong" 1
echo "plots: $png (colour error), $ids_png (id error)"
