#!/usr/bin/env bash
# docs_build.sh DOXYGEN DOXYFILE INCLUDE_DIR
#
# Builds the API reference as `cmake --build build --target docs` does
# (doxygen with the Doxyfile CMake configured from docs/Doxyfile.in) and
# fails on any warning: an undocumented function, macro, typedef or
# parameter, an @param naming no parameter, a broken reference or link. The
# Doxyfile sets WARN_AS_ERROR = FAIL_ON_WARNINGS, so doxygen's status says
# so too; this script also counts and lists the warnings, and checks that
# every public header (each *.h under INCLUDE_DIR) has its page in the
# reference: a header without a /** @file */ comment is silently left out.
#
# Without doxygen (DOXYGEN empty or *-NOTFOUND) the test is skipped (exit
# 77), except under CI (CI set and not "false"), where it fails: .ci/deps
# installs doxygen, so CI always builds the reference.
set -eu

if [ $# -ne 3 ]; then
    echo "usage: $0 DOXYGEN DOXYFILE INCLUDE_DIR" >&2
    exit 2
fi
doxygen=$1
doxyfile=$2
include_dir=$(cd "$3" && pwd)

if [ -z "$doxygen" ] || [ "${doxygen%NOTFOUND}" != "$doxygen" ] || ! command -v "$doxygen" >/dev/null; then
    if [ -n "${CI:-}" ] && [ "${CI:-}" != false ]; then
        echo "FAIL: doxygen not found (CI=$CI); .ci/deps installs it, then reconfigure" >&2
        exit 1
    fi
    echo "SKIP: doxygen not found (apt-get install doxygen, then reconfigure)"
    exit 77
fi

out_dir=$(cd "$(dirname "$doxyfile")" && pwd)
doxyfile="$out_dir/$(basename "$doxyfile")"
log="$out_dir/doxygen-warnings.log"
# Doxygen never removes pages: start afresh so that a stale page cannot
# stand in for a header that is no longer documented.
rm -rf "$out_dir/html"
echo "+ $doxygen $doxyfile   ($("$doxygen" --version))"
status=0
(cd "$out_dir" && "$doxygen" "$doxyfile") > /dev/null 2> "$log" || status=$?
warnings=$(grep -cE '(warning|error):' "$log" || true)
if [ "$status" -ne 0 ] || [ "$warnings" -ne 0 ] || [ -s "$log" ]; then
    cat "$log" >&2
    echo "FAIL: doxygen exited with status $status and $warnings warning(s)" \
        "(the rules are at the top of tests/api/docs_complete.py)" >&2
    exit 1
fi

html="$out_dir/html"
missing=()
[ -f "$html/index.html" ] || missing+=("index.html")
headers=0
while IFS= read -r h; do
    headers=$((headers + 1))
    name=${h#"$include_dir"/}
    # Doxygen's file page: demill/world.h -> world_8h.html
    page=$(basename "$name" | sed 's/_/__/g; s/\./_8/g').html
    if [ ! -f "$html/$page" ]; then
        missing+=("$name ($page)")
    fi
done < <(find "$include_dir" -name '*.h' | sort)
# A link to a page with an anchor (page.md#part) is left by Doxygen as a
# link to the .md file, dead in the HTML: link pages without one.
docs_dir=$(dirname "$include_dir")/docs
while IFS= read -r hit; do
    page=$(sed -E 's/.*\]\(([^)#]*)#.*/\1/' <<< "${hit#*:*:}")
    if [ -f "$docs_dir/$page" ]; then
        missing+=("${hit%%:*}:$(cut -d: -f2 <<< "$hit"): link $page without '#...' (Doxygen leaves it dead)")
    fi
done < <(cd "$docs_dir" && grep -noE '\]\([A-Za-z0-9_.-]+\.md#[^)]*\)' -- *.md || true)
if [ ${#missing[@]} -ne 0 ]; then
    echo "FAIL: not in the reference (a header needs a /** @file */ comment), or dead links:" >&2
    printf '  - %s\n' "${missing[@]}" >&2
    exit 1
fi
echo "docs_build: 0 warnings; $headers headers in the reference at $html/index.html"
