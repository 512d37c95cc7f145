#!/bin/sh
# Builds raycam's web page into build-web/ (a folder of static files: index.html, index.js, index.wasm,
# index.data with the DejaVu font and scenes/; and raycam.html, the same page in one file) and serves it on
# http://localhost:8000.
#   ./scripts/web.sh                build, then serve (Ctrl+C stops)
#   ./scripts/web.sh --build-only   build only
#   ./scripts/web.sh --single-file  build only build-web/raycam.html: the whole app in one file, which opens
#                                   from a file:// URL (a USB stick, a course page's attachment), no server
# Needs Debian 12's emscripten (scripts/install-deps.sh). See docs/web.md.
set -eu
cd "$(dirname "$0")/.."
build_only=0
target=all
case "${1:-}" in
  --build-only) build_only=1 ;;
  --single-file) build_only=1 target=raycam_web_single ;;
  "") ;;
  *) echo "web.sh: error: expected no argument, --build-only or --single-file, got '$1'" >&2; exit 2 ;;
esac
# Debian's emscripten uses its prebuilt system libraries (/usr/share/emscripten/cache, frozen); its
# JavaScript optimiser finds acorn only through NODE_PATH when node is not Debian's own.
export NODE_PATH="${NODE_PATH:-/usr/share/nodejs}"
mkdir -p build-web
[ -f build-web/CMakeCache.txt ] || emcmake cmake -S . -B build-web -DCMAKE_BUILD_TYPE=Release
cmake --build build-web -j"${WEB_JOBS:-2}" --target "$target"
# Its size as built, the figure docs/web.md gives.
single_mb=$(awk -v b="$(stat -c %s build-web/raycam.html)" 'BEGIN { printf "%.1f MB", b / 1e6 }')
if [ "$target" = raycam_web_single ]; then
  echo "web.sh: the single-file page is build-web/raycam.html, $single_mb (opens from a file:// URL, no server)"
  exit 0
fi
echo "web.sh: the page is build-web/index.html (+ index.js, index.wasm, index.data); build-web/raycam.html in one file, $single_mb"
[ "$build_only" = 1 ] && exit 0
echo "web.sh: serving on http://localhost:8000 (Ctrl+C stops)"
cd build-web && exec python3 -m http.server 8000
