#!/usr/bin/env bash
# Time against error: builds raycam-cli, sweeps the caster's knobs on the standard scenes and writes
# docs/accuracy.csv, docs/accuracy.png (colour error) and docs/accuracy_ids.png (id error), Pareto fronts
# marked. Extra arguments go to the bench (e.g. --quick, --repeats 9, --precision float,double).
# Needs gnuplot (Debian: gnuplot-nox). Takes about a minute on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${RAYCAM_BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target raycam-cli
mkdir -p docs
bench=(bench accuracy)
"$build/raycam-cli" "${bench[@]}" --csv docs/accuracy.csv --png docs/accuracy.png "$@" | tee docs/accuracy_table.md
rm -f docs/accuracy.png.dat docs/accuracy.png.gp
