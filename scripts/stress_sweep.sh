#!/usr/bin/env bash
# The long numerical stress sweep (CI runs the short one: tests/stress/). Every stress case × float/double ×
# naive/stable × world/camera-relative against the exact reference; prints the markdown table (setting →
# worst id error) and the arccos-vs-atan2 angle table, writes docs/stress.csv and docs/angles.csv.
# Exits non-zero if anything is non-finite. Pass --short for the CI list.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${RAYCAM_BUILD_DIR:-build}"
length=(--long)
[ "${1:-}" = "--short" ] && length=()
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target raycam-cli
mkdir -p docs
bench=(bench accuracy)
"$build/raycam-cli" "${bench[@]}" --stress "${length[@]}" --csv docs/stress.csv
"$build/raycam-cli" "${bench[@]}" --angles --csv docs/angles.csv
