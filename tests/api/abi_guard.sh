#!/usr/bin/env bash
# abi_guard.sh PATH_TO_LIBDEMILL_SO [--update]
#
# Guards the API and ABI of the 0.x series (libdemill.so.0) against
# accidental breaks. It describes the public interface as lines:
#   symbol NAME         every demill_ symbol the shared library exports
#   function DECL       every DEMILL_API declaration in the public headers,
#                       whitespace normalised (return type, name, parameters)
#   constant NAME=VALUE every enum constant DEMILL_* of the headers, with the
#                       value the C compiler gives it
#   type DECL           every typedef of the headers
# and compares them with the committed baseline, tests/api/abi-baseline.txt:
#   - a baseline line that is no longer there (a function removed or its
#     signature changed, a constant renumbered, a type changed, a symbol gone)
#     is a break: FAIL;
#   - a line not in the baseline is an addition, which the 0.x series allows
#     but which must be accepted on purpose: FAIL until the baseline is
#     updated with --update (which refuses while anything is broken).
# Opaque handles keep every struct out of the interface, so there are no
# layouts to compare; the headers' header_hygiene test checks they compile.
set -eu

if [ $# -lt 1 ] || [ $# -gt 2 ] || { [ $# -eq 2 ] && [ "$2" != "--update" ]; }; then
    echo "usage: $0 PATH_TO_LIBDEMILL_SO [--update]" >&2
    exit 2
fi
lib=$1
update=${2:-}
here=$(cd "$(dirname "$0")" && pwd)
include_dir=$(cd "$here/../../include" && pwd)
baseline="$here/abi-baseline.txt"
cc=${CC:-cc}

tmp=$(mktemp -d "${TMPDIR:-/tmp}/demill-abi.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# The headers without comments and preprocessor lines, as one line.
for h in "$include_dir/demill.h" "$include_dir"/demill/*.h; do
    grep -v '^[[:space:]]*#' "$h"
done | tr '\n' ' ' | sed -E 's@/\*([^*]|\*+[^*/])*\*+/@ @g' > "$tmp/flat"

normalise() { # collapse blanks, none around punctuation
    sed -E 's/[[:space:]]+/ /g; s/ ?([(),*;]) ?/\1/g; s/^ //; s/ $//'
}

{
    nm -D --defined-only "$lib" | awk 'NF >= 3 && $3 ~ /^demill_/ { print "symbol " $3 }' |
        sed 's/@.*//'
    grep -oE 'DEMILL_API[^;{}]*;' "$tmp/flat" | sed 's/^DEMILL_API//' | normalise |
        sed 's/^/function /'
    grep -oE 'typedef[^;{}]*;' "$tmp/flat" | normalise | sed 's/^/type /'
    # enum constants: their values from the compiler
    grep -oE '\bDEMILL_[A-Z0-9_]+[[:space:]]*=' "$tmp/flat" | sed -E 's/[[:space:]]*=$//' |
        sort -u > "$tmp/names"
    {
        echo '#include <stdio.h>'
        echo '#include <demill.h>'
        echo 'int main(void) {'
        sed 's/.*/    printf("constant &=%lld\\n", (long long)(&));/' "$tmp/names"
        echo '    return 0; }'
    } > "$tmp/constants.c"
    "$cc" -std=c99 -I"$include_dir" -o "$tmp/constants" "$tmp/constants.c"
    "$tmp/constants"
} | LC_ALL=C sort -u > "$tmp/current"

if [ ! -s "$tmp/current" ] || ! grep -q '^function ' "$tmp/current"; then
    echo "FAIL: could not describe the interface" >&2
    exit 1
fi
touch "$baseline"
LC_ALL=C sort -u "$baseline" > "$tmp/baseline"
LC_ALL=C comm -23 "$tmp/baseline" "$tmp/current" > "$tmp/broken"
LC_ALL=C comm -13 "$tmp/baseline" "$tmp/current" > "$tmp/added"

if [ -s "$tmp/broken" ]; then
    echo "FAIL: the interface of the 0.x series changed; these baseline lines are gone" \
        "(removed, renamed, renumbered or changed):" >&2
    sed 's/^/    /' "$tmp/broken" >&2
    echo "Extend the API instead of changing it (docs/api.md, Versions and compatibility)." >&2
    exit 1
fi
if [ -s "$tmp/added" ]; then
    if [ "$update" = "--update" ]; then
        cp "$tmp/current" "$baseline"
        echo "abi_guard: baseline updated with $(wc -l < "$tmp/added") additions"
        exit 0
    fi
    echo "FAIL: additions to the interface not yet in the baseline (accept them with" \
        "tests/api/abi_guard.sh build/libdemill.so --update, and commit the baseline):" >&2
    sed 's/^/    /' "$tmp/added" >&2
    exit 1
fi
echo "abi_guard: $(wc -l < "$tmp/current") lines of interface, as in the baseline"
