#!/bin/sh
# Builds raycam's web page into build-web/ (a folder of static files: index.html, index.js, index.wasm,
# index.data with the DejaVu font and scenes/) and serves it on http://localhost:8000.
#   ./scripts/web.sh               build, then serve (Ctrl+C stops)
#   ./scripts/web.sh --build-only  build only
# Needs Debian 12's emscripten (scripts/install-deps.sh). See docs/web.md.
set -eu
cd "$(dirname "$0")/.."
build_only=0
case "${1:-}" in
  --build-only) build_only=1 ;;
  "") ;;
  *) echo "web.sh: error: expected no argument or --build-only, got '$1'" >&2; exit 2 ;;
esac
# Debian's emscripten uses its prebuilt system libraries (/usr/share/emscripten/cache, frozen); its
# JavaScript optimiser finds acorn only through NODE_PATH when node is not Debian's own.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
mkdir -p build-web
[ -f build-web/CMakeCache.txt ] || emcmake cmake -S . -B build-web -DCMAKE_BUILD_TYPE=Release
cmake --build build-web -j"${WEB_JOBS:-2}"
echo "web.sh: the page is build-web/index.html (+ index.js, index.wasm, index.data)"
[ "$build_only" = 1 ] && exit 0
echo "web.sh: serving on http://localhost:8000 (Ctrl+C stops)"
cd build-web && exec python3 -m http.server 8000
