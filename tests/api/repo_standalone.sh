#!/usr/bin/env bash
# repo_standalone.sh SOURCE_DIR
#
# Checks that the repository stands alone: no file in it refers to documents
# a user of the library does not have. The project's definitions and sources
# were once kept in private notes (a physics reference, a scenes file, a
# style guide, numbered source documents in a folder beside the repository);
# everything users need now lives in docs/ (docs/physics.md, docs/scenes.md,
# docs/design.md), and formulas cite their published sources by author, year
# and title. This test fails when any file names one of those notes again:
#   SCENES.md, STYLE.md, PHYSICS.md  (upper case; docs/scenes.md and
#                                     docs/physics.md are the public pages)
#   ../shared or /work/shared         (the folder they were kept in)
#   "seed NNN", "seeds NNN"           (the numbered source documents, 000-099;
#                                     random seeds such as 1, 42 or 12345 do
#                                     not match)
# It reads the files git tracks (binary files skipped), or, outside a git
# checkout, every file under SOURCE_DIR but build*/ and .git/. This script is
# the one file allowed to name the patterns.
#
# Exits non-zero and lists every offending line.
set -eu

if [ $# -ne 1 ]; then
    echo "usage: $0 SOURCE_DIR" >&2
    exit 2
fi
src=$(cd "$1" && pwd)
self=tests/api/repo_standalone.sh

exact='SCENES\.md|STYLE\.md|PHYSICS\.md|(\.\./|/work/)shared\b'
numbered='\bseeds? 0[0-9]{2}\b'

if git -C "$src" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    search() { git -C "$src" grep -n -I -E "$@" -- . ":(exclude)$self" || true; }
else
    search() {
        (cd "$src" && grep -r -n -I -E --exclude-dir='build*' --exclude-dir=.git "$@" . |
            grep -v "^\./$self:" || true)
    }
fi

hits=$( { search "$exact"; search -i "$numbered"; } | sort -u)
if [ -n "$hits" ]; then
    echo "FAIL: these lines refer to documents that are not part of the repository;" >&2
    echo "move what users need into docs/ and cite published sources instead:" >&2
    echo "$hits" >&2
    exit 1
fi
echo "OK: no references to documents outside the repository"
