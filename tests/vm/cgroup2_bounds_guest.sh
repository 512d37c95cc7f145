#!/bin/bash
# Run as root inside the VM of tests/vm/boot_cgroup2_vm.sh (pure cgroup v2, as instructors' machines mount
# it): the grader's bound tests, a focused subset of raycam_check_tests' [bounds] (memory, processes, disk,
# CPU, a fork bomb beside a correct neighbour, the fallback's note), in the four settings a grader meets:
#   (a) root;  (b) a user alone in a delegated group (systemd-run --user --scope -p Delegate=yes CMD);
#   (c) a user whose delegated group also holds its shell (the same with bash as CMD);  (d) a user with
#   nothing delegated. Where no group can be made, the one-line reason `raycam-cli check` gives is asserted.
# Prints VM-OK when everything passed.   usage: cgroup2_bounds_guest.sh TESTS CLI STUDENT
set -u
tests=$1 cli=$2 student=$3
uid=1000  # the guest has no user database: a bare uid, groups cleared
subset='[memory],[processes],[disk],[cpu],[fallback],[filter],[facts],[sweep]'
advice='systemd-run --user --scope -p Delegate=yes raycam-cli check'
# Software emulation runs code 3-5x slower: the tests' guards and timeouts that a right run must not reach.
export RAYCAM_TEST_TIME_SCALE=3
as_user() { setpriv --reuid "$uid" --regid "$uid" --clear-groups "$@"; }

if [ "${4:-}" = --shell-in-group ]; then
  # (c), as the user: this shell stays in the group while it runs the check (a script's last command is not
  # exec'd), as an interactive shell under systemd-run would.
  group=$5 status=0
  "$cli" check --student "$student" --cases 1 > "$TMPDIR/shared.txt" 2>&1
  "$cli" check --student "$student" --cases 1 --require-limits > "$TMPDIR/refused.txt" 2>&1
  echo "refused: exit $?" >> "$TMPDIR/refused.txt"
  "$tests" "$subset" --durations yes --use-colour no || status=1
  echo "shell: $$ $(cat /proc/$$/comm)" >> "$TMPDIR/shared.txt"
  exit $status
fi

failed=0
fail() { echo "FAILED: $*"; failed=1; }
expect() {  # expect LABEL TEXT FILE: FILE holds TEXT
  grep -qF -- "$2" "$3" || { fail "$1: expected \"$2\" in:"; cat "$3"; }
}
started=$(date +%s)
step() { echo; echo "== $* (at $(($(date +%s) - started))s)"; }
# A group delegated to the user as systemd's Delegate=yes does: the folder and the files a delegatee writes.
delegate() { mkdir "$1" && chown "$uid" "$1" "$1/cgroup.procs" "$1/cgroup.subtree_control" "$1/cgroup.threads"; }
# Runs CMD as the user from inside GROUP: this shell joins it, then setpriv execs (runuser would stay there).
in_group() { local group=$1; shift; bash -c 'echo $$ > "$0/cgroup.procs" && exec "$@"' "$group" \
  setpriv --reuid "$uid" --regid "$uid" --clear-groups "$@"; }

step "(a) as root"
"$tests" "$subset" --durations yes --use-colour no || fail "(a) the bound tests as root"
"$cli" check --student "$student" --cases 1 --require-limits > "$TMPDIR/a.txt" 2>&1 || fail "(a) --require-limits refused"

step "(b) as uid $uid alone in a delegated group"
delegate /sys/fs/cgroup/raycam-alone
in_group /sys/fs/cgroup/raycam-alone "$tests" "$subset" --durations yes --use-colour no || fail "(b) the bound tests alone in a group"
# What the advised command gives: the check the group's only process.
delegate /sys/fs/cgroup/raycam-alone-cli
in_group /sys/fs/cgroup/raycam-alone-cli "$cli" check --student "$student" --cases 1 --require-limits \
  > "$TMPDIR/b.txt" 2>&1 || { fail "(b) --require-limits refused alone in a delegated group"; cat "$TMPDIR/b.txt"; }

step "(c) as uid $uid in a delegated group that also holds its shell"
delegate /sys/fs/cgroup/raycam-shared
in_group /sys/fs/cgroup/raycam-shared bash "$0" "$tests" "$cli" "$student" --shell-in-group /sys/fs/cgroup/raycam-shared ||
  fail "(c) the bound tests beside the shell"
shell=$(sed -n 's/^shell: //p' "$TMPDIR/shared.txt")
expect "(c)" "its control group /raycam-shared holds 1 other process ($shell)" "$TMPDIR/shared.txt"
expect "(c)" "$advice" "$TMPDIR/shared.txt"
expect "(c)" "--require-limits: runs cannot be bounded as a whole: no control group can be made here: its control group /raycam-shared holds 1 other process" "$TMPDIR/refused.txt"
expect "(c)" "refused: exit 2" "$TMPDIR/refused.txt"
# The check that could not use the group left it as it found it.
[ -z "$(find /sys/fs/cgroup/raycam-shared -mindepth 1 -type d)" ] || fail "(c) a folder left in the shell's group"

step "(d) as uid $uid with nothing delegated"
as_user "$cli" check --student "$student" --cases 1 > "$TMPDIR/d.txt" 2>&1 || fail "(d) the check failed"
expect "(d)" "memory not bounded per run: no control group can be made here: this user (uid $uid) cannot write its control group / (not delegated to it)" "$TMPDIR/d.txt"
expect "(d)" "$advice" "$TMPDIR/d.txt"
expect "(d)" "one run at a time" "$TMPDIR/d.txt"
as_user "$tests" "$subset" --durations yes --use-colour no || fail "(d) the bound tests with no group"

step "a delegated group without the memory and pids controllers"
mkdir /sys/fs/cgroup/raycam-bare  # its subtree_control left empty: nothing passed on to its children
delegate /sys/fs/cgroup/raycam-bare/inner
in_group /sys/fs/cgroup/raycam-bare/inner "$cli" check --student "$student" --cases 1 > "$TMPDIR/e.txt" 2>&1
expect "(e)" "the controllers memory, pids are not delegated to its control group /raycam-bare/inner" "$TMPDIR/e.txt"

step "done"
[ "$failed" = 0 ] && echo VM-OK
exit "$failed"
