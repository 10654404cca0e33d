#!/usr/bin/env bash
# Installs what libglfixed needs to build and to compare with Mesa, from
# Debian 12's packages. Run as root (or it uses sudo).
set -euo pipefail
packages=(
  build-essential cmake pkg-config python3
  libglm-dev libgtest-dev libpng-dev
  libx11-dev libxext-dev            # GLX and EGL windows: Xlib and MIT-SHM
  libosmesa6-dev libglu1-mesa-dev libgl-dev  # Mesa's OSMesa and GL headers: the reference
  khronos-api                       # gl.xml, for tools/gen_gl_header.py
  # Real programs (tests/programs): an X server for ctest, Debian's glxgears,
  # glxinfo and eglinfo, freeglut, X11 and EGL headers, valgrind for the soaks.
  xvfb xauth mesa-utils freeglut3-dev libegl-dev valgrind
  # piglit (issue 13): piglit's test programs, run under a private X server by
  # tests/piglit/run_piglit.sh; xauth is for xvfb-run.
  piglit
  xfonts-base                       # GLX: the X server's 'fixed' font (glXUseXFont tests)
)
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${packages[@]}"
