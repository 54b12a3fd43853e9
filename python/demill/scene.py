"""Running scene files from Python: :func:`run_scene`.

A scene file (YAML; docs/scene-files.md) describes a whole simulation. The
``demill`` program built and installed with the library runs it;
:func:`run_scene` runs that program, shows its progress on ``sys.stderr``
and returns what it wrote to ``summary.txt`` as a dict.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from ._lib import lib

__all__ = ["SceneError", "run_scene", "scene_program"]


class SceneError(Exception):
    """The ``demill`` program refused a scene or failed while running it.

    Attributes:
        returncode: the program's exit status.
        message: what it wrote to its standard error (a scene file's errors
            name the file, the line and the key).
    """

    def __init__(self, returncode, message):
        self.returncode = returncode
        self.message = message
        super().__init__(f"demill exited with status {returncode}:\n{message}")


def _library_file():
    """The file of the loaded libdemill: ``lib.path`` when it is a path, else
    the file the dynamic loader mapped for it."""
    if os.path.isabs(lib.path):
        return Path(lib.path).resolve()
    try:
        with open("/proc/self/maps") as maps:
            for line in maps:
                path = line.split(maxsplit=5)[-1].strip()
                if Path(path).name.startswith("libdemill.so"):
                    return Path(path).resolve()
    except OSError:
        pass
    return None


def scene_program():
    """The ``demill`` program :func:`run_scene` runs: the first of the
    environment variable ``DEMILL_PROGRAM``, the program installed with the
    loaded library (``bin/demill`` beside its ``lib`` folder), the program of
    the build tree the library comes from (``tools/demill/demill``), of a
    build tree of the checkout this package sits in (``build*/``, the newest)
    and ``demill`` on the ``PATH``.

    Raises:
        FileNotFoundError: none of them exists.
    """
    env = os.environ.get("DEMILL_PROGRAM")
    if env:
        return env
    tried, candidates = [], []
    found = _library_file()
    if found is not None:
        where = found.parent
        # lib/, lib64/ or lib/<multiarch>/ of an install; the build tree
        candidates += [p / "bin" / "demill" for p in list(where.parents)[:2]]
        candidates.append(where / "tools" / "demill" / "demill")
    root = Path(__file__).resolve().parent.parent.parent
    candidates += sorted(root.glob("build*/tools/demill/demill"), key=lambda p: p.stat().st_mtime,
                         reverse=True)
    for c in candidates:
        tried.append(str(c))
        if c.is_file() and os.access(c, os.X_OK):
            return str(c)
    on_path = shutil.which("demill")
    if on_path:
        return on_path
    raise FileNotFoundError(
        "the demill program was not found (tried " + ", ".join(tried + ["the PATH"]) +
        "); build it with `cmake --build build --target demill_runner`, install it with "
        "the library, or set DEMILL_PROGRAM to its path")


def _value(text):
    """A summary's value as an int, a float or, failing both, the text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _summary(folder):
    """summary.txt of a run's folder as a dict."""
    values = {}
    with open(Path(folder) / "summary.txt") as f:
        for line in f:
            key, sep, value = line.rstrip("\n").partition(" = ")
            if sep:
                values[key] = _value(value)
    return values


def _default_folder(scene, restart):
    """The folder the program writes to without --out: the scene file's name
    without .yaml in the current folder, or a restart's ``DIR/restart``."""
    if restart is not None:
        return Path(restart).parent / "restart"
    name = Path(scene).name
    return Path(name[:-5] if name.endswith(".yaml") and len(name) > 5 else name)


def _set_text(key, value):
    """One ``--set KEY=VALUE`` argument; a list or tuple of values is a sweep."""
    if isinstance(value, (list, tuple)):
        value = ",".join(str(v) for v in value)
    elif isinstance(value, bool):
        value = "true" if value else "false"
    return f"{key}={value}"


def run_scene(scene=None, out=None, set=None, restart=None, quiet=False, program=None):
    """Runs a scene file with the ``demill`` program
    (``demill run SCENE --out OUT --set KEY=VALUE ...``).

    Args:
        scene: the scene file's path (None with ``restart``).
        out: the folder the run writes to (the program's default, the
            scene's name in the current folder, if None).
        set: overrides, a dict ``{"drum.speed_fraction": 0.8}`` or a list of
            ``"KEY=VALUE"`` strings. A value that is a list (or a text with
            commas) runs a sweep: one run per value, each in
            ``OUT/KEY=VALUE``, and a table ``OUT/sweep.csv``.
        restart: a checkpoint written by an earlier run
            (``DIR/checkpoint``), to go on from with the overrides.
        quiet: True hides the program's progress, which otherwise goes to
            ``sys.stderr`` as it runs.
        program: the ``demill`` program to run (:func:`scene_program` if
            None).

    Returns:
        the run's ``summary.txt`` as a dict, numbers as ``int`` or
        ``float`` (``summary["mean_power_W"]``); for a sweep, a list of
        them, one per value in order, each with the key ``"sweep_value"``.

    Raises:
        SceneError: the program refused the scene (its message names the
            file, the line and the key) or the run failed.
        FileNotFoundError: no ``demill`` program was found.
    """
    if (scene is None) == (restart is None):
        raise ValueError("run_scene needs a scene file or a restart checkpoint, not both")
    sets = []
    if isinstance(set, dict):
        sets = [_set_text(k, v) for k, v in set.items()]
    elif set is not None:
        sets = [str(s) for s in set]
    args = [program or scene_program(), "run"]
    args += [os.fspath(scene)] if scene is not None else ["--restart", os.fspath(restart)]
    if out is not None:
        args += ["--out", os.fspath(out)]
    for s in sets:
        args += ["--set", s]
    tail = bytearray()
    with subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE) as proc:
        while True:
            chunk = proc.stderr.read1(4096)
            if not chunk:
                break
            tail += chunk
            del tail[:-16384]
            if not quiet:
                sys.stderr.write(chunk.decode(errors="replace"))
                sys.stderr.flush()
        stdout = proc.stdout.read().decode(errors="replace")
    if proc.returncode:
        raise SceneError(proc.returncode, tail.decode(errors="replace").strip())
    if not quiet and stdout:
        sys.stdout.write(stdout)
    if out is None:
        out = _default_folder(scene, restart)
    sweep = [s for s in sets if "," in s.partition("=")[2]
             and s.partition("=")[2][:1] not in "[{\"'"]
    if not sweep:
        return _summary(out)
    key, _, values = sweep[0].partition("=")
    runs = []
    for v in values.split(","):
        summary = _summary(Path(out) / f"{key}={v}")
        summary["sweep_value"] = _value(v)
        runs.append(summary)
    return runs
