#!/usr/bin/env python3
"""mill --shape on a tiny, short case (a 0.1 m drum filled to 25 % with
the example's dumbbells, one revolution: about 3 s): the files exist, the
summary counts the clumps and their spheres, and the charge's mass is the
clumps' count times a dumbbell's mass from the lens formula (two steel
spheres of radius r whose centres are d = r apart: 2 (4/3) pi r^3 less
their lens, pi (4r + d)(2r - d)^2 / 12, at 7800 kg/m^3). A shape file with
a bad line, and --shape with --radius, are refused.

usage: mill_shape.py MILL SHAPE_FILE WORK_DIR"""

import math
import os
import subprocess
import sys

from outputs import assert_png, read_summary


def main():
    mill, shape, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, "out")
    small = ["--diameter", "0.1", "--length", "0.03", "--revolutions", "1", "--lifters", "4",
             "--lifter-height", "0.008", "--fill", "25", "--vtk-every", "0"]
    subprocess.run([mill, *small, "--shape", shape, "--out", out], check=True)
    summary = read_summary(os.path.join(out, "summary.txt"))
    for png in ("charge.png", "power.png"):
        assert_png(os.path.join(out, png))
    clumps, per = int(summary["clumps"]), int(summary["spheres_per_clump"])
    assert per == 2 and clumps > 0, summary
    assert int(summary["particles"]) == clumps * per, summary
    r = d = 0.005
    volume = 2 * 4 / 3 * math.pi * r ** 3 - math.pi * (4 * r + d) * (2 * r - d) ** 2 / 12
    want = clumps * 7800 * volume
    mass = float(summary["mass_kg"])
    assert abs(mass - want) <= 1e-5 * want, f"mass {mass} kg, {clumps} dumbbells weigh {want}"
    assert float(summary["mean_power_W"]) > 0, summary
    bad = os.path.join(work, "bad.txt")
    with open(bad, "w") as f:
        f.write("0 0 0 0.005\n0.005 0 0\n")
    for args in (["--shape", bad], ["--shape", shape, "--radius", "0.004"]):
        run = subprocess.run([mill, *small, *args, "--out", out], capture_output=True, text=True)
        assert run.returncode != 0, f"{args} was accepted"
    print(f"mill --shape: {clumps} dumbbells, {mass:.6g} kg against {want:.6g} kg")


if __name__ == "__main__":
    main()
