#!/usr/bin/env bash
# The long numerical stress sweep (CI runs the short one: tests/stress/). Every stress case × float/double ×
# naive/stable × world/camera-relative against the exact reference; prints the markdown table (setting →
# worst id error) and the arccos-vs-atan2 angle table, writes docs/stress.csv and docs/angles.csv.
# Exits non-zero if anything is non-finite. Pass --short for the CI list.
set -euo pipefail
cd "$(dirname "$0")/.."
length=(--long)
[ "${1:-}" = "--short" ] && length=()
. scripts/build-cli.sh
bench=(bench accuracy)
"$cli" "${bench[@]}" --stress "${length[@]}" --csv docs/stress.csv
"$cli" "${bench[@]}" --angles --csv docs/angles.csv
