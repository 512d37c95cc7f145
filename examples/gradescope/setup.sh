#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image. The autograder's zip holds this
# file, run_autograder and raycam's source as raycam/ (README.md here: how to make the zip). It installs
# raycam's build dependencies from the distribution's packages and builds raycam-cli only (no window, no
# benchmarks, no tests). Needs CMake 3.24 or later: pick a base image with it (Ubuntu 24.04, Debian 12).
set -euo pipefail
source_dir=${AUTOGRADER:-/autograder}/source
apt-get update -qq
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
  cmake g++ make pkg-config libglm-dev nlohmann-json3-dev libstb-dev libcli11-dev libcairo2-dev libpng-dev \
  bubblewrap python3 > /dev/null
cmake -S "$source_dir/raycam" -B "$source_dir/build" -DCMAKE_BUILD_TYPE=Release \
  -DRAYCAM_BUILD_APP=OFF -DRAYCAM_BUILD_BENCH=OFF -DRAYCAM_BUILD_TESTS=OFF
cmake --build "$source_dir/build" -j"$(nproc)" --target raycam-cli
"$source_dir/build/raycam-cli" check --help > /dev/null  # the image is built only if raycam-cli runs
