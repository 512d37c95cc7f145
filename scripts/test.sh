#!/usr/bin/env bash
# The test command (README; docs/testing.md): installs the dependencies, builds in build/ (what changed; from nothing when build/ is new), runs CTest
# (every entry, the `slow` ones under qemu too), then checks that the tests wrote nothing into the checkout.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
scripts/web.sh --build-only  # the web page, for CTest's browser tests (docs/web.md)
# Tests write only into temporary folders: the checkout's status (tracked changes and untracked files,
# build/ ignored) must be the same after CTest as before it. Compared, not required empty, so a developer's
# own uncommitted edits do not fail it.
tree_status() {
  git rev-parse --is-inside-work-tree > /dev/null 2>&1 || return 0  # not a git checkout: nothing to compare
  git status --porcelain --untracked-files=all
  git diff HEAD --binary | sha1sum  # content changes to files a developer had already edited
}
before=$(tree_status)
status=0
ctest --test-dir build --output-on-failure -j"$(nproc)" || status=$?
after=$(tree_status)
if [ "$before" != "$after" ]; then
  echo "test.sh: the tests changed the checkout (they must write only into temporary folders):" >&2
  diff <(echo "$before") <(echo "$after") >&2 || true
  status=1
fi
exit $status
