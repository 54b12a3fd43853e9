"""outputs.py: reading what the example programs write, for their tests
(mill_ore.py, hopper.py): the "key = value" lines of a summary.txt, and the
signature of a PNG file."""


def read_summary(path):
    """The summary's values by key, as strings."""
    summary = {}
    with open(path) as f:
        for line in f:
            key, value = line.split(" = ")
            summary[key] = value.strip()
    return summary


def assert_png(path):
    """Fails unless the file starts with the PNG signature."""
    with open(path, "rb") as f:
        assert f.read(8) == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
