#!/usr/bin/env bash
# Installs raycam's build and test dependencies from Debian 12's packages (as root, or through sudo).
set -euo pipefail
packages=(
  cmake g++ pkg-config                       # toolchain (named explicitly: a fresh machine may lack them)
  libglm-dev nlohmann-json3-dev libstb-dev   # core: math, scene files, PNG output
  catch2                                     # tests
  libglfw3-dev libimgui-dev libosmesa6-dev   # app (GLFW + Dear ImGui) and headless renderer (OSMesa)
  libfontconfig-dev fonts-dejavu-core        # the TrueType font with accents, rasterised at the lecture size
  xvfb xauth mesa-utils xdotool              # the real window under a virtual X server, driven by xdotool, in tests
  libembree-dev libbenchmark-dev gnuplot-nox # speed reference, benchmarks, plots
  libcli11-dev                               # command lines
  libavcodec-dev libavformat-dev libswscale-dev  # `record`: MP4 (libx264), WebM (VP9), GIF through FFmpeg's libraries
  libcairo2-dev libpng-dev poppler-utils     # course figures (SVG, PDF, PNG) and their tests (pdftotext)
  texlive-latex-base texlive-latex-extra texlive-pictures texlive-lang-french lmodern  # TikZ figures' tests: pdflatex, standalone and Beamer, TikZ, babel French, Latin Modern
  bubblewrap libseccomp-dev keyutils python3 # `check`: sandbox, its system-call filter, the Python example student
  parallel                                   # `check`: the large course recipe's test (GNU parallel, 3 shards)
  qemu-user                                  # tests: the vector loops' SSE2 and AVX2 copies (tests/core)
  clang-14 libclang-rt-14-dev                # fuzzing and sanitizers
  emscripten chromium chromium-driver python3-selenium python3-pil  # the web page (scripts/web.sh) and its browser tests (PIL reads its screenshots); the docs' montages (scripts/montage.py)
)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "ok installed" || missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${packages[@]}" >/dev/null
fi
