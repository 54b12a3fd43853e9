#!/usr/bin/env bash
# install_consumer.sh SRC_DIR BUILD_DIR
#
# Checks that an installed libdemill can be used by a program outside the
# source tree, the two ways users find it:
#   * pkg-config: `pkg-config --cflags --libs demill` with PKG_CONFIG_PATH
#     pointing into the install, and a plain compiler command;
#   * CMake: find_package(demill REQUIRED) with CMAKE_PREFIX_PATH set to the
#     install, linking demill::demill (shared) and demill::demill_static.
# The consumer (tests/api/consumer/main.c) checks that headers and library
# agree on the version and drops one particle through the installed library,
# comparing with the analytic free fall. It also checks the shared library's
# SONAME (libdemill.so.0) and file name (libdemill.so.0.1.0), which users'
# programs and distribution packages depend on.
#
# Why: the build tree's targets hide packaging mistakes (missing installed
# headers, a .pc or CMake package pointing to the wrong place, a dependency
# not exported). Only building against a fresh install catches them.
#
# Everything goes into a fresh temporary directory that is removed on exit.
# All checks run; the script exits non-zero if any of them failed.
set -eu

if [ $# -ne 2 ]; then
    echo "usage: $0 SRC_DIR BUILD_DIR" >&2
    exit 2
fi
src_dir=$(cd "$1" && pwd)
build_dir=$(cd "$2" && pwd)
consumer_dir="$src_dir/tests/api/consumer"
cc=${CC:-cc}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/demill-install-consumer.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"
failures=()

fail() {
    echo "FAIL: $*" >&2
    failures+=("$*")
}

step() {
    echo
    echo "== $*"
}

# Runs an executable built against the install and checks its "OK" line.
run_consumer() { # label exe
    local out rc=0
    echo "+ $2"
    out=$("$2") || rc=$?
    echo "$out"
    if [ "$rc" -ne 0 ]; then
        fail "$1: consumer exited with status $rc"
    else
        case "$out" in
            *": OK") ;;
            *) fail "$1: unexpected output: $out" ;;
        esac
    fi
}

# Checks that the dynamic loader resolves libdemill to the installed copy.
check_resolved_lib() { # label exe
    local resolved
    resolved=$(ldd "$2" | awk '$1 ~ /^libdemill\.so/ { print $3 }')
    case "$resolved" in
        "$libdir"/libdemill.so.0) echo "$1 loads $resolved" ;;
        *) fail "$1 loads libdemill from '${resolved:-nowhere}', not $libdir" ;;
    esac
}

step "install $build_dir into $prefix"
cmake --install "$build_dir" --prefix "$prefix"

# GNUInstallDirs picks lib, lib64 or lib/<multiarch> depending on the system.
pcfile=$(find "$prefix" -path '*/pkgconfig/demill.pc' | head -n 1)
if [ -z "$pcfile" ]; then
    echo "FAIL: no demill.pc installed under $prefix" >&2
    find "$prefix" >&2
    exit 1
fi
libdir=$(dirname "$(dirname "$pcfile")")
echo "library directory: $libdir"

step "shared library name and SONAME"
if [ -f "$libdir/libdemill.so.0.1.0" ] && [ ! -L "$libdir/libdemill.so.0.1.0" ]; then
    echo "found $libdir/libdemill.so.0.1.0"
else
    fail "$libdir/libdemill.so.0.1.0 is missing or not a regular file"
fi
soname=$(readelf -d "$libdir/libdemill.so" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
if [ "$soname" = libdemill.so.0 ]; then
    echo "SONAME: $soname"
else
    fail "SONAME of libdemill.so is '$soname', expected libdemill.so.0"
fi
for link in libdemill.so libdemill.so.0; do
    if [ "$(readlink -f "$libdir/$link")" != "$(readlink -f "$libdir/libdemill.so.0.1.0")" ]; then
        fail "$libdir/$link does not lead to libdemill.so.0.1.0"
    fi
done

step "pkg-config consumer"
export PKG_CONFIG_PATH="$libdir/pkgconfig"
# Only the install under test, never a system-wide copy.
export PKG_CONFIG_LIBDIR="$libdir/pkgconfig"
pc_version=$(pkg-config --modversion demill)
echo "pkg-config demill version: $pc_version"
[ "$pc_version" = 0.1.0 ] || fail "pkg-config reports version $pc_version, expected 0.1.0"
# The .pc file must describe where the package was installed, or every user
# of a relocated install (cmake --install --prefix) compiles against the
# wrong headers or none.
# (Paths are compared after normalisation: a relocatable .pc file may say
# prefix=${pcfiledir}/../.. and so give .../lib/pkgconfig/../../include.)
pc_includedir=$(pkg-config --variable=includedir demill)
pc_libdir=$(pkg-config --variable=libdir demill)
if [ "$(realpath -m "$pc_includedir")" != "$(realpath -m "$prefix/include")" ] \
    || [ "$(realpath -m "$pc_libdir")" != "$(realpath -m "$libdir")" ]; then
    fail "demill.pc points to includedir=$pc_includedir libdir=$pc_libdir, not to the install ($prefix/include, $libdir): the .pc file is not relocatable (cmake --install --prefix)"
fi
flags=$(pkg-config --cflags --libs demill)
echo "pkg-config --cflags --libs demill: $flags"
# shellcheck disable=SC2086 # $flags is a list of words by design
if (set -x; "$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror \
        "$consumer_dir/main.c" -o "$tmp/consumer_pkgconfig" $flags); then
    LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
        check_resolved_lib "pkg-config consumer" "$tmp/consumer_pkgconfig"
    LD_LIBRARY_PATH="$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
        run_consumer "pkg-config consumer" "$tmp/consumer_pkgconfig"
else
    fail "pkg-config consumer does not build"
fi

step "CMake consumer (find_package(demill), shared and static)"
# No package registry: the install must be found through CMAKE_PREFIX_PATH.
if cmake -S "$consumer_dir" -B "$tmp/consumer-build" \
        -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
        -DCMAKE_FIND_USE_SYSTEM_PACKAGE_REGISTRY=OFF \
    && cmake --build "$tmp/consumer-build"; then
    found=$(sed -n 's/^demill_DIR:PATH=//p' "$tmp/consumer-build/CMakeCache.txt")
    if [ "$(readlink -f "$found")" != "$(readlink -f "$libdir/cmake/demill")" ]; then
        fail "find_package(demill) used $found, not $libdir/cmake/demill"
    fi
    # The imported target carries the library's path, so CMake gives the
    # executable a RUNPATH to the install: no LD_LIBRARY_PATH here.
    check_resolved_lib "CMake shared consumer" "$tmp/consumer-build/consumer_shared"
    run_consumer "CMake shared consumer" "$tmp/consumer-build/consumer_shared"
    if readelf -d "$tmp/consumer-build/consumer_static" | grep -q 'NEEDED.*libdemill'; then
        fail "consumer_static links libdemill.so, not the static library"
    else
        echo "consumer_static does not need libdemill.so"
    fi
    run_consumer "CMake static consumer" "$tmp/consumer-build/consumer_static"
else
    fail "CMake consumer does not configure or build"
fi

echo
if [ ${#failures[@]} -ne 0 ]; then
    echo "install_consumer: ${#failures[@]} check(s) failed:" >&2
    printf '  - %s\n' "${failures[@]}" >&2
    exit 1
fi
echo "install_consumer: all checks passed"
