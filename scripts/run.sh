#!/usr/bin/env bash
# The run command (README): builds, then opens the app where there is a display, or renders the same
# frame headless to raycam-shot.png where there is none. Extra arguments go to the app / renderer.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
if [ -n "${DISPLAY:-}" ] && [ -x build/raycam ]; then
  exec build/raycam "$@"
elif build/raycam-cli shot --help >/dev/null 2>&1; then
  build/raycam-cli shot --out raycam-shot.png "$@"
  echo "No display: rendered the app's window headless to $(pwd)/raycam-shot.png"
else
  build/raycam-cli render --out raycam-render.png "$@"
  echo "No display: rendered the colour map to $(pwd)/raycam-render.png"
fi
