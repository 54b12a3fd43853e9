#!/usr/bin/env bash
# install_python.sh SRC_DIR BUILD_DIR PYTHON
#
# Checks the Python package as a user installs it, outside the source tree:
#   * the library and the demill program installed with `cmake --install`;
#   * `pip install ./python` into a virtual environment made by PYTHON
#     (Debian's, with python3-venv; --system-site-packages for NumPy), offline:
#     the build's only requirement, setuptools, comes from the wheel Debian's
#     python3-setuptools-whl puts in /usr/share/python-wheels;
#   * from a folder outside the tree, `import demill` loads the installed
#     library (found through LD_LIBRARY_PATH, as ldconfig finds one installed
#     system-wide), demill.scene_program() is the installed program, and
#     demill.run_scene() runs scenes/hopper.yaml for 2 ms: its summary has the
#     2500 beads of 6 mm and 2500 kg/m³ the scene file gives (0.70686 kg,
#     2500 · 4/3 π (3 mm)³ · 2500 kg/m³), and a bad key raises
#     demill.SceneError naming it.
# Everything goes into a temporary directory removed on exit.
set -eu

if [ $# -ne 3 ]; then
    echo "usage: $0 SRC_DIR BUILD_DIR PYTHON" >&2
    exit 2
fi
src_dir=$(cd "$1" && pwd)
build_dir=$(cd "$2" && pwd)
python=$3

tmp=$(mktemp -d "${TMPDIR:-/tmp}/demill-install-python.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix="$tmp/prefix"

echo "== install $build_dir into $prefix"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null
libdir=$(dirname "$(find "$prefix" -name 'libdemill.so.0' | head -n 1)")
[ -x "$prefix/bin/demill" ] || { echo "FAIL: $prefix/bin/demill not installed" >&2; exit 1; }

echo "== pip install ./python into a virtual environment"
"$python" -m venv --system-site-packages "$tmp/env"
# pip builds in the source folder: a copy keeps the tree clean
cp -r "$src_dir/python" "$tmp/python"
"$tmp/env/bin/pip" install --no-index --find-links /usr/share/python-wheels "$tmp/python"

echo "== run a scene from Python"
mkdir "$tmp/work"
cd "$tmp/work"
system_copy=0
if /sbin/ldconfig -p 2>/dev/null | grep -q 'libdemill\.so'; then
    system_copy=1
fi
LD_LIBRARY_PATH="$libdir" DEMILL_SYSTEM_COPY=$system_copy DEMILL_PREFIX="$prefix" \
    DEMILL_SCENE="$src_dir/scenes/hopper.yaml" "$tmp/env/bin/python" - <<'PY'
import math
import os
import demill

prefix = os.path.realpath(os.environ["DEMILL_PREFIX"])
assert "site-packages" in demill.__file__, demill.__file__
lib = os.path.realpath(demill.scene.__dict__["_library_file"]())
if os.environ["DEMILL_SYSTEM_COPY"] == "0":
    assert lib.startswith(prefix + os.sep), f"loaded {lib}, not the install's"
    assert demill.scene_program() == os.path.join(prefix, "bin", "demill"), demill.scene_program()
s = demill.run_scene(os.environ["DEMILL_SCENE"], out="hopper",
                     set={"stop": "{time: 0.002}", "outputs.vtk_every": 0}, quiet=True)
mass = 2500 * 4 / 3 * math.pi * 0.003**3 * 2500
assert s["particles"] == 2500, s["particles"]
assert abs(s["mass_kg"] - mass) < 1e-5 * mass, (s["mass_kg"], mass)
assert 0.002 <= s["simulated_s"] < 0.003, s["simulated_s"]
try:
    demill.run_scene(os.environ["DEMILL_SCENE"], out="bad", set={"stop.tim": 1}, quiet=True)
    raise AssertionError("a bad key ran")
except demill.SceneError as e:
    assert "stop.tim" in e.message and e.returncode != 0, e.message
print(f"install_python: demill {demill.version()} from {lib}; the hopper ran "
      f"{s['steps']} steps, {s['mass_kg']} kg")
PY
echo "install_python: all checks passed"
