#!/bin/sh
# Runs the [bounds] tests of raycam_check_tests (its path: $1) as an ordinary user, the usual grader: once
# with no control group to be made (the fallback: said once, --require-limits refuses), once inside a cgroup
# v1 subtree delegated to that user (chown), as systemd's Delegate= gives one. Made by root: skipped (77)
# where the tests do not run as root or cannot make the user.
set -u
tests=$1
[ "$(id -u)" = 0 ] || { echo "as_ordinary_user.sh: not root, skipped"; exit 77; }
user=raycam-grader
if ! id -u "$user" >/dev/null 2>&1; then
  useradd --system --no-create-home --shell /usr/sbin/nologin "$user" || { echo "cannot make $user: skipped"; exit 77; }
fi
scratch=$(mktemp -d "${TMPDIR:-/tmp}/raycam-as-user.XXXXXX") || exit 1
chmod 755 "$scratch"
mkdir "$scratch/tmp" && chown "$user" "$scratch/tmp"
as_user() { runuser -u "$user" -- env TMPDIR="$scratch/tmp" HOME="$scratch/tmp" "$@"; }
status=0

echo "== as $user, no control group"
as_user "$tests" "[bounds]" || status=1

echo "== as $user, in a delegated cgroup v1 subtree"
delegated=""
for controller in memory pids cpuacct; do
  own=$(awk -F: -v c="$controller" '{ n = split($2, names, ","); for (i = 1; i <= n; i++) if (names[i] == c) print $3 }' /proc/self/cgroup)
  folder="/sys/fs/cgroup/$controller${own%/}/raycam-delegated-$$"
  mkdir "$folder" && chown -R "$user" "$folder" || { echo "cannot delegate $controller: skipped"; status=77; }
  delegated="$delegated $folder"
done
if [ "$status" != 77 ]; then
  # This shell's child joins the subtree, then becomes the user: the checker's groups are made under it.
  sh -c 'for folder in $1; do echo $$ > "$folder/cgroup.procs"; done; shift; exec "$@"' sh "$delegated" \
    runuser -u "$user" -- env TMPDIR="$scratch/tmp" HOME="$scratch/tmp" "$tests" "[bounds]" || status=1
fi
# Deepest first: a group a failed run left inside would keep the delegated folder.
for folder in $delegated; do find "$folder" -depth -type d -exec rmdir {} \; 2>/dev/null; done
rm -rf "$scratch"
exit $status
