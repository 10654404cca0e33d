#!/usr/bin/env bash
# Runs piglit's fixed-function tests (Debian's `piglit`) under a private Xvfb, once
# on Mesa (the system's libGL, llvmpipe) and once on libglfixed (the build's
# dropin/ folder first on LD_LIBRARY_PATH), and prints both results side by side.
#
#   run_piglit.sh [--mesa-only|--glfixed-only] [--dropin DIR] [--out DIR]
#                 [--jobs N] [--timeout S] [--display N] [LIST]
#   run_piglit.sh --test "<test> [args]" [--dropin DIR] [--mesa-only] ...
#
# LIST is a file of "<needs> <test> [args...]" lines (default: the
# fixed_function_tests.txt beside this script). Each test runs as
#   PIGLIT_PLATFORM=glx <piglit bin>/<test> <args> -auto
# in window mode, with a time limit; its result is the last `PIGLIT: {"result": ...}`
# line it prints, or timeout / crash (killed by a signal) / nostart (the loader
# refused it: a missing symbol or library) / noresult (it exited without one).
#
# With --glfixed-only the Mesa column is read from mesa_results.txt beside this
# script (the recorded run; "--mesa-only --record" writes it).
# Out folder (default build/piglit): results.txt, results.md (the table the README
# includes), logs/<mesa|glfixed>/<test>.log.
#
# --test runs one test on libglfixed (or Mesa with --mesa-only) and exits 0 when it
# passes, 1 when not, 77 when piglit or Xvfb is not installed (ctest's skip code).
set -u

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
repo="$(cd "$here/../.." && pwd)"

run_mesa=1 run_glfixed=1 record=0 one_test=""
dropin="${GLFIXED_DROPIN:-$repo/build/dropin}"
out="" jobs=2 limit=30 display="${PIGLIT_XVFB_DISPLAY:-}"
list="$here/fixed_function_tests.txt"
while [ $# -gt 0 ]; do
  case "$1" in
    --mesa-only) run_glfixed=0 ;;
    --glfixed-only) run_mesa=0 ;;
    --record) record=1 ;;
    --dropin) dropin="$2"; shift ;;
    --out) out="$2"; shift ;;
    --jobs) jobs="$2"; shift ;;
    --timeout) limit="$2"; shift ;;
    --display) display="$2"; shift ;;
    --test) one_test="$2"; shift ;;
    -h|--help) sed -n '2,26p' "${BASH_SOURCE[0]}"; exit 0 ;;
    -*) echo "run_piglit.sh: unknown option $1" >&2; exit 2 ;;
    *) list="$1" ;;
  esac
  shift
done
[ "$run_mesa$run_glfixed" = "00" ] && { echo "run_piglit.sh: nothing to run" >&2; exit 2; }
skip() { echo "run_piglit.sh: SKIP: $*" >&2; exit 77; }

# piglit's binaries: $PIGLIT_BIN, else where Debian's package put them.
bin="${PIGLIT_BIN:-}"
if [ -z "$bin" ] && command -v dpkg >/dev/null 2>&1; then
  bin="$(dpkg -L piglit 2>/dev/null | grep -m1 '/piglit/bin$' || true)"
fi
if [ -z "$bin" ]; then
  for d in /usr/lib/*/piglit/bin /usr/lib/piglit/bin /usr/local/lib/piglit/bin; do
    [ -d "$d" ] && { bin="$d"; break; }
  done
fi
[ -n "$bin" ] && [ -d "$bin" ] || skip "piglit is not installed (apt-get install piglit, or set PIGLIT_BIN)"
command -v Xvfb >/dev/null 2>&1 || skip "Xvfb is not installed (apt-get install xvfb)"
if [ "$run_glfixed" = 1 ] && [ ! -e "$dropin/libGL.so.1" ]; then
  echo "run_piglit.sh: $dropin/libGL.so.1 not found (build first, or give --dropin)" >&2
  exit 2
fi

[ -n "$out" ] || out="$repo/build/piglit"
[ -n "$one_test" ] && out="$(mktemp -d "${TMPDIR:-/tmp}/glfixed-piglit.XXXXXX")"
mkdir -p "$out/logs/mesa" "$out/logs/glfixed" "$out/status"

# The tests: "<needs> <command line>" pairs, in list order.
declare -a needs_of cmd_of
if [ -n "$one_test" ]; then
  needs_of=("-") cmd_of=("$one_test")
else
  [ -r "$list" ] || { echo "run_piglit.sh: cannot read $list" >&2; exit 2; }
  while read -r n rest; do
    case "$n" in ''|'#'*) continue ;; esac
    needs_of+=("$n") cmd_of+=("$rest")
  done <"$list"
fi

# One private X server a job, 24-bit, on a free display (or display, display+1,
# ...): tests that read the front buffer read the window itself, which another
# test's window must not cover. -noreset: the server would otherwise reset when a
# test's last connection closes and refuse the next test's while it does.
[ -n "$one_test" ] && jobs=1
xvfb_pids=()
cleanup() {
  local p
  for p in "${xvfb_pids[@]}"; do kill "$p" 2>/dev/null && wait "$p" 2>/dev/null; done
  [ -n "$one_test" ] && rm -rf "$out"
}
trap cleanup EXIT
trap 'exit 130' INT TERM
displays=()
for ((j = 0; j < jobs; j++)); do
  fdfile="$out/xvfb.$j.display"
  rm -f "$fdfile"
  if [ -n "$display" ]; then
    Xvfb ":$((display + j))" -screen 0 1280x1024x24 -nolisten tcp -noreset >"$out/xvfb.$j.log" 2>&1 &
    xvfb_pids+=($!)
    for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X$((display + j))" ] && break; sleep 0.1; done
    echo "$((display + j))" >"$fdfile"
  else
    Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$fdfile" >"$out/xvfb.$j.log" 2>&1 &
    xvfb_pids+=($!)
    for _ in $(seq 100); do [ -s "$fdfile" ] && break; sleep 0.1; done
  fi
  if ! kill -0 "${xvfb_pids[$j]}" 2>/dev/null || [ ! -s "$fdfile" ]; then
    cat "$out/xvfb.$j.log" >&2
    skip "Xvfb did not start"
  fi
  displays+=(":$(head -n1 "$fdfile" | tr -d ' \n')")
done
export PIGLIT_PLATFORM=glx PIGLIT_SOURCE_DIR="$(dirname "$bin")"
unset PIGLIT_NO_WINDOW

# One test on one library: writes its status to status/<lib>.<index>.
run_one() {
  local lib="$1" idx="$2" cmd="$3" log status rc
  local name="${cmd// /_}"
  log="$out/logs/$lib/${name//\//_}.log"
  read -r -a argv <<<"$cmd"
  if [ ! -x "$bin/${argv[0]}" ]; then
    echo "missing" >"$out/status/$lib.$idx"; return
  fi
  if [ "$lib" = glfixed ]; then
    # GLFX_GLFIXED_ENV: extra VAR=value words for the libglfixed runs only
    # (a sanitizer build's runtime, preloaded into piglit's programs).
    env LD_LIBRARY_PATH="$dropin${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" ${GLFX_GLFIXED_ENV:-} \
      timeout -k 5 "$limit" "$bin/${argv[0]}" "${argv[@]:1}" -auto >"$log" 2>&1 </dev/null
  else
    timeout -k 5 "$limit" "$bin/${argv[0]}" "${argv[@]:1}" -auto >"$log" 2>&1 </dev/null
  fi
  rc=$?
  status="$(sed -n 's/^PIGLIT: *{ *"result" *: *"\([a-z]*\)".*/\1/p' "$log" | tail -n1)"
  if [ -z "$status" ]; then
    if [ "$rc" = 124 ] || [ "$rc" = 137 ]; then status=timeout
    elif grep -qE 'symbol lookup error|error while loading shared libraries|undefined symbol' "$log"; then status=nostart
    elif [ "$rc" -gt 128 ]; then status=crash
    else status=noresult
    fi
  fi
  echo "$status" >"$out/status/$lib.$idx"
}
libs=()
[ "$run_mesa" = 1 ] && libs+=(mesa)
[ "$run_glfixed" = 1 ] && libs+=(glfixed)
# Job j runs every jobs-th test, one at a time, on its own server.
job_pids=()
for ((j = 0; j < jobs; j++)); do
  (
    export DISPLAY="${displays[$j]}"
    for lib in "${libs[@]}"; do
      for ((i = j; i < ${#cmd_of[@]}; i += jobs)); do run_one "$lib" "$i" "${cmd_of[$i]}"; done
    done
  ) &
  job_pids+=($!)
done
wait "${job_pids[@]}"

status_of() { cat "$out/status/$1.$2" 2>/dev/null || echo "-"; }

if [ -n "$one_test" ]; then
  lib=glfixed; [ "$run_glfixed" = 1 ] || lib=mesa
  s="$(status_of "$lib" 0)"
  echo "piglit $one_test on $lib: $s"
  [ "$s" = pass ] || { cat "$out/logs/$lib/"*.log; exit 1; }
  exit 0
fi

# The Mesa column: this run's, or the recorded one.
declare -A recorded
if [ "$run_mesa" = 0 ] && [ -r "$here/mesa_results.txt" ]; then
  while read -r s rest; do
    case "$s" in ''|'#'*) continue ;; esac
    recorded["$rest"]="$s"
  done <"$here/mesa_results.txt"
fi
declare -a mesa_s glfixed_s
for i in "${!cmd_of[@]}"; do
  if [ "$run_mesa" = 1 ]; then mesa_s[i]="$(status_of mesa "$i")"; else mesa_s[i]="${recorded[${cmd_of[$i]}]:--}"; fi
  if [ "$run_glfixed" = 1 ]; then glfixed_s[i]="$(status_of glfixed "$i")"; else glfixed_s[i]="-"; fi
done
mesa_of() { echo "${mesa_s[$1]}"; }
glfixed_of() { echo "${glfixed_s[$1]}"; }

if [ "$record" = 1 ] && [ "$run_mesa" = 1 ]; then
  {
    echo "# piglit's fixed-function tests on Mesa (llvmpipe) under Xvfb, as run_piglit.sh"
    echo "# --mesa-only --record found them: <result> <test command line>."
    for i in "${!cmd_of[@]}"; do echo "$(status_of mesa "$i") ${cmd_of[$i]}"; done
  } >"$here/mesa_results.txt"
fi

txt="$out/results.txt" md="$out/results.md"
mesa_label="Mesa"; [ "$run_mesa" = 1 ] || mesa_label="Mesa (recorded)"
{
  printf '%-62s %-28s %-9s %s\n' test needs mesa libglfixed
  for i in "${!cmd_of[@]}"; do
    printf '%-62s %-28s %-9s %s\n' "${cmd_of[$i]}" "${needs_of[$i]}" "$(mesa_of "$i")" "$(glfixed_of "$i")"
  done
} >"$txt"
{
  echo "| piglit test | needs | $mesa_label | libglfixed |"
  echo "| --- | --- | --- | --- |"
  for i in "${!cmd_of[@]}"; do
    echo "| \`${cmd_of[$i]}\` | ${needs_of[$i]} | $(mesa_of "$i") | $(glfixed_of "$i") |"
  done
} >"$md"
cat "$txt"

# Summary: counts per column, and the tests that matter most: pass on Mesa and
# need nothing the library lacks.
count() { # column index(1 mesa, 2 glfixed), status
  local c=0 i v
  for i in "${!cmd_of[@]}"; do
    if [ "$1" = 1 ]; then v="${mesa_s[i]}"; else v="${glfixed_s[i]}"; fi
    [ "$v" = "$2" ] && c=$((c + 1))
  done
  echo "$c"
}
summary="$out/summary.txt"
{
echo "summary (${#cmd_of[@]} tests):"
for col in 1 2; do
  label="$mesa_label"; [ "$col" = 2 ] && label=libglfixed
  [ "$col" = 2 ] && [ "$run_glfixed" = 0 ] && continue
  line=""
  for s in pass fail skip warn crash nostart timeout noresult missing; do
    n="$(count "$col" "$s")"; [ "$n" = 0 ] || line="$line $s $n,"
  done
  echo "  $label:${line%,}"
done
want=0 got=0 failing=""
for i in "${!cmd_of[@]}"; do
  [ "${needs_of[$i]}" = "-" ] && [ "$(mesa_of "$i")" = pass ] || continue
  want=$((want + 1))
  if [ "$(glfixed_of "$i")" = pass ]; then got=$((got + 1)); else failing="$failing ${cmd_of[$i]// /_}"; fi
done
if [ "$run_glfixed" = 1 ]; then
  echo "  libglfixed passes $got of the $want tests that pass on Mesa and need nothing it lacks"
  [ -n "$failing" ] && echo "  not yet:$failing"
else
  echo "  $want tests pass on Mesa and need nothing libglfixed lacks"
fi
} >"$summary"
echo; cat "$summary"
{ echo; grep -v '^  not yet:' "$summary" | sed 's/^  /- /'; } >>"$md"
echo "table: $txt; markdown: $md; logs: $out/logs"
