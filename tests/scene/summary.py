"""summary.txt of a demill run as a dict of its texts, shared by the scene
checks: each line KEY = VALUE."""

import os


def read_summary(folder):
    """The summary.txt in a folder (or a file of its KEY = VALUE lines, such
    as a sweep's shear_box.txt) as {key: text}."""
    path = folder if os.path.isfile(folder) else os.path.join(folder, "summary.txt")
    s = {}
    with open(path) as f:
        for line in f:
            key, _, value = line.strip().partition(" = ")
            s[key] = value
    return s
