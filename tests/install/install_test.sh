#!/usr/bin/env bash
# Installs the build into a prefix inside the build tree, moves the prefix (the
# install is relocatable), checks its layout, then builds consumer/lit_triangle.c
# from outside the tree twice, with `pkg-config --cflags --libs glfixed` and
# with consumer/CMakeLists.txt (find_package(glfixed)), runs both and checks
# that each loads libglfixed.so.0 from the prefix.
# Usage: install_test.sh <build dir> <work dir> <libdir> <C compiler> <cmake> <GLFIXED_INSTALL_DROPIN>
set -euo pipefail
build=$1 work=$2 libdir=$3 cc=$4 cmake=$5 with_dropin=$6
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "FAIL: $*" >&2; exit 1; }

rm -rf "$work"
mkdir -p "$work"
"$cmake" --install "$build" --prefix "$work/staged" > "$work/install.log"
mv "$work/staged" "$work/prefix"
prefix=$work/prefix
lib=$prefix/$libdir

# The library, its SONAME and the development link.
[ -f "$lib/libglfixed.so.0.1.0" ] && [ ! -L "$lib/libglfixed.so.0.1.0" ] || fail "no $libdir/libglfixed.so.0.1.0"
for link in libglfixed.so.0 libglfixed.so; do
  [ -L "$lib/$link" ] && [ -e "$lib/$link" ] || fail "$libdir/$link is not a working link"
done
readelf -d "$lib/libglfixed.so.0.1.0" | grep -q 'SONAME.*\[libglfixed\.so\.0\]' || fail "SONAME is not libglfixed.so.0"

# The headers, in include/glfixed only.
for header in GL/gl.h GL/osmesa.h; do
  [ -f "$prefix/include/glfixed/$header" ] || fail "no include/glfixed/$header"
done
[ ! -e "$prefix/include/GL" ] || fail "headers installed into include/GL, over the system's"

# The drop-in names in a folder of their own, as relative links to the library;
# none of them (and no libGL.so*) in the library folder itself.
dropin=$lib/glfixed
names=(libGL.so.1 libOSMesa.so.8 libOpenGL.so.0)
[ -e "$build/dropin/libEGL.so.1" ] && names+=(libEGL.so.1)
case "$with_dropin" in ON | on | TRUE | true | 1 | YES | yes) ;; *) names=() ;; esac
[ ${#names[@]} -gt 0 ] || [ ! -e "$dropin" ] || fail "GLFIXED_INSTALL_DROPIN is off, but $libdir/glfixed is there"
for name in "${names[@]}"; do
  [ -e "$dropin/$name" ] || fail "no $libdir/glfixed/$name"
done
for name in "${names[@]}"; do
  [ "$name" = libOpenGL.so.0 ] && continue
  target=$(readlink "$dropin/$name") || fail "$libdir/glfixed/$name is not a link"
  [ "${target#/}" = "$target" ] || fail "$libdir/glfixed/$name links an absolute path: $target"
  [ "$(realpath "$dropin/$name")" = "$(realpath "$lib/libglfixed.so.0.1.0")" ] || fail "$name is not the library"
done
stray=$(find "$lib" -maxdepth 1 \( -name 'libGL.so*' -o -name 'libGLX*' -o -name 'libEGL*' -o -name 'libOSMesa*' -o -name 'libOpenGL*' \))
[ -z "$stray" ] || fail "drop-in names in $libdir itself: $stray"

# Nothing but the library: no programs, no tests, no benchmark.
[ ! -e "$prefix/bin" ] || fail "programs installed: $(ls "$prefix/bin")"
extra=$(find "$prefix" -type f ! -path "$prefix/include/glfixed/*" ! -name 'libglfixed.so.*' ! -name 'libOpenGL.so.0' \
        ! -name glfixed.pc ! -path "$lib/cmake/glfixed/*")
[ -z "$extra" ] || fail "unexpected files installed: $extra"

# Runs a program built against the prefix and checks that it draws and that it
# loads libglfixed.so.0 from the prefix (through its RPATH).
check_program() {
  local program=$1
  readelf -d "$program" | grep -q 'NEEDED.*\[libglfixed\.so\.0\]' || fail "$program does not link libglfixed.so.0"
  local loaded
  loaded=$(env -u LD_LIBRARY_PATH ldd "$program" | awk '$1 == "libglfixed.so.0" { print $3 }')
  [ -n "$loaded" ] && [ "$(realpath "$loaded")" = "$(realpath "$lib/libglfixed.so.0")" ] \
    || fail "$program loads libglfixed.so.0 from '${loaded}', not from the prefix"
  env -u LD_LIBRARY_PATH "$program" || fail "$program did not draw the lit triangle"
}

# 1. pkg-config.
export PKG_CONFIG_PATH=$lib/pkgconfig
[ "$(pkg-config --modversion glfixed)" = 0.1.0 ] || fail "pkg-config does not find glfixed 0.1.0"
flags=$(pkg-config --cflags --libs glfixed)
echo "pkg-config --cflags --libs glfixed: $flags"
case "$flags" in *include/glfixed*) ;; *) fail "the Cflags do not name include/glfixed" ;; esac
# shellcheck disable=SC2086  # the flags are words
"$cc" -o "$work/lit_triangle_pkg_config" "$here/consumer/lit_triangle.c" $flags -Wl,-rpath,"$lib"
check_program "$work/lit_triangle_pkg_config"

# 2. find_package(glfixed).
"$cmake" -S "$here/consumer" -B "$work/consumer" -DCMAKE_C_COMPILER="$cc" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/consumer.log" || { cat "$work/consumer.log"; fail "cmake: find_package(glfixed)"; }
grep -q "^glfixed_DIR:PATH=$lib/cmake/glfixed\$" "$work/consumer/CMakeCache.txt" || fail "glfixed_DIR is not the prefix's"
expected_dropin=""
[ ${#names[@]} -gt 0 ] && expected_dropin=$dropin
grep -q "glfixed_DROPIN_DIR=$expected_dropin\$" "$work/consumer.log" || fail "glfixed_DROPIN_DIR is not '$expected_dropin'"
"$cmake" --build "$work/consumer" >> "$work/consumer.log" || { cat "$work/consumer.log"; fail "building the consumer"; }
check_program "$work/consumer/lit_triangle"
echo "PASS: installed, relocated, built with pkg-config and with find_package"
