#!/bin/sh
# `raycam-cli record` when the disk fills up part way: a file size limit (ulimit -f) makes the writes fail
# as ENOSPC would (EFBIG; SIGXFSZ ignored so that the write returns the error). Expected: exit 1, a message
# naming the file, and an empty folder (no video under the asked name, no temporary file left).
set -u
cli=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
status=0
(
  trap '' XFSZ
  ulimit -f 64  # KiB: less than a 1280x720 GIF's first frame
  "$cli" record --sweep theta=0:30 --seconds 0.2 --fps 10 --out "$dir/clip.gif"
) > "$dir.log" 2>&1 || status=$?
cat "$dir.log"
left=$(ls -A "$dir")
named=0
grep -q "^raycam-cli record: error: cannot write $dir/clip.gif" "$dir.log" || named=1
rm -f "$dir.log"
[ "$status" -eq 1 ] || { echo "full_disk: expected exit 1, got $status"; exit 1; }
[ "$named" -eq 0 ] || { echo "full_disk: the error does not name the file"; exit 1; }
[ -z "$left" ] || { echo "full_disk: left in the folder: $left"; exit 1; }
echo "full_disk: exit 1 and nothing left"
