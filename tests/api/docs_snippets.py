#!/usr/bin/python3
"""docs_snippets.py SRC_DIR

Keeps the programs shown in the documentation the same as the files that
are built and run (examples/first.c, ...), so that what a reader copies
compiles. In README.md and docs/*.md, a fenced code block right after a line

    <!-- file: examples/first.c -->

(the path relative to the top of the source tree; the comment is invisible
on GitHub and in the Doxygen pages) must hold exactly that file's text.
Fails, with a diff, for a block that differs, a marker without a block
right after it, or a marker naming a file that does not exist.
"""
import difflib
import glob
import os
import re
import sys

MARKER = re.compile(r"^<!--\s*file:\s*(\S+)\s*-->\s*$")
FENCE = re.compile(r"^(```+|~~~+)")


def main():
    if len(sys.argv) != 2:
        print("usage: docs_snippets.py SRC_DIR", file=sys.stderr)
        return 2
    src = os.path.abspath(sys.argv[1])
    pages = [os.path.join(src, "README.md")] + sorted(glob.glob(os.path.join(src, "docs", "*.md")))
    problems, checked = [], 0
    for page in pages:
        if not os.path.exists(page):
            continue
        with open(page, encoding="utf-8") as f:
            lines = f.read().split("\n")
        rel = os.path.relpath(page, src)
        for i, line in enumerate(lines):
            m = MARKER.match(line)
            if not m:
                continue
            path = os.path.join(src, m.group(1))
            fence = FENCE.match(lines[i + 1]) if i + 1 < len(lines) else None
            if not fence:
                problems.append(f"{rel}:{i + 1}: the marker is not followed by a code block")
                continue
            end = next((k for k in range(i + 2, len(lines)) if lines[k].startswith(fence.group(1))), None)
            if end is None:
                problems.append(f"{rel}:{i + 2}: the code block is not closed")
                continue
            if not os.path.isfile(path):
                problems.append(f"{rel}:{i + 1}: {m.group(1)} does not exist")
                continue
            block = "\n".join(lines[i + 2:end]) + "\n"
            with open(path, encoding="utf-8") as f:
                text = f.read()
            checked += 1
            if block != text:
                diff = "".join(difflib.unified_diff(text.splitlines(True), block.splitlines(True),
                                                    m.group(1), f"{rel}:{i + 3}"))
                problems.append(f"{rel}:{i + 3}: the block differs from {m.group(1)}; "
                                f"copy the file into the page:\n{diff}")
    for p in problems:
        print("FAIL:", p, file=sys.stderr)
    if problems:
        return 1
    if checked == 0:
        print("FAIL: no <!-- file: ... --> blocks found", file=sys.stderr)
        return 1
    print(f"docs_snippets: {checked} code blocks are the same as their files")
    return 0


if __name__ == "__main__":
    sys.exit(main())
