#!/bin/sh
# Debian's eglinfo (mesa-utils) on the drop-in: with no X server it must find
# the surfaceless platform and name libglfixed; under an Xvfb of its own
# (the first free display of :71-:75; skipped without Xvfb) the X11 platform
# too, with window configurations. It must never crash (eglinfo's exit code
# is the number of platforms whose eglInitialize failed).
# Usage: egl_eglinfo.sh <dropin-dir> <out-dir>
set -u
dropin=$1 out=$2
mkdir -p "$out"
command -v eglinfo > /dev/null || { echo "eglinfo is not installed (mesa-utils)"; exit 77; }
env -u DISPLAY LD_PRELOAD="${GLFX_DROPIN_PRELOAD:-}" LD_LIBRARY_PATH="$dropin" eglinfo > "$out/nodisplay.txt" 2>&1
rc=$?
cat "$out/nodisplay.txt"
[ $rc -eq 1 ] || { echo "eglinfo without a display: exit $rc, expected 1 (only X11 fails)"; exit 1; }
grep -q "EGL vendor string: libglfixed" "$out/nodisplay.txt" || { echo "libglfixed not named"; exit 1; }
grep -q "^0x01 24 .* pb$" "$out/nodisplay.txt" || { echo "no pbuffer configuration listed"; exit 1; }
command -v Xvfb > /dev/null || { echo "Xvfb missing: X11 part skipped"; exit 0; }
for n in 71 72 73 74 75; do
  [ -e /tmp/.X$n-lock ] && continue
  Xvfb :$n -screen 0 320x240x24 -nolisten tcp > "$out/xvfb.log" 2>&1 &
  xvfb=$!
  i=0
  while [ $i -lt 50 ] && ! [ -e /tmp/.X11-unix/X$n ]; do sleep 0.1; i=$((i + 1)); done
  if kill -0 $xvfb 2> /dev/null; then
    DISPLAY=:$n LD_PRELOAD="${GLFX_DROPIN_PRELOAD:-}" LD_LIBRARY_PATH="$dropin" eglinfo > "$out/x11.txt" 2>&1
    rc=$?
    kill $xvfb
    wait $xvfb 2> /dev/null
    cat "$out/x11.txt"
    [ $rc -eq 0 ] || { echo "eglinfo under Xvfb: exit $rc, expected 0"; exit 1; }
    [ "$(grep -c 'EGL vendor string: libglfixed' "$out/x11.txt")" -eq 2 ] || { echo "not two libglfixed platforms"; exit 1; }
    grep -q "TC .* win,pb,pix$" "$out/x11.txt" || { echo "no window configuration on X11"; exit 1; }
    exit 0
  fi
done
echo "no Xvfb could start on :71-:75"
exit 1
