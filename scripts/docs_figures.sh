#!/usr/bin/env bash
# Makes every example figure of docs/figures/ (README.md and docs/figures.md show them) with `raycam-cli
# figure`, from the scene files they name, as they are now. The one way these files are made: the test
# "docs: the figures in docs/figures/ are what scripts/docs_figures.sh makes now" runs this into a temporary
# folder and compares.
#   scripts/docs_figures.sh [RAYCAM_CLI] [--out DIR]   (default: build/raycam-cli, into docs/figures/)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cli="" out="$root/docs/figures"
while [ $# -gt 0 ]; do
  case "$1" in
    --out) [ $# -ge 2 ] || { echo "docs_figures.sh: --out needs a folder" >&2; exit 2; }; out=$2; shift 2 ;;
    -h|--help) sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "docs_figures.sh: unknown option '$1'" >&2; exit 2 ;;
    *) cli=$1; shift ;;
  esac
done
cli=${cli:-$root/build/raycam-cli}
[ -x "$cli" ] || { echo "docs_figures.sh: no raycam-cli at '$cli' (build it, or give its path)" >&2; exit 2; }
mkdir -p "$out"
frames=$(mktemp -d "${TMPDIR:-/tmp}/raycam-docs-figures.XXXXXX")
trap 'rm -rf "$frames"' EXIT

figure() { "$cli" figure "$@" >/dev/null; }
classic2d=$root/scenes/classic2d.json classic3d=$root/scenes/classic3d.json

# The files an instructor takes as they are: SVG frames at the default 160 × 120 mm, a PDF of pages, and the
# Beamer overlays at the size docs/figures.md gives for a slide.
figure --scene "$classic2d" --lang fr --out "$out/classic2d-fr.svg"
figure --scene "$classic3d" --lang fr --out "$out/classic3d-fr.svg"
figure --scene "$classic2d" --lang en --format pdf --pages --out "$out/classic2d-en.pdf"
figure --scene "$classic2d" --lang fr --format tikz --pages --size 105x72mm --out "$out/classic2d-fr-beamer.tex"

# The montages the docs show: each frame 100 × 75 mm at 120 dpi, (a) … (d) two to a row, steps 0 … 5 three.
for lang in fr en; do
  figure --scene "$classic2d" --lang "$lang" --format png --size 100x75mm --dpi 120 --out "$frames/2d-$lang.png"
  /usr/bin/python3 "$root/scripts/montage.py" --columns 2 "$out/classic2d-$lang.png" "$frames/2d-$lang"-[a-d].png
  figure --scene "$classic3d" --lang "$lang" --format png --size 100x75mm --dpi 120 --out "$frames/3d-$lang.png"
  /usr/bin/python3 "$root/scripts/montage.py" --columns 3 "$out/classic3d-$lang.png" "$frames/3d-$lang"-[0-5].png
done
echo "docs_figures.sh: wrote the figures into $out"
