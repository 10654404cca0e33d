#!/usr/bin/env bash
# run_scenes.sh - render reference scenes on Mesa and on libglfixed, compare.
# (configured into the build directory by reference/CMakeLists.txt)
#
# usage: run_scenes.sh [options] [scene...]      (default: every scene)
#   --self            compare Mesa against Mesa (harness self-test)
#   --no-fail         always exit 0 (used by the reference_report target)
#   --side-by-side    also write out/<scene>/side_by_side.png (mesa|glfixed|diff)
#   --scale N         upscale factor for side_by_side.png (default 1)
#   --list            print the scene names and exit
# environment:
#   GLFX_DROPIN_DIR   drop-in folder (default: configured, <build>/dropin)
#   GLFX_OTHER_ENV    e.g. "GALLIUM_DRIVER=softpipe": run the second side on
#                     Mesa with these variables instead of the drop-in
#                     (for testing the comparison itself)
#   GLFX_GLFIXED_ENV  extra VAR=value words for the drop-in runs only
#                     (e.g. "LD_PRELOAD=libasan.so.8" for a sanitizer build)
#   GLFX_OUT_DIR      output folder (default: out/ next to this script)
#   GLFX_TIMEOUT      seconds per scene run (default 60)
#   GLFX_RGB_RAW=1    do not work around llvmpipe's broken OSMESA_RGB output
#                     (see scenes/scene.h)
# Each scene run gets GLFX_SIDE=mesa or GLFX_SIDE=glfixed in its environment.
set -u

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
scene_dir="$here/@GLFX_REF_REL_SCENES@"
compare="$here/glfx_compare"
dropin="${GLFX_DROPIN_DIR:-$here/@GLFX_REF_REL_DROPIN@}"
out_root="${GLFX_OUT_DIR:-$here/out}"
timeout_s="${GLFX_TIMEOUT:-60}"
all_scenes=(@GLFX_REF_SCENE_LIST@)

other_env="${GLFX_OTHER_ENV:-}"
no_fail=0
sbs=0
scale=1
selected=()
while [ $# -gt 0 ]; do
    case "$1" in
        --self) other_env="GLFX_SELFTEST=1" ;;
        --no-fail) no_fail=1 ;;
        --side-by-side) sbs=1 ;;
        --scale) shift; scale="${1:-1}" ;;
        --list) printf '%s\n' "${all_scenes[@]}"; exit 0 ;;
        -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}"; exit 0 ;;
        -*) echo "run_scenes.sh: unknown option $1" >&2; exit 2 ;;
        *) selected+=("${1#scene_}") ;;
    esac
    shift
done
[ ${#selected[@]} -eq 0 ] && selected=("${all_scenes[@]}")

# Show paths relative to this script's folder where possible.
rel() { case "$1" in "$here"/*) echo "${1#"$here"/}" ;; *) echo "$1" ;; esac; }

describe_rc() {   # exit status -> words
    local rc=$1
    if [ "$rc" -eq 124 ]; then echo "timed out after ${timeout_s}s"
    elif [ "$rc" -gt 128 ]; then echo "crashed (signal $((rc - 128)))"
    else echo "exit status $rc"; fi
}

if [ ! -x "$compare" ]; then
    echo "run_scenes.sh: $(rel "$compare") is not built" >&2
    exit 2
fi

# Decide once how the second ("glfixed") side runs.
other_problem=""
if [ -n "$other_env" ]; then
    other_label="Mesa with $other_env"
else
    other_label="libglfixed drop-in ($(rel "$dropin"))"
    if [ ! -d "$dropin" ]; then
        other_problem="drop-in folder $(rel "$dropin") does not exist (build target glfixed_dropin or set GLFX_DROPIN_DIR)"
    elif [ ! -e "$dropin/libOSMesa.so.8" ]; then
        other_problem="no libOSMesa.so.8 in drop-in folder $(rel "$dropin")"
    else
        dropin="$(cd "$dropin" && pwd)"
    fi
fi

echo "# second side: $other_label"
"$compare" --header
passed=0
failed=0
fail_row() { "$compare" --error-row "$1" "$2"; failed=$((failed + 1)); }

for name in "${selected[@]}"; do
    exe="$scene_dir/scene_$name"
    dir="$out_root/$name"
    if [ ! -x "$exe" ]; then
        known=0
        for s in "${all_scenes[@]}"; do [ "$s" = "$name" ] && known=1; done
        if [ $known -eq 1 ]; then fail_row "$name" "scene executable not built"
        else fail_row "$name" "unknown scene"; fi
        continue
    fi
    mkdir -p "$dir"
    rm -f "$dir"/mesa.* "$dir"/glfixed.* "$dir"/diff*.png "$dir"/side_by_side.png

    env -u LD_LIBRARY_PATH GLFX_SIDE=mesa timeout "$timeout_s" "$exe" "$dir/mesa" \
        >"$dir/mesa.log" 2>&1
    rc=$?
    if [ $rc -ne 0 ]; then
        fail_row "$name" "Mesa run failed: $(describe_rc $rc) (see $(rel "$dir")/mesa.log)"
        continue
    fi

    if [ -n "$other_problem" ]; then
        fail_row "$name" "FAILED to run libglfixed: $other_problem"
        continue
    fi
    if [ -n "$other_env" ]; then
        # shellcheck disable=SC2086  # word splitting of the variable list is intended
        env -u LD_LIBRARY_PATH GLFX_SIDE=mesa $other_env timeout "$timeout_s" "$exe" "$dir/glfixed" \
            >"$dir/glfixed.log" 2>&1
        rc=$?
    else
        # Make sure the loader really picks the drop-in library.
        resolved="$(LD_LIBRARY_PATH="$dropin" ldd "$exe" 2>/dev/null |
                    awk '$1 == "libOSMesa.so.8" { print $3 }')"
        if [ -z "$resolved" ] || [ "$(readlink -f "$resolved")" != "$(readlink -f "$dropin/libOSMesa.so.8")" ]; then
            fail_row "$name" "loader does not pick $(rel "$dropin")/libOSMesa.so.8 (got: ${resolved:-nothing})"
            continue
        fi
        # shellcheck disable=SC2086
        env LD_LIBRARY_PATH="$dropin" GLFX_SIDE=glfixed ${GLFX_GLFIXED_ENV:-} \
            timeout "$timeout_s" "$exe" "$dir/glfixed" \
            >"$dir/glfixed.log" 2>&1
        rc=$?
    fi
    if [ $rc -ne 0 ]; then
        fail_row "$name" "glfixed run failed: $(describe_rc $rc) (see $(rel "$dir")/glfixed.log)"
        continue
    fi

    extra=()
    [ $sbs -eq 1 ] && extra=(--side-by-side "$dir/side_by_side.png" --scale "$scale")
    if "$compare" "${extra[@]}" "$name" "$dir/mesa" "$dir/glfixed" "$dir"; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
    fi
done

echo "$passed passed, $failed failed"
[ $no_fail -eq 1 ] && exit 0
[ $failed -eq 0 ]
