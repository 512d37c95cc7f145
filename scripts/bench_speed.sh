#!/usr/bin/env bash
# Speed: builds raycam-cli, runs `raycam-cli bench speed` (raycam's casters against Embree 3, median of 7)
# and writes docs/speed_table.md, docs/speed.csv and docs/speed.png (log-log median time against the
# sphere count K at 1024², 2 threads). Extra arguments go to the bench (e.g. --quick, --repeats 9).
# Needs gnuplot (Debian: gnuplot-nox) for the plot. Takes about 4 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/build-cli.sh
"$cli" bench speed --csv docs/speed.csv "$@" | tee docs/speed_table.md
scripts/plot_speed.sh docs/speed.csv docs/speed.png
