#!/usr/bin/env bash
# header_hygiene.sh INCLUDE_DIR
#
# Checks that every public header (demill.h and each demill/*.h) compiles on
# its own, as the first and only header of a translation unit, as strict C99
# and as C++11, with all warnings as errors:
#   gcc     -std=c99   -Wall -Wextra -Wpedantic -Werror -fsyntax-only
#   g++     -std=c++11 -Wall -Wextra -Wpedantic -Werror -fsyntax-only
# and the same with clang and clang++ when they are installed. The header is
# included twice, so a missing or broken include guard fails too. It also
# checks that each header declaring DEMILL_API functions has an extern "C"
# block (without it C++ mangles the names and fails to link; compiling alone
# cannot see that).
#
# Why: the library itself is built as C11 with the umbrella header, which
# hides a part header that relies on something included before it, on C11 or
# GNU extensions, or that warns in users' stricter builds. The API promises
# C99 and C++ callers (see demill/common.h).
#
# Exits non-zero and lists every failing header and compiler.
set -eu

if [ $# -ne 1 ]; then
    echo "usage: $0 INCLUDE_DIR" >&2
    exit 2
fi
include_dir=$(cd "$1" && pwd)

tmp=$(mktemp -d "${TMPDIR:-/tmp}/demill-header-hygiene.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

headers=(demill.h)
for h in "$include_dir"/demill/*.h; do
    headers+=("demill/${h##*/}")
done
if [ ! -f "$include_dir/demill.h" ] || [ ${#headers[@]} -lt 2 ]; then
    echo "FAIL: no public headers found in $include_dir" >&2
    exit 1
fi

# compiler language standard
compilers=("gcc c c99" "g++ c++ c++11")
if command -v clang >/dev/null 2>&1; then compilers+=("clang c c99"); fi
if command -v clang++ >/dev/null 2>&1; then compilers+=("clang++ c++ c++11"); fi

failures=()
checked=0
for h in "${headers[@]}"; do
    tu="$tmp/tu_${h//\//_}"
    printf '#include <%s>\n#include <%s>\n' "$h" "$h" > "$tu.c"
    for entry in "${compilers[@]}"; do
        read -r cc lang std <<< "$entry"
        if "$cc" -x "$lang" -std="$std" -Wall -Wextra -Wpedantic -Werror -fsyntax-only \
                -I "$include_dir" "$tu.c" 2> "$tmp/err"; then
            checked=$((checked + 1))
        else
            echo "FAIL: $h with $cc -std=$std:" >&2
            sed 's/^/    /' "$tmp/err" >&2
            failures+=("$h ($cc -std=$std)")
        fi
    done
    if grep -q '^DEMILL_API' "$include_dir/$h" && ! grep -q 'extern "C"' "$include_dir/$h"; then
        echo "FAIL: $h declares DEMILL_API functions but has no extern \"C\" block" >&2
        failures+=("$h (no extern \"C\")")
    fi
done

if [ ${#failures[@]} -ne 0 ]; then
    echo "header_hygiene: ${#failures[@]} failure(s):" >&2
    printf '  - %s\n' "${failures[@]}" >&2
    exit 1
fi
echo "header_hygiene: ${#headers[@]} headers x ${#compilers[@]} compilers ($checked compilations) passed:" \
    "${compilers[*]%% *}"
