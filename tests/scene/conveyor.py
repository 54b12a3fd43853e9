#!/usr/bin/env python3
"""scenes/conveyor.yaml reduced (docs/scenes.md, The belt conveyor): the
feed's rate halved to 2 kg/s, 2.6 s of which the last second is taken as
steady (the first particles reach the outlet at 1.4 s).

- The momentum balance along the belt's motion x: the particles enter
  from the feed with no velocity along x, the chute and the belt push
  them, and they leave through the outlet, which they reach in free
  flight from the belt's end at the belt's speed v = 2 m/s (the scene's
  surface velocity; the belt is horizontal, so gravity has no part along
  x, and nothing else touches them). Steady, the belt's resistance is
  F = m' (v - v_in), m' the outlet's rate and v_in = F_chute / m' the
  velocity along x the chute gives them: the acceleration resistance of
  DIN 22101 (2011), Continuous conveyors - Belt conveyors for loose bulk
  materials - Basis for calculation and dimensioning. The belt's mean
  force from conveyor.csv is within 5 % of it (the band of
  docs/scenes.md), m' fitted here from the outlet's mass column, the
  belt's and the chute's forces the means of their samples (conveyor.csv,
  every 0.2 ms).
- Steady, what the feed puts in comes out: m' is within 5 % of the feed's
  2 kg/s.
- The summary's numbers are those of conveyor.csv, and the power is F v.

usage: conveyor.py DEMILL SCENE WORK_DIR"""

import csv
import os
import shutil
import subprocess
import sys

from summary import read_summary

RATE, SPEED, FROM, STOP = 2.0, 2.0, 1.6, 2.6


def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    subprocess.run([demill, "run", scene, "--out", work, "--set", f"feeds.0.mass_rate={RATE}",
                    "--set", f"stop={{time: {STOP}}}", "--set", f"outputs.conveyor.from={FROM}",
                    "--set", "outputs.vtk_every=0"],
                   check=True, stdout=subprocess.DEVNULL)
    s = read_summary(work)
    assert os.path.getsize(os.path.join(work, "conveyor.png")) > 0, "no conveyor.png"
    with open(os.path.join(work, "conveyor.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    window = [r for r in rows if r["time_s"] >= FROM - 1e-9]
    n = len(window)
    t = [r["time_s"] for r in window]
    m = [r["discharged_kg"] for r in window]
    tm, mm = sum(t) / n, sum(m) / n
    rate = sum((a - tm) * (b - mm) for a, b in zip(t, m)) / sum((a - tm) ** 2 for a in t)
    belt = sum(r["belt_force_N"] for r in window) / n
    chute = sum(r["chute_force_N"] for r in window) / n
    v_in = chute / rate
    balance = rate * (SPEED - v_in)
    print(f"{n} samples from {t[0]} to {t[-1]} s: outlet {rate:.4f} kg/s (feed {RATE}), "
          f"v_in {v_in:.4f} m/s, belt {belt:.4f} N against m'(v - v_in) = {balance:.4f} N, "
          f"ratio {belt / balance:.4f}")
    for key, value in [("mass_flow_kg_s", rate), ("belt_force_N", belt), ("chute_force_N", chute),
                       ("landing_velocity_m_s", v_in), ("momentum_balance_N", balance),
                       ("belt_power_W", belt * SPEED)]:
        assert abs(float(s[key]) - value) <= 1e-5 * abs(value), (key, s[key], value)
    assert abs(rate / RATE - 1) <= 0.05, f"outlet {rate} kg/s against the feed's {RATE}"
    assert abs(belt / balance - 1) <= 0.05, f"belt {belt} N against {balance} N: outside 5 %"
    print("conveyor scene: ok")


if __name__ == "__main__":
    main()
