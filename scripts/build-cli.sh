# Sourced by the benchmark scripts: from the repository's root, (re)builds raycam-cli in Release into
# $RAYCAM_BUILD_DIR (default build/), sets $cli to it, and makes docs/ for the results.
build="${RAYCAM_BUILD_DIR:-build}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j2 --target raycam-cli
cli="$build/raycam-cli"
mkdir -p docs
