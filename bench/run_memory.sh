#!/usr/bin/env bash
# Peak memory on Mesa (llvmpipe) and on libglfixed, in one run, of one
# glBegin/glEnd of N lit vertices (bench/long_begin_end.c), one glDrawArrays of
# N lit vertices (bench/array_memory.c) and one glDrawElements of N indices
# (bench/elements_memory.c); N defaults to 10 million. Usage, after building:
#   bench/run_memory.sh [build-dir] [N]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
n="${2:-10000000}"
for program in long_begin_end array_memory elements_memory; do
  exe="$build/bench/bench_$program"
  echo "Mesa       $(env -u LD_LIBRARY_PATH "$exe" "$n")"
  echo "libglfixed $(LD_LIBRARY_PATH="$build/dropin" "$exe" "$n")"
done
