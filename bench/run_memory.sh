#!/usr/bin/env bash
# Peak memory of one glBegin/glEnd of N lit vertices (default 10 million) on
# Mesa (llvmpipe) and on libglfixed. Usage, after building:
#   bench/run_memory.sh [build-dir] [vertices]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
n="${2:-10000000}"
exe="$build/bench/bench_long_begin_end"
echo "Mesa       $(env -u LD_LIBRARY_PATH "$exe" "$n")"
echo "libglfixed $(LD_LIBRARY_PATH="$build/dropin" "$exe" "$n")"
