#!/usr/bin/env python3
"""scenes/silo.yaml reduced (docs/scenes.md, The silo): beads of 8 mm
instead of 5 mm, as deep a column, and a shorter run.

What the run measures in the zone of the column (outputs.janssen.zone):
the mobilised wall friction mu_w, the stress ratio K and the bulk density
rho_b. What is predicted from them, here and independently of the
summary's own prediction: Janssen's (1895), Versuche über Getreidedruck in
Silozellen, mean vertical stress at the floor, sigma_v(H) = rho_b g D /
(4 mu_w K) (1 - exp(-4 mu_w K H / D)), H the fill height, against the
stress the floor measures (its contact forces over its area), below the
zone: within 15 % (the band of docs/scenes.md). And:

- the floor carries far less than a liquid of the bulk density would,
  rho_b g H (the screening Janssen measured): under 0.7 of it;
- the column is at rest: the floor's force and the side's support add up
  to the particles' weight (the summary's mass times g) within 1 %
  (Newton's first law);
- mu_w is at most the pair's friction coefficient 0.3: every contact's
  tangential force is at most 0.3 times its normal force (Coulomb), so
  their sums are too.

usage: silo.py DEMILL SCENE WORK_DIR"""

import csv
import math
import os
import shutil
import subprocess
import sys

from summary import read_summary

D, G, MU_PAIR = 0.1, 9.81, 0.3
REDUCED = ["particles.0.sizes={normal: [0.008, 0.0004, 0.0072, 0.0088]}",
           "particles.0.count=5800", "walls.1.motion.velocity=[0, 0.004, 0]", "stop.time=1.0",
           "outputs.janssen.window=0.15"]


def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    cmd = [demill, "run", scene, "--out", work]
    for s in REDUCED:
        cmd += ["--set", s]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)
    s = read_summary(work)
    assert os.path.getsize(os.path.join(work, "silo.png")) > 0, "no silo.png"
    with open(os.path.join(work, "silo.csv")) as f:
        rows = list(csv.DictReader(f))

    mu, k = float(s["wall_friction_mobilised"]), float(s["stress_ratio_K"])
    rho, fill = float(s["bulk_density_kg_m3"]), float(s["fill_height_m"])
    floor = float(s["floor_stress_Pa"])
    assert 0.5 < rho / 2500 < 0.66, f"bulk density {rho}: not a bed of spheres"
    assert fill > 3 * D, f"filled {fill} m deep: not 3 diameters"
    assert len(rows) == math.ceil(fill / 0.01 - 0.5), (len(rows), fill)
    sat = rho * G * D / (4 * mu * k)
    pred = sat * (1 - math.exp(-4 * mu * k * fill / D))
    hydro = rho * G * fill
    print(f"mu_w {mu:.4f}, K {k:.4f}, rho_b {rho:.1f} kg/m^3, H {fill:.4f} m: Janssen's floor "
          f"stress {pred:.1f} Pa (saturation {sat:.1f}), the floor's {floor:.1f} Pa, ratio "
          f"{floor / pred:.4f}; hydrostatic {hydro:.1f} Pa")
    assert abs(float(s["janssen_floor_Pa"]) / pred - 1) < 1e-3, s["janssen_floor_Pa"]
    assert abs(floor / pred - 1) <= 0.15, f"floor {floor} against Janssen's {pred}: outside 15 %"
    assert floor < 0.7 * hydro, f"floor {floor} against the hydrostatic {hydro}: no screening"

    weight = float(s["mass_kg"]) * G
    assert abs(float(s["weight_N"]) / weight - 1) < 1e-6, (s["weight_N"], weight)
    balance = float(s["floor_force_N"]) + float(s["wall_support_N"])
    print(f"floor {s['floor_force_N']} N + side {s['wall_support_N']} N = {balance:.4f} N, "
          f"weight {weight:.4f} N")
    assert abs(balance / weight - 1) < 0.01, f"{balance} N against the weight {weight} N"
    assert 0 < mu <= MU_PAIR, f"mobilised wall friction {mu} above the pair's {MU_PAIR}"
    print("silo scene: ok")


if __name__ == "__main__":
    main()
