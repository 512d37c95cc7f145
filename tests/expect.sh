#!/bin/sh
# Runs a command and checks BOTH its exit status and its output (stdout + stderr), so a CTest entry can
# never pass on output alone (PASS_REGULAR_EXPRESSION makes CTest ignore the exit code).
#   expect.sh --exit 0|nonzero|N [--match ERE]... [--no-match ERE]... -- command [args...]
# (the command and its input files by absolute paths: it runs in a temporary folder, see below).
# Patterns are extended regular expressions (grep -E); match the flag name and the range, not whole
# sentences, so a reworded message still passes and a wrong range does not.
set -u
want=0
matches=""
rejects=""
nl='
'
while [ $# -gt 0 ]; do
  case "$1" in
    --exit) want=$2; shift 2 ;;
    --match) matches="$matches$2$nl"; shift 2 ;;
    --no-match) rejects="$rejects$2$nl"; shift 2 ;;
    --) shift; break ;;
    *) echo "expect.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
[ $# -gt 0 ] || { echo "expect.sh: no command" >&2; exit 2; }
# The command runs in a fresh temporary folder, removed afterwards: a file it writes by a relative name lands
# there, never in the build or the source tree.
scratch=$(mktemp -d "${TMPDIR:-/tmp}/raycam-expect.XXXXXX") || { echo "expect.sh: no temporary folder" >&2; exit 2; }
out=$(cd "$scratch" && "$@" 2>&1)
status=$?
rm -rf "$scratch"
printf '%s\n' "$out"
fail=0
case "$want" in
  nonzero) [ "$status" -ne 0 ] || { echo "expect.sh: FAIL: exit status 0, expected non-zero" >&2; fail=1; } ;;
  *) [ "$status" -eq "$want" ] || { echo "expect.sh: FAIL: exit status $status, expected $want" >&2; fail=1; } ;;
esac
# A crash is never the expected failure.
[ "$status" -lt 128 ] || { echo "expect.sh: FAIL: killed by signal $((status - 128))" >&2; fail=1; }
old_ifs=$IFS
IFS=$nl
for pattern in $matches; do
  printf '%s\n' "$out" | grep -Eq -e "$pattern" || { echo "expect.sh: FAIL: no output matches '$pattern'" >&2; fail=1; }
done
for pattern in $rejects; do
  if printf '%s\n' "$out" | grep -Eq -e "$pattern"; then echo "expect.sh: FAIL: output matches '$pattern'" >&2; fail=1; fi
done
IFS=$old_ifs
exit $fail
