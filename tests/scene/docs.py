#!/usr/bin/env python3
"""docs/scene-files.md holds the key tables exactly as `demill keys` prints
them from the parameter registry and the reader's own key lists, between its
markers, so that the page cannot drift from what the reader accepts.

usage: docs.py DEMILL DOCS_PAGE"""

import subprocess
import sys


def main():
    demill, page = sys.argv[1:3]
    keys = subprocess.run([demill, "keys"], check=True, capture_output=True, text=True).stdout
    text = open(page).read()
    begin, end = "<!-- demill keys: begin -->\n", "<!-- demill keys: end -->"
    assert begin in text and end in text, f"{page}: no {begin.strip()} ... {end} block"
    block = text[text.index(begin) + len(begin):text.index(end)]
    if block != keys:
        sys.exit(f"{page}: the key tables differ from `demill keys`; replace the block with its "
                 f"output:\n{keys}")
    print(f"docs: {len(keys.splitlines())} lines of key tables as `demill keys` prints them")


if __name__ == "__main__":
    main()
