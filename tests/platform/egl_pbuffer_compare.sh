#!/bin/sh
# Runs the EGL pbuffer probe with no X server on Mesa (the system's libEGL and
# libGL) and on libglfixed (the drop-in folder first on LD_LIBRARY_PATH), and
# compares the two pictures within the fidelity bar.
# Usage: egl_pbuffer_compare.sh <probe> <dropin-dir> <out-dir>
set -u
probe=$1 dropin=$2 out=$3
mkdir -p "$out"
env -u DISPLAY -u LD_LIBRARY_PATH "$probe" "$out/mesa.rgba" > "$out/mesa.log" 2>&1 || {
  echo "the probe failed on Mesa:"; cat "$out/mesa.log"; exit 1; }
env -u DISPLAY LD_PRELOAD="${GLFX_DROPIN_PRELOAD:-}" LD_LIBRARY_PATH="$dropin" "$probe" "$out/glfixed.rgba" > "$out/glfixed.log" 2>&1 || {
  echo "the probe failed on libglfixed:"; cat "$out/glfixed.log"; exit 1; }
grep -q "renderer llvmpipe" "$out/mesa.log" || { echo "the Mesa run is not llvmpipe"; cat "$out/mesa.log"; exit 1; }
grep -q "renderer libglfixed" "$out/glfixed.log" || { echo "the drop-in run is not libglfixed"; cat "$out/glfixed.log"; exit 1; }
echo "--- Mesa"; cat "$out/mesa.log"
echo "--- libglfixed"; cat "$out/glfixed.log"
"$probe" --compare "$out/mesa.rgba" "$out/glfixed.rgba"
