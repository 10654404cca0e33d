#!/usr/bin/env bash
# Side-by-side speed of one legacy program on Mesa (llvmpipe) and on
# libglfixed, in one run: ms per frame and the ratio. Usage, after building:
#   bench/run_bench.sh [build-dir] [frames]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
frames="${2:-20}"
exe="$build/bench/bench_lit_spheres"
declare -A ms
# texfill: the fill quads under a trilinear (GL_LINEAR_MIPMAP_LINEAR) texture
# (issue 14). blendfill: the fill quads blended (SRC_ALPHA, ONE_MINUS_SRC_ALPHA).
# fogfill: the fill quads in GL_EXP2 fog (a fog factor per pixel).
# upload: a 1024x1024 RGBA glTexImage2D each frame, drawn on a small quad.
for what in geometry list vbo fill texfill blendfill fogfill upload; do
  mesa=$(env -u LD_LIBRARY_PATH "$exe" "$frames" "$what")
  ours=$(LD_LIBRARY_PATH="$build/dropin" "$exe" "$frames" "$what")
  echo "Mesa       $mesa"
  echo "libglfixed $ours"
  m=$(sed -E 's/.* ([0-9.]+) ms\/frame/\1/' <<<"$mesa")
  o=$(sed -E 's/.* ([0-9.]+) ms\/frame/\1/' <<<"$ours")
  ms[mesa_$what]=$m
  ms[ours_$what]=$o
  awk -v m="$m" -v o="$o" -v w="$what" 'BEGIN { printf "%s: libglfixed is %.2fx the speed of Mesa\n\n", w, m / o }'
done
# The display list replay of the geometry against the same immediate-mode calls.
awk -v i="${ms[ours_geometry]}" -v l="${ms[ours_list]}" -v mi="${ms[mesa_geometry]}" -v ml="${ms[mesa_list]}" \
  'BEGIN { printf "list replay vs immediate mode: libglfixed %.2fx, Mesa %.2fx (speed)\n", i / l, mi / ml }'
# The buffer-object draws of the same vertices against immediate mode.
awk -v i="${ms[ours_geometry]}" -v b="${ms[ours_vbo]}" -v mi="${ms[mesa_geometry]}" -v mb="${ms[mesa_vbo]}" \
  'BEGIN { printf "buffer-object draws vs immediate mode: libglfixed %.2fx, Mesa %.2fx (speed)\n\n", i / b, mi / mb }'
# Whole-process start-up: load, context, one frame, exit.
start() { local t0 t1; t0=$(date +%s%N); "$@" >/dev/null; t1=$(date +%s%N); echo $(( (t1 - t0) / 1000000 )); }
m=$(start env -u LD_LIBRARY_PATH "$exe" 1 geometry)
o=$(start env LD_LIBRARY_PATH="$build/dropin" "$exe" 1 geometry)
echo "whole process, one frame: Mesa ${m} ms, libglfixed ${o} ms"
