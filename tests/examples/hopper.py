#!/usr/bin/env python3
"""hopper (examples/hopper) on a short run: 400 beads of 6 mm and 0.15 s of
discharge (about 3 s), which leaves some in the hopper. Its files exist, and
mass is conserved: the mass in the hopper at the start is 400 beads of
rho pi d^3 / 6 (glass, 2500 kg/m3; the sphere's volume); at the end the
beads discharged and those still in the world add up to it, in number and
in mass; every row of discharge.csv has the mass of its count of beads (to
its 10 digits); the mass discharged never falls, and its last row is the
summary's total.

usage: hopper.py HOPPER WORK_DIR"""

import math
import os
import subprocess
import sys

from outputs import assert_png, read_summary


def main():
    hopper, work = sys.argv[1:3]
    os.makedirs(work, exist_ok=True)
    out = os.path.join(work, "out")
    subprocess.run([hopper, "--particles", "400", "--time-limit", "0.15", "--out", out],
                   check=True)
    summary = read_summary(os.path.join(out, "summary.txt"))
    assert_png(os.path.join(out, "hopper.png"))
    bead = 2500 * math.pi * 0.006 ** 3 / 6
    n0, m0 = int(summary["initial_particles"]), float(summary["initial_mass_kg"])
    assert n0 == 400, f"{n0} beads in the hopper, asked for 400"
    assert abs(m0 - 400 * bead) <= 1e-12 * m0, f"initial mass {m0!r} kg, 400 beads {400 * bead!r}"
    n_out, m_out = int(summary["discharged_particles"]), float(summary["discharged_mass_kg"])
    n_in, m_in = int(summary["remaining_particles"]), float(summary["remaining_mass_kg"])
    assert n_out > 0 and n_in > 0, f"{n_out} beads out, {n_in} in: the run should stop half-way"
    assert n_out + n_in == n0, f"{n_out} out + {n_in} in, {n0} at the start"
    assert abs(m_out + m_in - m0) <= 1e-12 * m0, f"{m_out!r} out + {m_in!r} in, {m0!r} at the start"
    with open(os.path.join(out, "discharge.csv")) as f:
        rows = [[float(x) for x in line.split(",")] for line in list(f)[1:]]
    for t, m, count in rows:
        assert abs(m - count * bead) <= 1e-9 * max(m, bead), f"t = {t}: {m!r} kg for {count} beads"
    assert all(a[1] <= b[1] for a, b in zip(rows, rows[1:])), "the discharged mass falls"
    assert abs(rows[-1][1] - m_out) <= 1e-9 * m_out, f"last row {rows[-1][1]!r} kg, summary {m_out!r}"
    print(f"hopper: {n_out} of {n0} beads out ({m_out:.6f} kg) and {n_in} in ({m_in:.6f} kg): "
          f"{m_out + m_in!r} kg of {m0!r}; rate {summary['steady_rate_kg_s']} kg/s")


if __name__ == "__main__":
    main()
