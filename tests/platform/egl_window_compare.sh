#!/bin/sh
# Runs the EGL window probe under an Xvfb of its own (the first free display
# of :71-:75) on Mesa and on libglfixed, and compares the two windows, read
# back with XGetImage, within the fidelity bar; the drop-in run draws 400
# frames first and must not grow in memory. Exit 77 (skipped) without Xvfb.
# Usage: egl_window_compare.sh <window-probe> <compare-probe> <dropin-dir> <out-dir>
set -u
probe=$1 compare=$2 dropin=$3 out=$4
mkdir -p "$out"
command -v Xvfb > /dev/null || { echo "Xvfb is not installed"; exit 77; }
for n in 71 72 73 74 75; do
  [ -e /tmp/.X$n-lock ] && continue
  Xvfb :$n -screen 0 320x240x24 -nolisten tcp > "$out/xvfb.log" 2>&1 &
  xvfb=$!
  i=0
  while [ $i -lt 50 ] && ! [ -e /tmp/.X11-unix/X$n ]; do sleep 0.1; i=$((i + 1)); done
  kill -0 $xvfb 2> /dev/null || continue
  env -u LD_LIBRARY_PATH DISPLAY=:$n "$probe" "$out/mesa.rgba" > "$out/mesa.log" 2>&1
  mesa=$?
  env DISPLAY=:$n LD_PRELOAD="${GLFX_DROPIN_PRELOAD:-}" LD_LIBRARY_PATH="$dropin" "$probe" "$out/glfixed.rgba" \
    smooth 400 > "$out/glfixed.log" 2>&1
  glfixed=$?
  kill $xvfb
  wait $xvfb 2> /dev/null
  echo "--- Mesa (exit $mesa)"; cat "$out/mesa.log"
  echo "--- libglfixed (exit $glfixed)"; cat "$out/glfixed.log"
  [ $mesa -eq 0 ] && [ $glfixed -eq 0 ] || exit 1
  grep -q "renderer llvmpipe" "$out/mesa.log" || { echo "the Mesa run is not llvmpipe"; exit 1; }
  grep -q "vendor libglfixed" "$out/glfixed.log" || { echo "the drop-in run is not libglfixed"; exit 1; }
  # 400 frames on the drop-in first: its memory must not grow with them.
  growth=$(sed -n 's/^rss growth \(-*[0-9]*\) KiB.*/\1/p' "$out/glfixed.log")
  # GLFX_RSS_SLACK_KIB: a sanitizer build's quarantine keeps freed memory resident.
  [ -n "$growth" ] && [ "$growth" -le "${GLFX_RSS_SLACK_KIB:-512}" ] || { echo "resident memory grew by ${growth:-?} KiB"; exit 1; }
  exec "$compare" --compare "$out/mesa.rgba" "$out/glfixed.rgba"
done
echo "no Xvfb could start on :71-:75"
exit 1
