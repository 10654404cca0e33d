#!/usr/bin/env bash
# Peak memory of one glDrawArrays of 10 million lit vertices
# (bench/array_memory.c) and of one glDrawElements of 10 million indices
# (bench/elements_memory.c), on Mesa (llvmpipe) and on libglfixed. Usage,
# after building:
#   bench/run_memory_bench.sh [build-dir] [vertices]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
n="${2:-10000000}"
exe="$build/bench/bench_array_memory"
echo "Mesa       $(env -u LD_LIBRARY_PATH "$exe" "$n")"
echo "libglfixed $(LD_LIBRARY_PATH="$build/dropin" "$exe" "$n")"
exe="$build/bench/bench_elements_memory"
echo "Mesa       $(env -u LD_LIBRARY_PATH "$exe" "$n")"
echo "libglfixed $(LD_LIBRARY_PATH="$build/dropin" "$exe" "$n")"
