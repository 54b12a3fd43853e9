#!/usr/bin/env bash
# exported_symbols.sh PATH_TO_LIBDEMILL_SO
#
# Checks that the shared library's dynamic symbol table is exactly the public
# API declared in the headers (include/demill.h, include/demill/*.h):
#   1. every defined dynamic symbol (nm -D --defined-only) starts with
#      demill_ (no internal helper leaks into users' symbol namespace);
#   2. every function declared with DEMILL_API in a public header is exported;
#   3. every exported symbol is declared with DEMILL_API in a public header.
#
# Why: the library is compiled with hidden visibility and only DEMILL_API
# marks exports. Forgetting DEMILL_API on a definition silently drops a
# function from the ABI (users fail to link); marking an internal function
# exports it, and users may come to rely on it. The exported set is the ABI
# that the SONAME (libdemill.so.0) promises to keep.
#
# The headers are found relative to this script (../../include), since CTest
# passes only the library. Exits non-zero with a list of differences.
set -eu

if [ $# -ne 1 ]; then
    echo "usage: $0 PATH_TO_LIBDEMILL_SO" >&2
    exit 2
fi
lib=$1
include_dir=$(cd "$(dirname "$0")/../../include" && pwd)

if [ ! -f "$lib" ]; then
    echo "FAIL: no such library: $lib" >&2
    exit 1
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/demill-exported-symbols.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# Linker-defined symbols that are not part of the library's code and that
# some linkers put into the dynamic symbol table of every shared object:
# _init and _fini (the DT_INIT/DT_FINI functions from crti.o) and the
# section-boundary symbols _edata, _end and __bss_start (exported by older
# GNU ld versions and by gold). Debian 12's GNU ld (2.40) exports none of
# them; they are tolerated, by exact name only, so that another toolchain
# does not fail this test for something the library cannot control.
linker_defined='^(_init|_fini|_edata|_end|__bss_start)$'

# 1. The exported (defined, dynamic) symbols. Symbol versions (name@@VER),
#    if a version script is ever added, are stripped.
nm -D --defined-only "$lib" > "$tmp/nm.txt"
awk 'NF >= 3 { print $3 }' "$tmp/nm.txt" | sed 's/@.*//' | sort -u > "$tmp/all_exported"
grep -Ev "$linker_defined" "$tmp/all_exported" > "$tmp/exported" || true
grep -v '^demill_' "$tmp/exported" > "$tmp/foreign" || true
# The API has no variables: every export must be a function (T) in .text.
awk 'NF >= 3 && $3 ~ /^demill_/ && $2 != "T" { print $3 " (nm type " $2 ")" }' \
    "$tmp/nm.txt" > "$tmp/non_function"

# 2. The functions declared with DEMILL_API. Comments and preprocessor lines
#    (the #define of DEMILL_API itself) are removed, the rest is joined into
#    one line, and the name is the last identifier before the "(" that
#    follows DEMILL_API: "DEMILL_API const char *demill_strerror(".
for h in "$include_dir/demill.h" "$include_dir"/demill/*.h; do
    grep -v '^[[:space:]]*#' "$h" | tr '\n' ' ' |
        sed -E 's@/\*([^*]|\*+[^*/])*\*+/@ @g' |
        grep -oE 'DEMILL_API[^(;{}]*\(' |
        sed -E 's/.*[^A-Za-z0-9_]([A-Za-z_][A-Za-z0-9_]*)[[:space:]]*\($/\1/'
done | sort > "$tmp/declared_all"
sort -u "$tmp/declared_all" > "$tmp/declared"
n_api=$(cat "$include_dir/demill.h" "$include_dir"/demill/*.h |
        grep -v '^[[:space:]]*#' | grep -o 'DEMILL_API' | wc -l)

status=0
report() { # title file
    if [ -s "$2" ]; then
        echo "FAIL: $1:" >&2
        sed 's/^/    /' "$2" >&2
        status=1
    fi
}

# Sanity of the header parsing: one name per DEMILL_API, each declared once.
if [ "$(wc -l < "$tmp/declared_all")" -ne "$n_api" ]; then
    echo "FAIL: found $n_api DEMILL_API in the headers but extracted" \
        "$(wc -l < "$tmp/declared_all") declarations:" >&2
    sed 's/^/    /' "$tmp/declared_all" >&2
    status=1
fi
uniq -d "$tmp/declared_all" > "$tmp/duplicates"
report "functions declared with DEMILL_API more than once" "$tmp/duplicates"
grep -v '^demill_' "$tmp/declared" > "$tmp/bad_names" || true
report "DEMILL_API declarations whose name does not start with demill_" "$tmp/bad_names"

report "exported symbols that do not start with demill_" "$tmp/foreign"
report "exported demill_ symbols that are not functions" "$tmp/non_function"
comm -23 "$tmp/declared" "$tmp/exported" > "$tmp/missing"
report "declared with DEMILL_API in a public header but not exported by $lib" "$tmp/missing"
comm -13 "$tmp/declared" "$tmp/exported" > "$tmp/undeclared"
report "exported by $lib but not declared with DEMILL_API in a public header" "$tmp/undeclared"
grep -E "$linker_defined" "$tmp/all_exported" > "$tmp/tolerated" || true
if [ -s "$tmp/tolerated" ]; then
    echo "note: linker-defined symbols tolerated: $(tr '\n' ' ' < "$tmp/tolerated")"
fi

if [ "$status" -ne 0 ]; then
    exit 1
fi
echo "exported_symbols: $(wc -l < "$tmp/exported") exported symbols, all declared with" \
    "DEMILL_API in $include_dir; all $(wc -l < "$tmp/declared") declarations exported"
