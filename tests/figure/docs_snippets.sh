#!/bin/sh
# docs/figures.md's LaTeX snippets, compiled as written: each ```latex block that \input's a figure, with the
# raycam-cli command its comment gives, in a document of its kind (a figure: an A4 article at 11 pt; a frame:
# Beamer) after the preamble block the page lists. A snippet that fails to compile or whose picture is wider
# than the text (an "Overfull \hbox": the figure runs into the margin or off the slide) fails the test.
# Usage: docs_snippets.sh RAYCAM_CLI DOCS_FIGURES_MD SCENE_2D
set -eu
cli=$1
doc=$2
scene=$3
work=$(mktemp -d "${TMPDIR:-/tmp}/raycam-docs-snippets.XXXXXX")
trap 'rm -rf "$work"' EXIT

# The fenced ```latex blocks, one file each: block-1.tex, block-2.tex, …
awk -v dir="$work" '
  /^```latex$/ { n++; inside = 1; next }
  /^```$/ && inside { inside = 0; close(file); next }
  inside { file = dir "/block-" n ".tex"; print > file }
' "$doc"
[ -f "$work/block-1.tex" ] || { echo "docs_snippets: no \`\`\`latex block in $doc"; exit 1; }
grep -q '\\usepackage{tikz}' "$work/block-1.tex" || { echo "docs_snippets: the first block is not the preamble"; exit 1; }

snippets=0
for block in "$work"/block-*.tex; do
  line=$(grep -E '\\input\{[^}]*\}[[:space:]]*% raycam-cli figure ' "$block" || true)
  [ -n "$line" ] || continue
  snippets=$((snippets + 1))
  # The command as the comment gives it; "…" stands for the demo scene (with --scene) or the scene and language.
  args=$(printf '%s\n' "$line" | sed -e 's/.*% raycam-cli figure //' \
           -e "s|--scene …|--scene $scene|" -e "s|^… |--scene $scene --lang fr |")
  # shellcheck disable=SC2086  # the flags split as the shell splits them when pasted
  (cd "$work" && "$cli" figure $args > /dev/null)
  if grep -q '\\begin{frame}' "$block"; then class='beamer'; else class='[a4paper,11pt]{article}'; fi
  case $class in \[*) header="\\documentclass$class" ;; *) header="\\documentclass{$class}" ;; esac
  name=snippet-$snippets
  { printf '%s\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}\n' "$header"
    cat "$work/block-1.tex"
    printf '\\begin{document}\n'
    cat "$block"
    printf '\\end{document}\n'; } > "$work/$name.tex"
  if ! (cd "$work" && pdflatex -interaction=nonstopmode -halt-on-error "$name.tex" > /dev/null 2>&1); then
    echo "docs_snippets: snippet $snippets ($class) does not compile:"; grep -A3 '^!' "$work/$name.log" | head -8
    exit 1
  fi
  if grep -q 'Overfull \\hbox' "$work/$name.log"; then
    echo "docs_snippets: snippet $snippets ($class, figure $args): wider than the text:"
    grep 'Overfull \\hbox' "$work/$name.log" | head -2
    exit 1
  fi
  echo "snippet $snippets ($class): compiles, fits the text width"
done
[ "$snippets" -ge 2 ] || { echo "docs_snippets: expected the notes and the slide snippets, found $snippets"; exit 1; }
echo "docs_snippets: $snippets snippets compile as written"
