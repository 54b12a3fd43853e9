#!/usr/bin/env python3
"""The demill program (tools/demill/) on scenes/mill.yaml, cut short: 245
balls of 10 mm (1 kg) in the mill's drum, turning from t = 0.

- A run writes its files, one time-series row per 1 ms sample, and the
  power each size class draws adds up to the drum's power: summed over the
  samples, the classes' power (F.v_wall at every contact of the drum, by
  size) against the mean of the time series' drum.power (P = -T_z w, from
  the library) at the same instants. The two are the same sum, contact by
  contact, but the library's force is that of the step (its dashpots see
  the predicted velocity of velocity Verlet, docs/physics.md section 8) and
  the classes' that of the state at the end of the step
  (demill_contacts_read): 9e-5 apart measured, 1e-3 allowed. With 10 and
  20 mm balls each class draws a part.
- A restart from a checkpoint at 0.02 s run on to 0.04 s ends in the same
  checkpoint, byte for byte, as an unbroken run to 0.04 s (the library's
  checkpoints are bitwise); a restart with --set drum.speed_fraction=0.9
  turns the drum at 0.9 of its critical speed sqrt(2 g / (D - d)).
- A sweep of drum.speed_fraction=0.6,0.8 makes a folder per value and a
  table whose rows have those speeds.
- tests/scene/hopper.yaml, a small conical hopper, stops when it is empty
  (its first sample with no bead left in the hopper, before its 3 s limit):
  its outlet then holds all 300 beads of 4 mm and their mass, 300 rho pi
  d^3 / 6 (glass, 2500 kg/m^3), and the beads in the world never grew in
  number. tests/scene/rest.yaml, a ball dropped on a floor, stops when its
  count of wall contacts is steady: one, the ball resting, long before its
  5 s limit. Dropped from 5 mm above the floor, its particles.centre_y
  column is y0 - g t^2 / 2 until it lands at sqrt(2 h / g) = 0.032 s
  (velocity Verlet is exact under a constant force; 1e-12 m allowed).
- tests/scene/spring.yaml, a 0.3 kg body on a spring of 9720 N/m, swings
  at sqrt(k/m)/(2 pi) = 28.64789 Hz, measured over the zero crossings of its
  body.box.position_y column (velocity Verlet's frequency error (w dt)^2/24,
  Hairer, Lubich and Wanner 2003, Geometric numerical integration
  illustrated by the Stormer-Verlet method, is 1.4e-7 at dt = 1e-5 s; 1e-5
  allowed).
- A scene with an error runs nothing and writes no folder; nor does a
  sweep one of whose values is wrong (checked before the first runs).

usage: runner.py DEMILL SCENE WORK_DIR (the other scenes beside this file)"""

import csv
import math
import os
import shutil
import subprocess
import sys

from summary import read_summary

SHORT = ["--set", "particles.0.mass=1", "--set", "drum.start_time=0",
         "--set", "outputs.vtk_every=0"]


def run(demill, *args):
    subprocess.run([demill, "run", *args], check=True, stdout=subprocess.DEVNULL)



def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    at = lambda name: os.path.join(work, name)

    # a run, and the power by size class against the drum's
    run(demill, scene, *SHORT, "--set", "stop={time: 0.1}", "--out", at("one"))
    for name in ("scene.yaml", "mill.csv", "summary.txt", "checkpoint", "charge.png", "power.png"):
        assert os.path.getsize(os.path.join(at("one"), name)) > 0, f"{name} missing or empty"
    with open(os.path.join(at("one"), "mill.csv")) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 100, f"{len(rows)} rows, 100 samples of 1 ms in 0.1 s"
    s = read_summary(at("one"))
    assert int(s["particles"]) == 245, s["particles"]
    drum = sum(float(r["drum.power"]) for r in rows) / len(rows)
    classes = float(s["class_power_sum_W"])
    assert int(s["class_power_samples"]) == 100
    assert drum > 0.1, f"the drum draws {drum} W"
    assert abs(classes - drum) <= 1e-3 * drum, f"classes {classes} W, drum {drum} W"
    assert float(s["class_1_power_W"]) == 0, "no ball of 15 mm or more, yet power drawn"

    run(demill, scene, *SHORT, "--set", "stop={time: 0.1}", "--out", at("two"),
        "--set", "particles.0.sizes.classes=[[0.010, 0.5], [0.020, 0.5]]")
    s = read_summary(at("two"))
    p0, p1 = float(s["class_0_power_W"]), float(s["class_1_power_W"])
    assert p0 > 0 and p1 > 0, f"class powers {p0}, {p1}"
    assert abs(p0 + p1 - float(s["class_power_sum_W"])) <= 1e-5 * (p0 + p1)

    # restart: bitwise the unbroken run
    run(demill, scene, *SHORT, "--set", "stop={time: 0.02}", "--out", at("first"))
    run(demill, "--restart", os.path.join(at("first"), "checkpoint"), "--set", "stop.time=0.04",
        "--out", at("then"))
    run(demill, scene, *SHORT, "--set", "stop={time: 0.04}", "--out", at("whole"))
    with open(os.path.join(at("then"), "checkpoint"), "rb") as f:
        then = f.read()
    with open(os.path.join(at("whole"), "checkpoint"), "rb") as f:
        whole = f.read()
    assert then == whole, "the restarted run's checkpoint differs from the unbroken run's"
    run(demill, "--restart", os.path.join(at("first"), "checkpoint"), "--set", "stop.time=0.04",
        "--set", "drum.speed_fraction=0.9", "--out", at("faster"))
    s = read_summary(at("faster"))
    critical = math.sqrt(2 * 9.81 / (0.3 - 0.010))
    assert abs(float(s["critical_speed_rad_s"]) - critical) <= 1e-5 * critical
    assert abs(float(s["speed_rad_s"]) - 0.9 * critical) <= 1e-5 * critical, s["speed_rad_s"]

    # a sweep
    run(demill, scene, *SHORT, "--set", "stop={time: 0.005}", "--out", at("sweep"),
        "--set", "drum.speed_fraction=0.6,0.8")
    with open(os.path.join(at("sweep"), "sweep.csv")) as f:
        table = list(csv.DictReader(f))
    assert [r["drum.speed_fraction"] for r in table] == ["0.6", "0.8"], table
    assert [float(r["speed_fraction_critical"]) for r in table] == [0.6, 0.8]
    for v in ("0.6", "0.8"):
        assert os.path.exists(os.path.join(at("sweep"), f"drum.speed_fraction={v}", "summary.txt"))

    # stops: an emptied hopper, a steady count of contacts
    here = os.path.dirname(os.path.abspath(__file__))
    run(demill, os.path.join(here, "hopper.yaml"), "--out", at("hopper"))
    s = read_summary(at("hopper"))
    bead = 2500 * math.pi * 0.004 ** 3 / 6
    assert float(s["emptied_s"]) < 3 - 1e-9, f"not emptied: {s['emptied_s']}"
    assert int(s["outlet_0_particles"]) == 300, s["outlet_0_particles"]
    assert abs(float(s["outlet_0_mass_kg"]) - 300 * bead) <= 1e-5 * 300 * bead
    with open(os.path.join(at("hopper"), "flow.csv")) as f:
        count = [float(r["world.particle_count"]) for r in csv.DictReader(f)]
    assert all(b <= a for a, b in zip(count, count[1:])) and count[-1] == 0, count[-5:]
    run(demill, os.path.join(here, "rest.yaml"), "--out", at("rest"))
    s = read_summary(at("rest"))
    assert s["steady"] == "yes" and float(s["steady_mean"]) == 1, s
    assert float(s["simulated_s"]) < 1, s["simulated_s"]
    # the same ball falling, before it touches: its centre of mass
    run(demill, os.path.join(here, "rest.yaml"), "--out", at("fall"), "--set",
        "outputs={every: 1e-3, csv: fall.csv, columns: [world.time, particles.centre_y]}",
        "--set", "stop={time: 0.03}")
    with open(os.path.join(at("fall"), "fall.csv")) as f:
        for r in csv.DictReader(f):
            t = float(r["world.time"])
            want = 0.015 - 0.5 * 9.81 * t * t
            assert abs(float(r["particles.centre_y"]) - want) < 1e-12, (t, r, want)

    # a body on a spring
    run(demill, os.path.join(here, "spring.yaml"), "--out", at("spring"))
    with open(os.path.join(at("spring"), "box.csv")) as f:
        rows = [(float(r["world.time"]), float(r["body.box.position_y"]) - 0.001)
                for r in csv.DictReader(f)]
    crossings = [t0 + (t1 - t0) * -y0 / (y1 - y0) for (t0, y0), (t1, y1) in zip(rows, rows[1:])
                 if (y0 < 0) != (y1 < 0)]
    f = (len(crossings) - 1) / (2 * (crossings[-1] - crossings[0]))
    want = math.sqrt(9720 / 0.3) / (2 * math.pi)
    assert len(crossings) >= 10 and abs(f - want) <= 1e-5 * want, f"{f} Hz, {want} Hz analytic"

    # an error: a message naming the file, the line and the key; nothing runs
    bad = at("bad.yaml")
    with open(scene) as f, open(bad, "w") as g:
        g.write(f.read().replace("density: 7800", "density: heavy"))
    p = subprocess.run([demill, "run", bad, "--out", at("bad")], capture_output=True, text=True)
    assert p.returncode != 0
    line = next(k + 1 for k, text in enumerate(open(bad)) if "heavy" in text)
    want = f"{bad}:{line}: materials.steel.density: expected a number > 0 kg/m^3, got 'heavy'"
    assert want in p.stderr, p.stderr
    assert not os.path.exists(at("bad")), "a bad scene made its output folder"
    p = subprocess.run([demill, "run", scene, *SHORT, "--set", "stop={time: 0.005}",
                        "--set", "drum.speed_fraction=0.5,200",
                        "--out", at("bad-sweep")], capture_output=True, text=True)
    assert p.returncode != 0 and "--set drum.speed_fraction: expected a number in [-100, 100], " \
        "got '200'" in p.stderr, p.stderr
    assert not os.path.exists(at("bad-sweep")), "a sweep with a bad value ran"
    print("runner: run, power by size class, restart, sweep and error checked")


if __name__ == "__main__":
    main()
