#!/usr/bin/env bash
# Time against error: builds raycam-cli, sweeps the caster's knobs on the standard scenes and writes
# docs/accuracy.csv, docs/accuracy.png (colour error) and docs/accuracy_ids.png (id error), Pareto fronts
# marked. Extra arguments go to the bench (e.g. --quick, --repeats 9, --precision float,double).
# Needs gnuplot (Debian: gnuplot-nox). Takes about a minute on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/build-cli.sh
bench=(bench accuracy)
"$cli" "${bench[@]}" --csv docs/accuracy.csv --png docs/accuracy.png "$@" | tee docs/accuracy_table.md
rm -f docs/accuracy.png.dat docs/accuracy.png.gp
