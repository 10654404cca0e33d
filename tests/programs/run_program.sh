#!/usr/bin/env bash
# run_program.sh - runs real programs under an Xvfb of its own, on Mesa and on
# libglfixed's drop-in folder, and checks them (issue 13, real programs).
# (configured into the build directory by tests/programs/CMakeLists.txt)
#
# usage: run_program.sh [--on-mesa] TEST [PROGRAM]
#   compare PROGRAM   runs PROGRAM (glut_lit_scene, egl_window_scene,
#                     egl_pbuffer_scene) in each of its variants on Mesa and
#                     on libglfixed and compares the pictures with
#                     glfx_compare (0 coverage mismatches, >= 99.99% of the
#                     covered pixels identical, no channel off by more than 1)
#   mesa              every program and variant on Mesa only: each draws (some
#                     pixels but not all are covered), the variants of a
#                     program draw the same picture, and the picture of another
#                     frame fails the comparison (so it can fail)
#   glxgears          glxgears -info for GLFX_GEARS_SECONDS (default 12): it
#                     names libglfixed as GL_RENDERER, is still running at the
#                     end and printed "N frames in 5.0 seconds" lines, N > 0
#   symbols           every gl/glX/egl name the programs, libglut and the
#                     mesa-utils tools import is defined in the drop-in (all
#                     missing names at once; libglut is linked BIND_NOW)
#   glxinfo           exits 0, "OpenGL renderer string" names libglfixed
#   eglinfo           an "EGL vendor string" names libglfixed (with DISPLAY);
#                     it does not crash, with DISPLAY and without one
#   soak PROGRAM      GLFX_SOAK_FRAMES (default 600) frames of PROGRAM with
#                     --rss: the peak RSS (VmHWM) after the last frame is at
#                     most GLFX_SOAK_SLACK_KB (default 1024) above the peak
#                     after frame 100
#   valgrind PROGRAM  GLFX_VALGRIND_FRAMES (default 3) frames of PROGRAM under
#                     valgrind's memcheck: an error or a definitely lost block
#                     fails (valgrind.supp: a false positive inside ld.so)
#   --on-mesa         run the libglfixed side on Mesa instead, expecting
#                     Mesa's names (checks the harness before GLX/EGL land)
# environment:
#   GLFX_DROPIN_DIR     drop-in folder (default: configured, <build>/dropin)
#   GLFX_OUT_DIR        output folder (default: out/ next to this script)
#   GLFX_TIMEOUT        seconds per program run (default 60)
#   GLFX_XVFB_DISPLAYS  display numbers to try for Xvfb (default 100 to 199)
#   GLFX_GLFIXED_ENV    extra VAR=value words for the libglfixed runs only
#   GLFX_VALGRIND_OPTS  extra valgrind options (e.g. --suppressions=FILE)
# Exit status: 0 pass, 1 fail, 2 usage, 77 skipped (Xvfb, the program or
# valgrind is not installed).
set -u

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="$here/@GLFX_PROG_REL_BIN@"
compare="$here/@GLFX_PROG_COMPARE@"
dropin="${GLFX_DROPIN_DIR:-$here/@GLFX_PROG_REL_DROPIN@}"
out_root="${GLFX_OUT_DIR:-$here/out}"
timeout_s="${GLFX_TIMEOUT:-60}"
SKIP=77
unset DISPLAY   # only the Xvfb started here is used
[ -d "$dropin" ] && dropin="$(cd "$dropin" && pwd)"

on_mesa=0
while [ $# -gt 0 ]; do
    case "$1" in
        --on-mesa) on_mesa=1 ;;
        -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "${BASH_SOURCE[0]}"; exit 0 ;;
        -*) echo "run_program.sh: unknown option $1" >&2; exit 2 ;;
        *) break ;;
    esac
    shift
done
test_name="${1:-}"
program="${2:-}"
[ -n "$test_name" ] || { echo "usage: run_program.sh [--on-mesa] TEST [PROGRAM] (--help)" >&2; exit 2; }

# What the second side must call itself.
if [ $on_mesa -eq 1 ]; then
    side2=mesa2; side2_label="Mesa (--on-mesa)"; expect_gl="llvmpipe"; expect_egl="Mesa"
else
    side2=glfixed; side2_label="libglfixed ($dropin)"; expect_gl="libglfixed"; expect_egl="libglfixed"
fi

rel() { case "$1" in "$here"/*) echo "${1#"$here"/}" ;; *) echo "$1" ;; esac; }
describe_rc() {
    local rc=$1
    if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then echo "timed out after ${timeout_s}s"
    elif [ "$rc" -gt 128 ]; then echo "crashed (signal $((rc - 128)))"
    else echo "exit status $rc"; fi
}
row() { printf '%-36s %-4s  %s\n' "$1" "$2" "$3"; }   # name, PASS/FAIL/SKIP, notes

# ---- Xvfb of our own ---------------------------------------------------------
xvfb_pid=""
stop_xvfb() {
    if [ -n "$xvfb_pid" ]; then
        kill "$xvfb_pid" 2>/dev/null
        wait "$xvfb_pid" 2>/dev/null
        xvfb_pid=""
    fi
}
trap stop_xvfb EXIT
trap 'stop_xvfb; exit 1' INT TERM

# Starts Xvfb on the first free display of GLFX_XVFB_DISPLAYS and exports
# DISPLAY; -displayfd tells when the server accepts connections.
start_xvfb() {
    command -v Xvfb >/dev/null 2>&1 || return 1
    local n ready_file="$work/xvfb.displayfd" _
    for n in ${GLFX_XVFB_DISPLAYS:-$(seq 100 199)}; do
        [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ] && continue
        : >"$ready_file"
        Xvfb ":$n" -screen 0 1024x768x24 -nolisten tcp -noreset -displayfd 3 \
            3>"$ready_file" >"$work/xvfb.log" 2>&1 &
        xvfb_pid=$!
        for _ in $(seq 1 100); do
            [ -s "$ready_file" ] && break
            kill -0 "$xvfb_pid" 2>/dev/null || break
            sleep 0.1
        done
        if [ -s "$ready_file" ] && kill -0 "$xvfb_pid" 2>/dev/null; then
            export DISPLAY=":$n"
            return 0
        fi
        stop_xvfb
    done
    return 1
}

# ---- running one side ----------------------------------------------------------
# run_side SIDE NODISPLAY LOG CMD ARGS...: runs CMD with the side's libraries
# (mesa / mesa2: the system's, glfixed: the drop-in folder), with a timeout,
# DISPLAY unset when NODISPLAY is 1; extra VAR=value words in run_env.
run_env=()
run_side() {
    local side=$1 nodisplay=$2 log=$3
    shift 3
    local pre=(env)
    [ "$nodisplay" -eq 1 ] && pre+=(-u DISPLAY)
    if [ "$side" = glfixed ]; then
        # shellcheck disable=SC2206  # word splitting of the variable list is intended
        pre+=(LD_LIBRARY_PATH="$dropin" ${GLFX_GLFIXED_ENV:-})
    else
        pre+=(-u LD_LIBRARY_PATH)
    fi
    "${pre[@]}" "${run_env[@]}" timeout -k 5 "$run_timeout" "$@" >"$log" 2>&1
}
run_timeout=$timeout_s

# The loader must take LIB (libGL.so.1, libEGL.so.1) from the drop-in folder.
check_loader() {   # EXE LIB -> empty, or the reason it does not
    local exe=$1 lib=$2 resolved
    [ "$side2" = glfixed ] || return 0
    if [ ! -e "$dropin/$lib" ]; then
        echo "no $lib in the drop-in folder $dropin (GLX/EGL not built into it yet?)"
        return 0
    fi
    resolved="$(LD_LIBRARY_PATH="$dropin" ldd "$exe" 2>/dev/null | awk -v l="$lib" '$1 == l { print $3 }')"
    # libGL.so.1 and libEGL.so.1 are one file in the drop-in: the loader
    # loads it once and ldd lists it under the first name it met.
    if [ -z "$resolved" ]; then
        local other
        for other in $(LD_LIBRARY_PATH="$dropin" ldd "$exe" 2>/dev/null | awk '$2 == "=>" { print $3 }'); do
            [ "$(readlink -f "$other")" = "$(readlink -f "$dropin/$lib")" ] && resolved=$other
        done
    fi
    if [ -z "$resolved" ] || [ "$(readlink -f "$resolved")" != "$(readlink -f "$dropin/$lib")" ]; then
        echo "the loader does not take $lib from $dropin (got: ${resolved:-nothing})"
    fi
}
loader_problem() {   # EXE -> reason or empty, for the libraries EXE links
    local exe=$1 lib p
    for lib in libGL.so.1 libEGL.so.1; do
        ldd "$exe" 2>/dev/null | awk '{ print $1 }' | grep -qx "$lib" || continue
        p="$(check_loader "$exe" "$lib")"
        [ -n "$p" ] && { echo "$p"; return; }
    done
}

renderer_of() { sed -n 's/^GL_RENDERER: //p' "$1" | head -n 1; }
# renderer_problem SIDE LOG: the renderer must be the side's.
renderer_problem() {
    local side=$1 log=$2 r
    r="$(renderer_of "$log")"
    if [ -z "$r" ]; then echo "printed no GL_RENDERER"
    elif [ "$side" = mesa ] && [[ "$r" == *libglfixed* ]]; then echo "the Mesa run drew with libglfixed"
    elif [ "$side" != mesa ] && [[ "$r" != *"$expect_gl"* ]]; then
        echo "drew with \"$r\", not $expect_gl"
    fi
}
covered_of() { sed -n 's/^covered pixels: \([0-9]*\) of \([0-9]*\)$/\1 \2/p' "$1" | head -n 1; }

# ---- the programs and their variants ----------------------------------------------
# variants PROGRAM: the names; set_variant PROGRAM VARIANT sets v_args
# (arguments after the frame count), v_env (VAR=value), v_nodisplay (run with
# DISPLAY unset), v_picture (0: writes no picture, checks only) and v_own (1:
# a picture of its own, not the one the program's other variants draw).
variants() {
    case "$1" in
        glut_lit_scene) echo "window resized" ;;
        egl_window_scene) echo "platform get_display resized" ;;
        egl_pbuffer_scene) echo "surfaceless default_display default_display_x11 no_surface" ;;
        *) return 1 ;;
    esac
}
set_variant() {
    v_args=(); v_env=(); v_nodisplay=0; v_picture=1; v_own=0
    case "$1/$2" in
        glut_lit_scene/window) ;;
        glut_lit_scene/resized) v_args=(--resize); v_own=1 ;;   # 320x240, then 256x200 at half the frames
        egl_window_scene/platform) ;;   # eglGetPlatformDisplay + eglCreatePlatformWindowSurface
        egl_window_scene/get_display) v_args=(--get-display --window-surface) ;;
        egl_window_scene/resized) v_args=(--resize); v_own=1 ;;   # XResizeWindow to 256x200 at half the frames
        egl_pbuffer_scene/surfaceless) v_nodisplay=1 ;;
        # Mesa's eglGetDisplay(EGL_DEFAULT_DISPLAY) is its X11 platform, which
        # fails with no DISPLAY unless EGL_PLATFORM names another one.
        egl_pbuffer_scene/default_display) v_args=(--default-display); v_nodisplay=1; v_env=(EGL_PLATFORM=surfaceless) ;;
        egl_pbuffer_scene/default_display_x11) v_args=(--default-display) ;;
        egl_pbuffer_scene/no_surface) v_args=(--no-surface); v_nodisplay=1; v_picture=0 ;;
        *) return 1 ;;
    esac
}
program_exe() {
    local exe="$bin/$1"
    if ! variants "$1" >/dev/null; then echo "run_program.sh: unknown program '$1'" >&2; exit 2; fi
    if [ ! -x "$exe" ]; then echo "run_program.sh: $(rel "$exe") is not built" >&2; exit 2; fi
    echo "$exe"
}

# run_variant SIDE PROGRAM VARIANT PREFIX FRAMES [EXTRA ARGS]: runs one
# variant on one side; prints nothing and returns 0 when it ran and drew with
# the side's renderer, else prints the reason.
run_variant() {
    local side=$1 prog=$2 variant=$3 prefix=$4 frames=$5 exe rc p
    shift 5
    exe="$bin/$prog"
    set_variant "$prog" "$variant"
    if [ "$v_nodisplay" -eq 0 ] && [ -z "${DISPLAY:-}" ]; then echo "SKIP: no X server"; return 1; fi
    run_env=("${v_env[@]}")
    rm -f "$prefix.glfx"
    run_side "$side" "$v_nodisplay" "$prefix.log" "$exe" "$prefix" "$frames" "${v_args[@]}" "$@"
    rc=$?
    run_env=()
    if [ $rc -ne 0 ]; then
        echo "$side run: $(describe_rc $rc): $(grep -v '^\(GL_\|EGL_\)' "$prefix.log" | tail -n 2 | tr '\n' ' ')(see $(rel "$prefix.log"))"
        return 1
    fi
    p="$(renderer_problem "$side" "$prefix.log")"
    [ -n "$p" ] && { echo "$side run: $p (see $(rel "$prefix.log"))"; return 1; }
    if [ "$v_picture" -eq 1 ] && [ ! -s "$prefix.glfx" ]; then
        echo "$side run: wrote no picture (see $(rel "$prefix.log"))"
        return 1
    fi
    return 0
}

work=""
make_out() {   # make_out NAME: a fresh output folder
    work="$out_root/$1"
    rm -rf "$work"
    mkdir -p "$work"
}

failed=0
skipped=0
ran=0
fail() { row "$1" FAIL "$2"; failed=$((failed + 1)); ran=$((ran + 1)); }
pass() { row "$1" PASS "$2"; ran=$((ran + 1)); }
skip() { row "$1" SKIP "$2"; skipped=$((skipped + 1)); }
finish() {
    if [ $failed -gt 0 ]; then exit 1; fi
    if [ $ran -eq 0 ] && [ $skipped -gt 0 ]; then exit $SKIP; fi
    exit 0
}

# ---- the tests -----------------------------------------------------------------
test_compare() {
    local prog=$1 exe variant dir p
    exe="$(program_exe "$prog")" || exit 2
    make_out "compare_$prog"
    start_xvfb || echo "# no Xvfb: the variants that need an X server are skipped"
    p="$(loader_problem "$exe")"
    echo "# $prog: Mesa against $side2_label, display ${DISPLAY:-none}"
    "$compare" --header
    for variant in $(variants "$prog"); do
        dir="$work/$variant"
        mkdir -p "$dir"
        set_variant "$prog" "$variant"   # (run_variant runs in a subshell)
        if [ -n "$p" ]; then "$compare" --error-row "$prog/$variant" "$p"; failed=$((failed + 1)); continue; fi
        local m g
        m="$(run_variant mesa "$prog" "$variant" "$dir/mesa" 10)"
        if [ -n "$m" ]; then
            if [[ "$m" == SKIP:* ]]; then skip "$prog/$variant" "${m#SKIP: }"; continue; fi
            "$compare" --error-row "$prog/$variant" "$m"; failed=$((failed + 1)); continue
        fi
        g="$(run_variant "$side2" "$prog" "$variant" "$dir/glfixed" 10)"
        if [ -n "$g" ]; then "$compare" --error-row "$prog/$variant" "$g"; failed=$((failed + 1)); continue; fi
        ran=$((ran + 1))
        if [ "$v_picture" -eq 0 ]; then
            row "$prog/$variant" PASS "ran on both: $(renderer_of "$dir/glfixed.log")"
            continue
        fi
        "$compare" "$prog/$variant" "$dir/mesa" "$dir/glfixed" "$dir" || failed=$((failed + 1))
    done
    finish
}

# Mesa only: each program draws, its variants agree, another frame differs.
test_mesa() {
    local prog variant dir first m n total
    make_out mesa
    start_xvfb || echo "# no Xvfb: the variants that need an X server are skipped"
    echo "# Mesa only, display ${DISPLAY:-none}"
    for prog in glut_lit_scene egl_window_scene egl_pbuffer_scene; do
        program_exe "$prog" >/dev/null || exit 2
        first=""
        for variant in $(variants "$prog"); do
            dir="$work/$prog/$variant"
            mkdir -p "$dir"
            set_variant "$prog" "$variant"   # (run_variant runs in a subshell)
            m="$(run_variant mesa "$prog" "$variant" "$dir/mesa" 10)"
            if [ -n "$m" ]; then
                if [[ "$m" == SKIP:* ]]; then skip "$prog/$variant" "${m#SKIP: }"; else fail "$prog/$variant" "$m"; fi
                continue
            fi
            if [ "$v_picture" -eq 0 ]; then pass "$prog/$variant" "context works: $(renderer_of "$dir/mesa.log")"; continue; fi
            read -r n total <<<"$(covered_of "$dir/mesa.log")"
            if [ -z "${n:-}" ] || [ "$n" -eq 0 ] || [ "$n" -ge "$total" ]; then
                fail "$prog/$variant" "covered ${n:-?} of ${total:-?} pixels: drew nothing, or everything"
                continue
            fi
            if [ -z "$first" ] || [ "$v_own" -eq 1 ]; then
                [ "$v_own" -eq 1 ] || first="$dir"
                # The picture one frame later must fail the comparison.
                m="$(run_variant mesa "$prog" "$variant" "$dir/later" 11)"
                if [ -n "$m" ]; then fail "$prog/$variant" "frame 11: $m"; continue; fi
                if "$compare" "$prog/$variant/frame11" "$dir/mesa" "$dir/later" "$dir" >"$dir/later.row"; then
                    fail "$prog/$variant" "frame 11 compares equal to frame 10: the comparison cannot fail"
                    continue
                fi
                pass "$prog/$variant" "covered $n of $total; frame 11 fails: $(awk '{ print "cov_mism " $3 ", worse " $7 ", max " $8 }' "$dir/later.row")"
            else
                # A variant draws what the first variant draws.
                if "$compare" "$prog/$variant" "$first/mesa" "$dir/mesa" "$dir" >"$dir/row"; then
                    pass "$prog/$variant" "covered $n of $total; same picture as $(basename "$first")"
                else
                    fail "$prog/$variant" "differs from $(basename "$first"): $(cat "$dir/row")"
                fi
            fi
        done
    done
    # The soak check passes 300 frames of the pbuffer program and catches
    # the same program keeping 16 kB more each frame.
    local dir="$work/soak_check"
    mkdir -p "$dir"
    set_variant egl_pbuffer_scene surfaceless
    m="$(run_variant mesa egl_pbuffer_scene surfaceless "$dir/clean" 300 --rss)"
    if [ -n "$m" ]; then fail soak_check "$m"; finish; fi
    m="$(run_variant mesa egl_pbuffer_scene surfaceless "$dir/leaking" 300 --rss --leak-kb 16)"
    if [ -n "$m" ]; then fail soak_check "--leak-kb 16: $m"; finish; fi
    local clean leaking
    if ! clean="$(soak_verdict "$dir/clean.log" 300 "${GLFX_SOAK_SLACK_KB:-1024}")"; then
        fail soak_check "300 clean frames: $clean"
    elif leaking="$(soak_verdict "$dir/leaking.log" 300 "${GLFX_SOAK_SLACK_KB:-1024}")"; then
        fail soak_check "16 kB kept each frame passes the soak check: $leaking"
    else
        pass soak_check "clean: $clean; leaking 16 kB a frame fails: ${leaking%% (*}"
    fi
    finish
}

# mesa_utils_setup NAME TOOL LIB: output folder, Xvfb, the tool and its library.
mesa_utils_setup() {
    make_out "$1"
    tool="$(command -v "$2" 2>/dev/null)"
    if [ -z "$tool" ]; then row "$1" SKIP "$2 is not installed (Debian's mesa-utils)"; exit $SKIP; fi
    if ! start_xvfb; then row "$1" SKIP "Xvfb is not installed or did not start (Debian's xvfb)"; exit $SKIP; fi
    local p
    p="$(check_loader "$tool" "$3")"
    if [ -n "$p" ]; then fail "$1" "$p"; finish; fi
}

test_glxgears() {
    local seconds="${GLFX_GEARS_SECONDS:-12}" rc lines bad r
    mesa_utils_setup glxgears glxgears libGL.so.1
    run_timeout=$seconds
    run_side "$side2" 0 "$work/glxgears.log" "$tool" -info
    rc=$?
    run_timeout=$timeout_s
    r="$(sed -n 's/^GL_RENDERER *= *//p' "$work/glxgears.log" | head -n 1)"
    lines="$(grep -c ' frames in [0-9.]* seconds' "$work/glxgears.log")"
    bad="$(grep ' frames in [0-9.]* seconds' "$work/glxgears.log" | awk '$1 + 0 <= 0' | head -n 1)"
    local log; log="see $(rel "$work/glxgears.log")"
    if [ $rc -ne 124 ]; then
        fail glxgears "it did not keep running for ${seconds}s: $(describe_rc $rc): $(tail -n 1 "$work/glxgears.log") ($log)"
    elif [[ "$r" != *"$expect_gl"* ]]; then fail glxgears "GL_RENDERER is \"$r\", not $expect_gl ($log)"
    elif [ "$lines" -lt 2 ]; then fail glxgears "$lines \"frames in\" lines in ${seconds}s, not 2 or more ($log)"
    elif [ -n "$bad" ]; then fail glxgears "it stopped drawing: \"$bad\" ($log)"
    else pass glxgears "$r; $(grep ' frames in ' "$work/glxgears.log" | tail -n 1)"; fi
    finish
}

test_glxinfo() {
    local rc r
    mesa_utils_setup glxinfo glxinfo libGL.so.1
    run_side "$side2" 0 "$work/glxinfo.log" "$tool"
    rc=$?
    r="$(sed -n 's/^OpenGL renderer string: //p' "$work/glxinfo.log" | head -n 1)"
    if [ $rc -ne 0 ]; then fail glxinfo "$(describe_rc $rc): $(tail -n 1 "$work/glxinfo.log") (see $(rel "$work/glxinfo.log"))"
    elif [[ "$r" != *"$expect_gl"* ]]; then fail glxinfo "OpenGL renderer string is \"$r\", not $expect_gl"
    else pass glxinfo "$r; $(grep -c '^0x' "$work/glxinfo.log") visual and FBConfig rows"; fi
    finish
}

test_eglinfo() {
    local rc rc2 vendors
    mesa_utils_setup eglinfo eglinfo libEGL.so.1
    # Debian's eglinfo tries every platform its client extensions name and
    # exits 2 when one of them fails to initialize (GBM and Wayland do
    # under Xvfb on Mesa): only a crash or a hang is a failure.
    run_side "$side2" 0 "$work/eglinfo.log" "$tool"
    rc=$?
    run_side "$side2" 1 "$work/eglinfo_nodisplay.log" "$tool"
    rc2=$?
    vendors="$(sed -n 's/^EGL vendor string: //p' "$work/eglinfo.log" | sort -u | tr '\n' ',' | sed 's/,$//')"
    if [ $rc -ge 124 ]; then fail eglinfo "with DISPLAY: $(describe_rc $rc) (see $(rel "$work/eglinfo.log"))"
    elif [ $rc2 -ge 124 ]; then fail eglinfo "without DISPLAY: $(describe_rc $rc2) (see $(rel "$work/eglinfo_nodisplay.log"))"
    elif ! grep -q "^EGL vendor string: .*$expect_egl" "$work/eglinfo.log"; then
        fail eglinfo "no \"EGL vendor string\" names $expect_egl (vendors: ${vendors:-none}; see $(rel "$work/eglinfo.log"))"
    else
        pass eglinfo "vendor $vendors; exit $rc with DISPLAY, $rc2 without; platforms: $(grep -c '^EGL vendor string' "$work/eglinfo.log") initialized"
    fi
    finish
}

test_soak() {
    local prog=$1 frames="${GLFX_SOAK_FRAMES:-600}" slack="${GLFX_SOAK_SLACK_KB:-1024}" exe variant m
    local at100 atend
    exe="$(program_exe "$prog")" || exit 2
    make_out "soak_$prog"
    variant="$(variants "$prog" | awk '{ print $1 }')"
    set_variant "$prog" "$variant"
    if [ "$v_nodisplay" -eq 0 ] && ! start_xvfb; then row "$prog/soak" SKIP "Xvfb is not installed or did not start"; exit $SKIP; fi
    m="$(loader_problem "$exe")"
    [ -n "$m" ] && { fail "$prog/soak" "$m"; finish; }
    if [ "$frames" -lt 200 ]; then echo "run_program.sh: GLFX_SOAK_FRAMES must be 200 or more" >&2; exit 2; fi
    run_timeout=$((timeout_s * 5))
    m="$(run_variant "$side2" "$prog" "$variant" "$work/soak" "$frames" --rss)"
    run_timeout=$timeout_s
    [ -n "$m" ] && { fail "$prog/soak" "$m"; finish; }
    if m="$(soak_verdict "$work/soak.log" "$frames" "$slack")"; then pass "$prog/soak" "$m"
    else fail "$prog/soak" "$m"; fi
    finish
}

# soak_verdict LOG FRAMES SLACK_KB: prints the finding; status 0 when the
# peak RSS after FRAMES frames is at most SLACK_KB above the one after 100.
soak_verdict() {
    local log=$1 frames=$2 slack=$3 at100 atend
    at100="$(sed -n 's/^rss frame=100 .*VmHWM=\([0-9]*\)$/\1/p' "$log")"
    atend="$(sed -n "s/^rss frame=$frames .*VmHWM=\([0-9]*\)\$/\1/p" "$log")"
    if [ -z "$at100" ] || [ -z "$atend" ]; then
        echo "no VmHWM at frames 100 and $frames (see $(rel "$log"))"
        return 1
    fi
    if [ $((atend - at100)) -gt "$slack" ]; then
        echo "peak RSS grew by $((atend - at100)) kB from frame 100 to frame $frames (${at100} -> ${atend} kB, slack $slack kB)"
        return 1
    fi
    echo "peak RSS ${at100} kB at frame 100, ${atend} kB at frame $frames (+$((atend - at100)) kB, slack $slack kB)"
}

test_valgrind() {
    local prog=$1 frames="${GLFX_VALGRIND_FRAMES:-3}" exe variant m rc
    exe="$(program_exe "$prog")" || exit 2
    make_out "valgrind_$prog"
    if ! command -v valgrind >/dev/null 2>&1; then row "$prog/valgrind" SKIP "valgrind is not installed"; exit $SKIP; fi
    m="$(loader_problem "$exe")"
    [ -n "$m" ] && { fail "$prog/valgrind" "$m"; finish; }
    for variant in $(variants "$prog"); do
        set_variant "$prog" "$variant"
        if [ "$v_nodisplay" -eq 0 ] && [ -z "${DISPLAY:-}" ] && ! start_xvfb; then
            skip "$prog/$variant/valgrind" "Xvfb is not installed or did not start"; continue
        fi
        # shellcheck disable=SC2206
        local vg=(valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite
                  --show-leak-kinds=definite --suppressions="$here/valgrind.supp"
                  --log-file="$work/$variant.valgrind" ${GLFX_VALGRIND_OPTS:-})
        run_env=("${v_env[@]}")
        run_timeout=$((timeout_s * 3))
        run_side "$side2" "$v_nodisplay" "$work/$variant.log" "${vg[@]}" "$exe" "$work/$variant" "$frames" "${v_args[@]}"
        rc=$?
        run_timeout=$timeout_s
        run_env=()
        if [ $rc -eq 99 ]; then
            fail "$prog/$variant/valgrind" "valgrind: $(grep -m 1 -E '^==[0-9]+== +[^ ]' "$work/$variant.valgrind" | sed 's/^==[0-9]*== *//') (see $(rel "$work/$variant.valgrind"))"
        elif [ $rc -ne 0 ]; then
            fail "$prog/$variant/valgrind" "$(describe_rc $rc) (see $(rel "$work/$variant.log"))"
        elif m="$(renderer_problem "$side2" "$work/$variant.log")" && [ -n "$m" ]; then
            fail "$prog/$variant/valgrind" "$m"
        else
            pass "$prog/$variant/valgrind" "$frames frames: no memcheck error, no block definitely lost"
        fi
    done
    finish
}

# Every gl*/glX*/egl* name the programs, Debian's libglut and the mesa-utils
# tools import must exist in the drop-in library (libglut is linked BIND_NOW:
# one missing name and the program does not start). Lists all missing names.
test_symbols() {
    local lib exe dep missing names
    make_out symbols
    lib="$dropin/libGL.so.1"
    [ "$side2" = glfixed ] || lib="$(ldconfig -p | awk '$1 == "libGL.so.1" { print $NF; exit }')"
    if [ ! -e "$lib" ]; then fail symbols "no libGL.so.1 in $dropin"; finish; fi
    nm -D --defined-only "$lib" | awk '{ print $NF }' | sed 's/@.*//' | sort -u >"$work/defined"
    if [ "$side2" = glfixed ] && [ -e "$dropin/libEGL.so.1" ]; then
        nm -D --defined-only "$dropin/libEGL.so.1" | awk '{ print $NF }' | sed 's/@.*//' >>"$work/defined"
        sort -u -o "$work/defined" "$work/defined"
    elif [ "$side2" != glfixed ]; then
        nm -D --defined-only "$(ldconfig -p | awk '$1 == "libEGL.so.1" { print $NF; exit }')" |
            awk '{ print $NF }' | sed 's/@.*//' >>"$work/defined"
        sort -u -o "$work/defined" "$work/defined"
    fi
    for exe in "$bin"/glut_lit_scene "$bin"/egl_window_scene "$bin"/egl_pbuffer_scene \
               "$(command -v glxgears)" "$(command -v glxinfo)" "$(command -v eglinfo)"; do
        [ -x "$exe" ] || continue
        names="$(nm -D --undefined-only "$exe" | awk '{ print $NF }')"
        for dep in $(ldd "$exe" 2>/dev/null | awk '$1 ~ /^libglut|^libGLU/ { print $3 }'); do
            names="$names $(nm -D --undefined-only "$dep" | awk '{ print $NF }')"
        done
        # shellcheck disable=SC2086  # one name a word
        missing="$(printf '%s\n' $names | sed 's/@.*//' | grep -E '^(gl|glX|egl)[A-Z]' | sort -u |
                   comm -23 - "$work/defined" | tr '\n' ' ')"
        if [ -n "$missing" ]; then
            fail "symbols/$(basename "$exe")" "$(wc -w <<<"$missing") missing: $missing"
        else
            pass "symbols/$(basename "$exe")" "every imported gl/glX/egl name is defined in $(basename "$lib")"
        fi
    done
    finish
}

mkdir -p "$out_root"
case "$test_name" in
    symbols) test_symbols ;;
    compare) [ -n "$program" ] || exit 2; test_compare "$program" ;;
    mesa) test_mesa ;;
    glxgears) test_glxgears ;;
    glxinfo) test_glxinfo ;;
    eglinfo) test_eglinfo ;;
    soak) [ -n "$program" ] || exit 2; test_soak "$program" ;;
    valgrind) [ -n "$program" ] || exit 2; test_valgrind "$program" ;;
    *) echo "run_program.sh: unknown test '$test_name' (--help)" >&2; exit 2 ;;
esac
