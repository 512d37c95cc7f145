#!/usr/bin/env bash
# The core and CLI tests, and the frame's (ui: the null host runs whole frames with no GL context), under
# AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/). Any report fails.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# The benchmarks' commands stay in (their CTest entries run the accuracy sweep's code under the sanitizers);
# Embree, an uninstrumented outside library, is left out.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRAYCAM_SANITIZE=ON -DRAYCAM_BUILD_APP=OFF \
      -DRAYCAM_BUILD_FRAME=ON -DRAYCAM_BUILD_BENCH=ON -DCMAKE_DISABLE_FIND_PACKAGE_embree=ON >/dev/null
cmake --build build-asan -j"$(nproc)"
# Not the `vm` entry (the kernel's bounds under cgroup v2, in a VM): scripts/test.sh runs it; here it would
# add minutes of software emulation for no code of raycam's that the other entries do not run.
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  LSAN_OPTIONS=suppressions="$PWD/tests/lsan.supp" ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -LE vm
