#!/bin/sh
# The frames docs/record.md shows: three recordings made with raycam-cli record (an orbit, the 2D and the 3D
# construction of M_d), each as a strip of four of its frames scaled to a quarter (PIL, python3-pil).
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
  # shellcheck disable=SC2086  # the frame numbers, one argument each
  /usr/bin/python3 - "$work/$name" "$out/record_$name.png" $frames <<'PY'
import sys
from PIL import Image
folder, target, frames = sys.argv[1], sys.argv[2], [int(k) for k in sys.argv[3:]]
shots = [Image.open("%s/frame_%05d.png" % (folder, k)).convert("RGB") for k in frames]
w, h, gap = shots[0].width // 4, shots[0].height // 4, 6
sheet = Image.new("RGB", (len(shots) * w + (len(shots) - 1) * gap, h), (255, 255, 255))
for i, shot in enumerate(shots):
    sheet.paste(shot.resize((w, h), Image.LANCZOS), (i * (w + gap), 0))
sheet.save(target, optimize=True)
PY
  echo "wrote $out/record_$name.png"
}
strip orbit "0 10 20 30" --sweep theta=0:360 --seconds 3
strip construction2d "0 14 27 40" --view 2d --construction --seconds 4 --lang fr
strip construction3d "0 17 36 60" --construction --seconds 6
