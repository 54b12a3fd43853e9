#!/usr/bin/env python3
"""scenes/repose.yaml reduced (docs/scenes.md, The angle of repose): 300
beads in a tube of 12 mm radius, so that their column still stands some 9
diameters high, lifted as in the scene.

- Without friction between the beads (pairs.0.friction=0 and
  pairs.0.rolling_friction=0) the heap flattens: its angle of repose is
  below 8 degrees. Frictionless spheres still pile a little: Peyneau and
  Roux (2008), Frictionless bead packs have macroscopic friction, but no
  dilatancy (Physical Review E 78, 011307), measure a macroscopic friction
  coefficient of about 0.1 for them, atan(0.1) = 5.7 degrees; 8 allows for
  the fit over a heap a few beads high.
- With the scene's friction (sliding 0.5, rolling 0.05) the angle is at
  least 10 degrees larger: sliding and rolling friction raise the angle of
  repose (Zhou, Xu, Yu and Zulli 2001, Numerical investigation of the angle
  of repose of monosized spheres, Physical Review E 64, 021301).
- Both heaps are still when measured (no bead faster than 20 mm/s) and
  repose.png is drawn.

usage: repose.py DEMILL SCENE WORK_DIR"""

import os
import shutil
import subprocess
import sys

from summary import read_summary

REDUCED = ["--set", "particles.0.count=300", "--set", "walls.1.cylinder.radius=0.012",
           "--set", "particles.0.region={cylinder: [0, 0.002, 0, 0, 0.17, 0, 0.010]}"]


def run(demill, scene, out, extra):
    subprocess.run([demill, "run", scene, "--out", out] + REDUCED + extra, check=True,
                   stdout=subprocess.DEVNULL)
    s = read_summary(out)
    assert os.path.getsize(os.path.join(out, "repose.png")) > 0, "no repose.png"
    assert float(s["repose_fastest_m_s"]) < 0.02, s["repose_fastest_m_s"]
    print(f"{out}: angle {s['repose_angle_deg']} deg over {s['repose_fit_points']} points, "
          f"heap {float(s['repose_height_m']) * 1e3:.1f} mm high at t = {s['simulated_s']} s, "
          f"fastest bead {s['repose_fastest_m_s']} m/s")
    return float(s["repose_angle_deg"])


def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    flat = run(demill, scene, os.path.join(work, "frictionless"),
               ["--set", "pairs.0.friction=0", "--set", "pairs.0.rolling_friction=0"])
    rough = run(demill, scene, os.path.join(work, "friction"), [])
    assert flat < 8, f"frictionless heap at {flat} deg"
    assert rough >= flat + 10, f"{rough} deg with friction against {flat} without"
    print("repose scene: ok")


if __name__ == "__main__":
    main()
