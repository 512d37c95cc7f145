#!/usr/bin/env bash
# Runs each libFuzzer target for SECONDS (default 60) from the committed seed corpus in fuzz/corpus/.
# New inputs go to a scratch corpus (build-fuzz/corpus/), never into the committed one. A crash leaves its
# input in build-fuzz/artifacts/ and exits non-zero: turn it into a regression test (tests/core/).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
scripts/install-deps.sh
CXX=clang++-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAYCAM_FUZZ=ON -DRAYCAM_BUILD_APP=OFF \
  -DRAYCAM_BUILD_BENCH=OFF -DRAYCAM_BUILD_TESTS=OFF >/dev/null
cmake --build build-fuzz -j"$(nproc)" --target fuzz_scene_file fuzz_camera fuzz_answer
mkdir -p build-fuzz/artifacts
for target in scene_file camera answer; do
  mkdir -p "build-fuzz/corpus/$target"
  echo "fuzz_$target: ${seconds} s"
  "build-fuzz/fuzz_$target" "build-fuzz/corpus/$target" "fuzz/corpus/$target" -max_total_time="$seconds" \
    -rss_limit_mb=4096 -timeout=10 -artifact_prefix="build-fuzz/artifacts/$target-" -print_final_stats=1 2>&1 |
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|==.*ERROR|SUMMARY|Done)" || true
  [ "${PIPESTATUS[0]}" -eq 0 ] || { echo "fuzz_$target found a crash: see build-fuzz/artifacts/"; exit 1; }
done
