#!/usr/bin/env python3
"""Every scene file shipped in scenes/ runs for a few steps: each is cut to
2 ms of simulated time (--set 'stop={time: 0.002}'; none of their other
stops comes first) and must run to it, writing summary.txt whose
simulated_s is that time or later by less than one sample (the run stops at
a sample: outputs.every, at most 1 ms in these scenes), with particles in
the world (at the start, or at the end for a scene a feed fills); the progress bar
of a scene without a drum shows no revolutions; every picture its
outputs.pictures names is drawn.

usage: shipped.py DEMILL SCENES_DIR WORK_DIR"""

import os
import re
import shutil
import subprocess
import sys

from summary import read_summary


def main():
    demill, scenes, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    names = sorted(n for n in os.listdir(scenes) if n.endswith(".yaml"))
    assert names, f"no scene in {scenes}"
    for name in names:
        out = os.path.join(work, name[:-5])
        with open(os.path.join(scenes, name)) as f:
            text = f.read()
        has_drum = any(line.startswith("drum:") for line in text.splitlines())
        pictures = [p.strip() for m in re.findall(r"^\s*pictures:\s*\[([^\]]*)\]", text, re.M)
                    for p in m.split(",")]
        run = subprocess.run([demill, "run", os.path.join(scenes, name), "--out", out,
                              "--set", "stop={time: 0.002}", "--set", "outputs.vtk_every=0"],
                             check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                             text=True)
        assert has_drum or "revolution" not in run.stderr, f"{name}: revolutions without a drum"
        s = read_summary(out)
        dt = float(s["time_step_s"])
        t = float(s["simulated_s"])
        assert 0.002 - 0.5 * dt <= t < 0.003, (name, t)
        assert int(s["particles"]) > 0 or int(s["particles_end"]) > 0, \
            (name, s["particles"], s["particles_end"])
        for p in pictures:
            assert os.path.getsize(os.path.join(out, p + ".png")) > 0, (name, p)
        print(f"{name}: {s['steps']} steps of {s['particles']} particles to "
              f"{s['simulated_s']} s")
    print(f"{len(names)} shipped scenes run")


if __name__ == "__main__":
    main()
