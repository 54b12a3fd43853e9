#!/usr/bin/env python3
"""scenes/vibrating-box.yaml reduced: the box without its particles, a
damper of c = 5.4 N s/m beside its spring (damping ratio 0.05), a time step
of 2e-5 s, 1 s run and the amplitude taken over the last 0.3 s (the
transient has decayed by exp(-c t / 2m) < 2e-3 by then), in two frequency
sweeps through --set:

- the box alone (m = 0.3 kg), about its natural frequency
  sqrt(k/m)/(2 pi) = 28.648 Hz;
- the box carrying the particles' mass as a rigid mass, m = 0.3 kg +
  2000 rho pi d^3 / 6 = 0.3226 kg (aluminium, 2700 kg/m^3, d = 2 mm), about
  sqrt(k/m)/(2 pi) = 27.63 Hz.

At every frequency the box's amplitude is the driven damped oscillator's
steady one, F0 / sqrt((k - m w^2)^2 + (c w)^2) with F0 = 9.72 N and k =
9720 N/m (any text on vibrations, e.g. Den Hartog 1956, Mechanical
Vibrations), within 1 %; and of 0.9, 1 and 1.1 times the natural
frequency, the natural one gives the largest amplitude (the resonance).

Then the box with 300 of its particles, softened to E = 0.7 GPa (a time
step of 7.4e-7 s), forced at 28 Hz for 40 ms: outputs.dissipation's shares
over the last 20 ms sum to 1, and the energy the contacts dissipated
(dissipated_J) is the loss the energy balance gives, computed here from the
energy account's terms in the time series at the window's first and last
samples: the work of the forcing less the change of the kinetic, elastic
and potential energies of the particles, the contacts and the box. Within
1 % of the dissipated energy (3e-4 measured: the integration's error; the
work put in is 360 times larger).

usage: vibrating_box.py DEMILL SCENE WORK_DIR"""

import csv
import math
import os
import shutil
import subprocess
import sys

from summary import read_summary

K, F0, C = 9720.0, 9.72, 5.4


def sweep(demill, scene, out, mass):
    fn = math.sqrt(K / mass) / (2 * math.pi)
    freqs = [0.9 * fn, fn, 1.1 * fn]
    subprocess.run([demill, "run", scene, "--out", out, "--set", "particles=[]",
                    "--set", "world.time_step=2e-5", "--set", "stop.time=1",
                    "--set", "outputs.amplitude.window=0.3", "--set", "outputs.every=2e-4",
                    "--set", f"bodies.box.mass={mass!r}",
                    "--set", f"bodies.box.springs.0.damping={C}",
                    "--set", "bodies.box.force.frequency=" + ",".join(f"{f:.6f}" for f in freqs)],
                   check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "sweep.csv")) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 3, rows
    amps = []
    for r in rows:
        f = float(r["bodies.box.force.frequency"])
        w = 2 * math.pi * f
        want = F0 / math.hypot(K - mass * w * w, C * w)
        got = float(r["amplitude_body.box.position_x"])
        print(f"m = {mass:.5f} kg, f = {f:.4f} Hz: amplitude {got:.6e} m, "
              f"analytic {want:.6e} m ({got / want - 1:+.2e})")
        assert abs(got / want - 1) < 0.01, (f, got, want)
        amps.append(got)
    assert amps[1] > amps[0] and amps[1] > amps[2], f"no resonance at {fn} Hz: {amps}"
    print(f"resonance at {fn:.4f} Hz")


def dissipation(demill, scene, out):
    stored = ["kinetic_translational", "kinetic_rotational", "potential", "elastic_normal",
              "elastic_tangential", "elastic_rolling", "body_kinetic", "body_elastic",
              "body_potential"]
    columns = ["world.time", "energy.body_work", "energy.body_dissipated", "energy.dissipated"]
    columns += ["energy." + name for name in stored]
    subprocess.run([demill, "run", scene, "--out", out, "--set", "particles.0.count=300",
                    "--set", "materials.aluminium.youngs_modulus=7e8",
                    "--set", "bodies.box.force.frequency=28", "--set", "stop.time=0.04",
                    "--set", "outputs.amplitude.window=0.02",
                    "--set", "outputs.dissipation.window=0.02",
                    "--set", "outputs.columns=[" + ", ".join(columns) + "]"],
                   check=True, stdout=subprocess.DEVNULL)
    s = read_summary(out)
    shares = {k: float(v) for k, v in s.items() if k.startswith("dissipation_share_")}
    assert len(shares) == 7, shares
    assert abs(sum(shares.values()) - 1) < 1e-5, shares
    with open(os.path.join(out, "box.csv")) as f:
        rows = [r for r in csv.DictReader(f)
                if float(r["world.time"]) >= float(s["dissipation_from_s"]) - 1e-6]
    first, last = rows[0], rows[-1]  # the summary prints its times to 6 digits; samples are 1e-4 s apart
    assert abs(float(first["world.time"]) - float(s["dissipation_from_s"])) < 1e-6, first
    assert abs(float(last["world.time"]) - float(s["dissipation_to_s"])) < 1e-6, last

    def change(name):
        return float(last["energy." + name]) - float(first["energy." + name])

    work = change("body_work")
    loss = work - change("body_dissipated") - sum(change(name) for name in stored)
    dissipated = float(s["dissipated_J"])
    print(f"28 Hz, 300 particles: shares {shares}; dissipated {dissipated:.6e} J, the balance's "
          f"loss {loss:.6e} J ({dissipated / loss - 1:+.2e}), work put in {work:.6e} J")
    assert abs(change("dissipated") - dissipated) <= 1e-5 * dissipated, change("dissipated")
    assert dissipated > 0 and abs(dissipated / loss - 1) < 0.01, (dissipated, loss)


def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    particles = 2000 * 2700 * math.pi * 0.002 ** 3 / 6
    sweep(demill, scene, os.path.join(work, "empty"), 0.3)
    sweep(demill, scene, os.path.join(work, "loaded"), 0.3 + particles)
    dissipation(demill, scene, os.path.join(work, "dissipation"))
    print("vibrating box: ok")


if __name__ == "__main__":
    main()
