#!/usr/bin/env python3
"""scenes/shear-box.yaml reduced (docs/scenes.md, The shear box): 1000
spheres of 44 mm instead of 2000 of 35 mm, 50 mm of shear at 0.1 m/s
instead of 70 mm at 0.05 m/s, swept over the three normal loads of the
full run.

- Each lid is at rest under its load: the particles' force on it is the
  load plus its weight, (F + m g) / A, within 1 % (Newton's second law
  for a body at rest; the numbers are the scene's, not the summary's).
- The sweep-level Mohr-Coulomb lines of shear_box.txt are the
  least-squares lines through the runs' (sigma, tau) points, recomputed
  here from the runs' summaries.
- The residual friction angle is above the contact friction angle,
  atan 0.5 = 26.57 degrees: the bed's strength is its particles' sliding
  friction and the work of lifting them over one another, so that its
  friction angle exceeds the contact's (Rowe 1962, The stress-dilatancy
  relation for static equilibrium of an assembly of particles in contact,
  Proc. Royal Society A 269, 500-527: phi_f > phi_mu at the critical
  state).
- The peak friction angle is not below the residual one, and each run's
  peak shear stress is not below its residual.

usage: shear_box.py DEMILL SCENE WORK_DIR"""

import math
import os
import shutil
import subprocess
import sys

from summary import read_summary

LOADS = [6835, 13670, 27340]  # N: 25, 50 and 100 kPa on the box's 0.27340 m^2
LID_MASS, AREA, G, MU = 50.0, 0.27340, 9.81, 0.5



def fit(sig, tau):
    n = len(sig)
    sx, sy = sum(sig), sum(tau)
    sxx, sxy = sum(x * x for x in sig), sum(x * y for x, y in zip(sig, tau))
    slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
    return math.degrees(math.atan(slope)), (sy - slope * sx) / n


def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    sets = ["particles.0.count=1000", "particles.0.sizes={normal: [0.044, 0.004, 0.038, 0.050]}",
            "walls.0.motion.velocity=[0.1, 0, 0]",
            "walls.1.motion.velocity=[0.1, 0, 0]", "walls.2.motion.velocity=[0.1, 0, 0]",
            "stop.time=1.0",
            "bodies.lid.load.force.1=" + ",".join(str(-f) for f in LOADS)]
    cmd = [demill, "run", scene, "--out", work]
    for s in sets:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    box = read_summary(os.path.join(work, "shear_box.txt"))
    for name in ("shear_stress.png", "mohr_coulomb.png"):
        assert os.path.getsize(os.path.join(work, name)) > 0, f"no {name}"
    sig, peak, res = [], [], []
    for k, load in enumerate(LOADS):
        s = read_summary(os.path.join(work, box[f"run_{k}"], "summary.txt"))
        sigma = float(s["normal_stress_Pa"])
        expected = (load + LID_MASS * G) / AREA
        print(f"load {load} N: normal stress {sigma:.1f} Pa (lid at rest: {expected:.1f}), "
              f"peak {float(s['peak_shear_stress_Pa']):.1f} Pa at "
              f"{1e3 * float(s['peak_displacement_m']):.1f} mm, residual "
              f"{float(s['residual_shear_stress_Pa']):.1f} Pa")
        assert abs(sigma / expected - 1) < 0.01, (sigma, expected)
        assert float(s["shear_displacement_m"]) > 0.049, s["shear_displacement_m"]
        sig.append(sigma)
        peak.append(float(s["peak_shear_stress_Pa"]))
        res.append(float(s["residual_shear_stress_Pa"]))
        assert peak[-1] >= res[-1], (peak[-1], res[-1])
    phi_p, c_p = fit(sig, peak)
    phi_r, c_r = fit(sig, res)
    print(f"Mohr-Coulomb: peak {phi_p:.2f} deg (c {c_p:.0f} Pa), residual {phi_r:.2f} deg "
          f"(c {c_r:.0f} Pa); contact friction atan {MU} = {math.degrees(math.atan(MU)):.2f} deg")
    assert abs(float(box["peak_friction_deg"]) - phi_p) < 1e-3, (box["peak_friction_deg"], phi_p)
    assert abs(float(box["residual_friction_deg"]) - phi_r) < 1e-3, (box["residual_friction_deg"], phi_r)
    assert abs(float(box["peak_cohesion_Pa"]) - c_p) <= 1e-4 * max(1, abs(c_p)), (box, c_p)
    assert abs(float(box["residual_cohesion_Pa"]) - c_r) <= 1e-4 * max(1, abs(c_r)), (box, c_r)
    assert phi_r > math.degrees(math.atan(MU)), f"residual {phi_r} deg not above atan {MU}"
    assert phi_p >= phi_r, (phi_p, phi_r)
    print("shear box scene: ok")


if __name__ == "__main__":
    main()
