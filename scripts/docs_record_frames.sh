#!/bin/sh
# The frames docs/record.md shows: three recordings made with raycam-cli record (an orbit, the 2D and the 3D
# construction of M_d), each as a strip of four of its frames scaled to a quarter (scripts/montage.py).
# Usage: scripts/docs_record_frames.sh [RAYCAM_CLI] [OUT_FOLDER]   (defaults: build/raycam-cli, docs/)
set -eu
cli=${1:-build/raycam-cli}
out=${2:-docs}
[ -x "$cli" ] || { echo "docs_record_frames.sh: no raycam-cli at $cli (build it first, or give its path)" >&2; exit 2; }
work=$(mktemp -d "${TMPDIR:-/tmp}/raycam-record-frames.XXXXXX")
trap 'rm -rf "$work"' EXIT
# name, frames to show, then record's flags (10 fps: frame k is the camera at k/10 s)
strip() {
  name=$1 frames=$2
  shift 2
  "$cli" record --fps 10 --out "$work/$name/" "$@" > /dev/null
  set --
  for k in $frames; do set -- "$@" "$(printf '%s/%s/frame_%05d.png' "$work" "$name" "$k")"; done
  /usr/bin/python3 "$(dirname "$0")/montage.py" --scale 0.25 --gap 6 "$out/record_$name.png" "$@"
  echo "wrote $out/record_$name.png"
}
strip orbit "0 10 20 30" --sweep theta=0:360 --seconds 3
strip construction2d "0 14 27 40" --view 2d --construction --seconds 4 --lang fr
strip construction3d "0 17 36 60" --construction --seconds 6
