#!/usr/bin/env bash
# Speed: builds raycam-cli, runs `raycam-cli bench speed` (Google Benchmark: raycam's casters against Embree 3
# and the floor, median of 7 repetitions), prints the summary table (raycam, Embree, the floor, per K and
# size) and writes it to docs/speed_table.md, Google Benchmark's full output to docs/speed_run.txt, every
# median to docs/speed.csv and docs/speed.png (log-log median time against the sphere count K at 1024²,
# 2 threads). Extra arguments go to the bench (e.g. --quick, --repeats 9, --counts 1000,100000).
# Needs gnuplot (Debian: gnuplot-nox) for the plot. Takes about 4 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/build-cli.sh
"$cli" bench speed --csv docs/speed.csv "$@" > docs/speed_run.txt
sed -n '/^raycam (automatic) against/,$p' docs/speed_run.txt | tee docs/speed_table.md
scripts/plot_speed.sh docs/speed.csv docs/speed.png
