#!/usr/bin/env bash
# A program that links both libGL.so.1 and libOSMesa.so.8 still renders on the
# drop-in folder, with one library instance behind both names.
# Usage: one_instance_test.sh <program> <drop-in folder>
set -euo pipefail
program=$1 dropin=$2
fail() { echo "FAIL: $*" >&2; exit 1; }

needed=$(readelf -d "$program" | sed -n 's/.*(NEEDED).*\[\(lib\(GL\|OSMesa\)\.so\.[0-9]*\)\]/\1/p' | tr '\n' ' ')
[ "$needed" = "libGL.so.1 libOSMesa.so.8 " ] || fail "the program needs '$needed', not libGL.so.1 then libOSMesa.so.8"

# Stock Debian: libglvnd's libGL.so.1 with Mesa's libOSMesa.so.8 draws nothing.
if env -u LD_LIBRARY_PATH "$program" --one-instance > /dev/null 2>&1; then
  echo "note: the program also renders without the drop-in folder (libGL.so.1 and libOSMesa.so.8 are one instance here)"
else
  echo "without the drop-in folder it does not render (two instances), as expected"
fi

output=$(LD_LIBRARY_PATH=$dropin "$program" --one-instance) || { echo "$output"; fail "it does not render with LD_LIBRARY_PATH=<drop-in>"; }
echo "$output"
echo "$output" | grep -q "libGL.so.1's .* in .*/libglfixed\.so\.[0-9.]*," || fail "glClear does not resolve into libglfixed"
echo "PASS: one instance"
