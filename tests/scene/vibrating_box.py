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

usage: vibrating_box.py DEMILL SCENE WORK_DIR"""

import csv
import math
import os
import shutil
import subprocess
import sys

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


def main():
    demill, scene, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    particles = 2000 * 2700 * math.pi * 0.002 ** 3 / 6
    sweep(demill, scene, os.path.join(work, "empty"), 0.3)
    sweep(demill, scene, os.path.join(work, "loaded"), 0.3 + particles)
    print("vibrating box: ok")


if __name__ == "__main__":
    main()
