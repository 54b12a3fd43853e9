#!/usr/bin/env python3
"""scenes/clump-mill.yaml reduced (docs/scenes.md, clump-mill.yaml): 1 kg of
its rocks, the drum turning from t = 0, run for 30 ms.

- The rock's template is read from examples/rock/rock.stl at the scene's
  scale: its mesh volume in the summary is the volume the file's triangles
  enclose, computed here from the file by the divergence theorem (the sum
  of the signed tetrahedra from the origin to each triangle) times the
  scale cubed, to 1e-12.
- The charge is whole clumps: the fill by mass gives the nearest whole
  number of clumps to 1 kg, and the charge's mass (the clumps' masses
  summed over the world, each clump once) is that count times the
  template's mass, to 1e-12; mass_kg, the summary's charge, is the same
  (each of a clump's spheres reads its whole clump's mass, so a sum over
  the spheres would give 6 times as much).
- A restart from the checkpoint at 15 ms run on to 30 ms ends in the same
  checkpoint, byte for byte, as the unbroken run (the library's checkpoints
  keep the templates, with their fit, and the clumps bit for bit); its
  summary reports the checkpoint's template and clumps.

usage: clump_mill.py DEMILL SCENE WORK_DIR"""

import os
import re
import shutil
import subprocess
import sys

from summary import read_summary

REDUCED = ["--set", "particles.0.mass=1", "--set", "drum.start_time=0",
           "--set", "outputs.vtk_every=0", "--set", "outputs.pictures=[]"]


def run(demill, *args):
    subprocess.run([demill, "run", *args], check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL)



def stl_volume(path):
    """The volume an ASCII STL file's closed mesh encloses, in its units cubed."""
    with open(path) as f:
        v = [tuple(map(float, m.groups())) for m in
             re.finditer(r"vertex\s+(\S+)\s+(\S+)\s+(\S+)", f.read())]
    assert v and len(v) % 3 == 0, path
    total = 0.0
    for k in range(0, len(v), 3):
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = v[k:k + 3]
        total += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)
    return total / 6.0


def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    at = lambda name: os.path.join(work, name)
    run(demill, scene, "--out", at("whole"), *REDUCED, "--set", "stop={time: 0.03}")
    s = read_summary(at("whole"))

    with open(scene) as f:
        text = f.read()
    stl = re.search(r"stl: \{file: (\S+), scale: (\S+),", text)
    scale = float(stl.group(2))
    mesh = stl_volume(os.path.join(os.path.dirname(scene), stl.group(1))) * scale ** 3
    got = float(s["template_rock_mesh_volume_m3"])
    print(f"rock: mesh volume {got:.10e} m^3, from the file {mesh:.10e} m^3")
    assert abs(got / mesh - 1) < 1e-12, (got, mesh)

    m, n = float(s["template_rock_mass_kg"]), int(s["template_rock_clumps"])
    assert n == int(s["clumps"]) and n == round(1 / m), (n, s["clumps"], 1 / m)
    charge = float(s["clumps_mass_kg"])
    print(f"charge: {n} clumps of {m * 1e3:.4f} g, {charge:.12f} kg; {s['particles']} spheres")
    assert abs(charge / (n * m) - 1) < 1e-12, (charge, n * m)
    assert int(s["particles"]) == n * int(s["template_rock_spheres"]), s["particles"]
    assert abs(float(s["mass_kg"]) / charge - 1) < 1e-5, (s["mass_kg"], charge)

    run(demill, scene, "--out", at("first"), *REDUCED, "--set", "stop={time: 0.015}")
    run(demill, "--restart", os.path.join(at("first"), "checkpoint"), "--set", "stop.time=0.03",
        "--out", at("then"))
    with open(at("then/checkpoint"), "rb") as f:
        then = f.read()
    with open(at("whole/checkpoint"), "rb") as f:
        whole = f.read()
    assert then == whole, "the restarted run's checkpoint differs from the unbroken run's"
    r = read_summary(at("then"))
    assert r["clumps"] == s["clumps"] and r["clumps_mass_kg"] == s["clumps_mass_kg"], r
    assert r["template_rock_fit_volume_error"] == s["template_rock_fit_volume_error"], r
    assert "template_rock_clumps" not in r, "a restart cannot know the fills' counts"
    print("clump mill: mesh volume, charge and restart checked")


if __name__ == "__main__":
    main()
