#!/usr/bin/env bash
# Installs ffvk's C library as a system library; `make install-c` runs it. Into
# $DESTDIR$LIBDIR: libffvk_c.so.$VERSION, the links libffvk_c.so.$MAJOR (its SONAME) and
# libffvk_c.so, and libffvk_c.a; into $DESTDIR$INCLUDEDIR: ffvk.h; into
# $DESTDIR$INCLUDEDIR/ffvk: the shader library (ffvk/glsl/lib/ffvk/*.glsl); into
# $DESTDIR$LIBDIR/pkgconfig: ffvk.pc, written for $PREFIX (DESTDIR only stages the files).
#
# Environment: FFVK_C_LIB_DIR (where cargo built libffvk_c.so and libffvk_c.a), PREFIX, LIBDIR,
# INCLUDEDIR, DESTDIR (may be empty), RPATH: auto (the default) gives ffvk.pc's Libs
# -Wl,-rpath,${libdir} when LIBDIR is not a directory the dynamic loader searches, so that a
# program built with `pkg-config --libs ffvk` starts without LD_LIBRARY_PATH; yes or no force it.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
: "${FFVK_C_LIB_DIR:?the directory cargo built libffvk_c.so in}"
: "${PREFIX:?the installation prefix}"
LIBDIR=${LIBDIR:-$PREFIX/lib}
INCLUDEDIR=${INCLUDEDIR:-$PREFIX/include}
DESTDIR=${DESTDIR:-}
RPATH=${RPATH:-auto}

fail() {
  echo "ffvk: install-c: $*" >&2
  exit 1
}

for path in PREFIX LIBDIR INCLUDEDIR; do
  [[ ${!path} == /* ]] || fail "$path is ${!path}: expected an absolute path"
done
version=$(sed -n 's/^version = "\(.*\)"$/\1/p' "$root/ffvk-c/Cargo.toml" | head -n 1)
[[ $version =~ ^[0-9]+\.[0-9]+\.[0-9]+ ]] || fail "no version in ffvk-c/Cargo.toml"
major=${version%%.*}
soname=libffvk_c.so.$major

for file in libffvk_c.so libffvk_c.a; do
  [[ -f $FFVK_C_LIB_DIR/$file ]] ||
    fail "$FFVK_C_LIB_DIR/$file is missing: build it with cargo build --release -p ffvk-c (or set FFVK_C_LIB_DIR)"
done
# A library built before its SONAME carried the major version would install under a name
# programs linked with it do not ask for.
if command -v readelf >/dev/null; then
  built=$(readelf -d "$FFVK_C_LIB_DIR/libffvk_c.so" | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
  [[ $built == "$soname" ]] ||
    fail "$FFVK_C_LIB_DIR/libffvk_c.so has the SONAME '${built}': expected $soname (rebuild it with cargo build -p ffvk-c)"
fi

# Whether the dynamic loader finds libraries in LIBDIR by itself: the directories ldconfig
# scans (its configuration and its built-in ones) and the system's own.
searched() {
  local ldconfig dir want
  ldconfig=$(command -v ldconfig || echo /sbin/ldconfig)
  want=$(realpath -m "$1")
  while read -r dir; do
    [[ -n $dir && $(realpath -m "$dir") == "$want" ]] && return 0
  done < <({ "$ldconfig" -vNX 2>/dev/null || true; } | sed -n 's|^\(/[^:]*\):.*|\1|p'; printf '%s\n' /lib /usr/lib /lib64 /usr/lib64)
  return 1
}
case $RPATH in
  auto) if searched "$LIBDIR"; then rpath=no; else rpath=yes; fi ;;
  yes | no) rpath=$RPATH ;;
  *) fail "RPATH is $RPATH: expected auto, yes or no" ;;
esac

lib=$DESTDIR$LIBDIR
include=$DESTDIR$INCLUDEDIR
install -d "$lib/pkgconfig" "$include"
install -m 0755 "$FFVK_C_LIB_DIR/libffvk_c.so" "$lib/libffvk_c.so.$version"
ln -sfn "libffvk_c.so.$version" "$lib/$soname"
ln -sfn "$soname" "$lib/libffvk_c.so"
install -m 0644 "$FFVK_C_LIB_DIR/libffvk_c.a" "$lib/libffvk_c.a"
install -m 0644 "$root/ffvk-c/include/ffvk.h" "$include/ffvk.h"
# The shader library beside it: a shader compiled with -I$INCLUDEDIR includes "ffvk/lighting.glsl".
install -d "$include/ffvk"
install -m 0644 "$root"/ffvk/glsl/lib/ffvk/*.glsl "$include/ffvk/"

# Paths under the prefix are written relative to it, as pkg-config's files spell them.
pc_libdir=$LIBDIR
pc_includedir=$INCLUDEDIR
[[ $LIBDIR == "$PREFIX"/* ]] && pc_libdir="\${prefix}${LIBDIR#"$PREFIX"}"
[[ $INCLUDEDIR == "$PREFIX"/* ]] && pc_includedir="\${prefix}${INCLUDEDIR#"$PREFIX"}"
pc_rpath=
[[ $rpath == yes ]] && pc_rpath=' -Wl,-rpath,${libdir}'
# A value as sed's replacement text spells it.
literal() { printf '%s' "$1" | sed 's/[&|\\]/\\&/g'; }
sed -e "s|@PREFIX@|$(literal "$PREFIX")|" -e "s|@LIBDIR@|$(literal "$pc_libdir")|" \
  -e "s|@INCLUDEDIR@|$(literal "$pc_includedir")|" -e "s|@VERSION@|$version|" \
  -e "s|@RPATH@|$(literal "$pc_rpath")|" "$root/ffvk-c/ffvk.pc.in" >"$lib/pkgconfig/ffvk.pc"

echo "ffvk: installed libffvk_c.so.$version ($soname), libffvk_c.a, ffvk.h, the shader library (ffvk/*.glsl) and ffvk.pc into ${DESTDIR}${PREFIX}"
if [[ $rpath == no && -z $DESTDIR ]]; then
  if [[ $(id -u) -eq 0 ]]; then
    "$(command -v ldconfig || echo /sbin/ldconfig)"
  else
    echo "ffvk: run ldconfig as root, so that the dynamic loader finds $soname in $LIBDIR" >&2
  fi
fi
