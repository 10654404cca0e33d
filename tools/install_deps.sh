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
  # GLX (tests/platform/glx_test.cpp): an X server to draw on, and its 'fixed' font
  xvfb xfonts-base
)
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${packages[@]}"
