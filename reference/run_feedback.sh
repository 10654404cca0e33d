#!/usr/bin/env bash
# run_feedback.sh - run selection/feedback programs on Mesa and on libglfixed
# and diff their text output exactly.
# (configured into the build directory by reference/CMakeLists.txt)
#
# usage: run_feedback.sh [program ...]      (default: every program)
#   --list    print the program names and exit
# environment:
#   GLFX_DROPIN_DIR   drop-in folder (default: configured, <build>/dropin)
#   GLFX_GLFIXED_ENV  extra VAR=value words for the drop-in runs only
#   GLFX_OUT_DIR      output folder (default: out-feedback/ next to this script)
#   GLFX_TIMEOUT      seconds per run (default 60)
# Each program prints its selection and feedback buffers as text (see
# feedback/fb_common.h); out-feedback/<program>/{mesa,glfixed}.txt keep them.
set -u

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin_dir="$here/@GLFX_REF_REL_FEEDBACK@"
dropin="${GLFX_DROPIN_DIR:-$here/@GLFX_REF_REL_DROPIN@}"
out_root="${GLFX_OUT_DIR:-$here/out-feedback}"
timeout_s="${GLFX_TIMEOUT:-60}"
all=(@GLFX_FEEDBACK_LIST@)

selected=()
for a in "$@"; do
    case "$a" in
        --list) printf '%s\n' "${all[@]}"; exit 0 ;;
        -*) echo "run_feedback.sh: unknown option $a" >&2; exit 2 ;;
        *) selected+=("${a#fb_}") ;;
    esac
done
[ ${#selected[@]} -eq 0 ] && selected=("${all[@]}")

if [ ! -e "$dropin/libOSMesa.so.8" ]; then
    echo "run_feedback.sh: no libOSMesa.so.8 in drop-in folder $dropin" >&2
    exit 2
fi
dropin="$(cd "$dropin" && pwd)"

failed=0
for name in "${selected[@]}"; do
    exe="$bin_dir/fb_$name"
    dir="$out_root/$name"
    mkdir -p "$dir"
    if [ ! -x "$exe" ]; then echo "FAIL $name: not built"; failed=$((failed + 1)); continue; fi
    resolved="$(LD_LIBRARY_PATH="$dropin" ldd "$exe" 2>/dev/null | awk '$1 == "libOSMesa.so.8" { print $3 }')"
    if [ -z "$resolved" ] || [ "$(readlink -f "$resolved")" != "$(readlink -f "$dropin/libOSMesa.so.8")" ]; then
        echo "FAIL $name: loader does not pick the drop-in libOSMesa.so.8 (got: ${resolved:-nothing})"
        failed=$((failed + 1)); continue
    fi
    env -u LD_LIBRARY_PATH timeout "$timeout_s" "$exe" >"$dir/mesa.txt" 2>"$dir/mesa.log"
    rc_m=$?
    # shellcheck disable=SC2086  # word splitting of the variable list is intended
    env LD_LIBRARY_PATH="$dropin" ${GLFX_GLFIXED_ENV:-} timeout "$timeout_s" "$exe" \
        >"$dir/glfixed.txt" 2>"$dir/glfixed.log"
    rc_g=$?
    if [ $rc_m -ne 0 ] || [ $rc_g -ne 0 ]; then
        echo "FAIL $name: exit status mesa $rc_m, glfixed $rc_g (see $dir/*.log)"
        failed=$((failed + 1)); continue
    fi
    if [ ! -s "$dir/mesa.txt" ]; then echo "FAIL $name: no output on Mesa"; failed=$((failed + 1)); continue; fi
    if diff -u "$dir/mesa.txt" "$dir/glfixed.txt" >"$dir/diff.txt"; then
        echo "PASS $name ($(wc -l <"$dir/mesa.txt") lines identical)"
    else
        echo "FAIL $name: outputs differ ($(grep -c '^[-+][^-+]' "$dir/diff.txt") lines; $dir/diff.txt):"
        head -40 "$dir/diff.txt"
        failed=$((failed + 1))
    fi
done
[ $failed -eq 0 ]
