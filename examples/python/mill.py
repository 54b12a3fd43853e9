#!/usr/bin/python3
"""The default mill of examples/mill, from Python: a 0.3 m x 0.1 m drum with
eight 15 mm lifters, 8.82 kg of steel balls of 5 mm radius (Hertz-Mindlin
contacts, restitution 0.5, friction 0.5), settled for 0.3 s at rest and
turned for two revolutions at 75 % of critical speed. Prints the mean power
draw over the last revolution, the toe and the shoulder as
build/examples/mill does, and plots the power draw against time.

    PYTHONPATH=python /usr/bin/python3 examples/python/mill.py --out power.png
"""

import argparse
import math
import sys
import time
from pathlib import Path

try:
    import demill
except ImportError:  # run from a source checkout without PYTHONPATH
    sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
    import demill

import numpy as np

SETTLE = 0.3              # s at rest before the drum turns
CHARGE_MASS = 10000 * 8.8216e-4  # kg: the drum3d charge
BALL_DIAMETER = 0.01      # m
SAMPLE = 1e-3             # s between samples of the power
VTK_EVERY = 0.1           # s between VTK frames (with --vtk)


def parse_args(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--revolutions", type=int, default=2, help="revolutions to run [2]")
    p.add_argument("--speed", type=float, default=75, help="speed, %% of critical [75]")
    p.add_argument("--time-step", type=float, default=1e-5, help="s [1e-5]")
    p.add_argument("--threads", type=int, default=1,
                   help="threads; the results are the same for any number [1]")
    p.add_argument("--out", default="mill_power.png", help="the plot [mill_power.png]")
    p.add_argument("--vtk", metavar="PREFIX",
                   help="also write VTK frames every 0.1 s for ParaView (PREFIX.pvd, ...)")
    args = p.parse_args(argv)
    if args.revolutions < 1:
        p.error("--revolutions must be at least 1")
    return args


def build(time_step, threads):
    """The world of examples/mill/scene.c with the default charge."""
    world = demill.World(3, time_step=time_step)
    steel = world.material(density=7800, youngs_modulus=1e8, poisson_ratio=0.3,
                           restitution=0.5, friction=0.5)
    world.pair(steel, steel, normal=demill.Normal.HERTZ, damping=demill.Damping.RESTITUTION,
               tangential=demill.Tangential.MINDLIN, clamp_normal=False)
    drum = world.add_drum(steel, diameter=0.3, length=0.1, lifter_height=0.015,
                          lifter_width=0.015, lifters=8)
    world.threads = threads
    drum.fill(steel, demill.Sizes.CLASSES, [BALL_DIAMETER, 1.0], demill.Fill.MASS, CHARGE_MASS,
              seed=1)
    return world, drum


class ProgressBar:
    """The progress line, drawn by the library's progress callback during
    each :meth:`demill.World.step`: on a terminal a line that updates itself
    4 times a second, otherwise a line every 10 s (on stderr)."""

    def __init__(self, drum, total_steps, width=30):
        self.drum, self.total, self.width = drum, total_steps, width
        self.done = 0          # steps of the whole run before the current call
        self.turning = False
        self.rate = 0.0        # steps per second, smoothed
        self.tty = sys.stderr.isatty()
        self.every = 0.25 if self.tty else 10.0
        self.last = time.monotonic()

    def __call__(self, progress):
        """The callback: ``progress`` is a :class:`demill.Progress`."""
        rate = progress.steps_per_second
        self.rate = 0.9 * self.rate + 0.1 * rate if self.rate > 0 else rate
        if time.monotonic() - self.last >= self.every:
            self.draw(self.done + progress.steps_done, progress.time)

    def draw(self, steps, sim_time):
        self.last = time.monotonic()
        frac = min(steps / self.total, 1.0)
        eta = max(self.total - steps, 0) / self.rate if self.rate > 0 else 0.0
        bar = "#" * int(frac * self.width)
        revolution = self.drum.angle / (2 * math.pi) if self.turning else 0.0
        start, end = ("\r", "  ") if self.tty else ("", "\n")
        sys.stderr.write(f"{start}mill.py: [{bar:.<{self.width}}] {100 * frac:3.0f} %  "
                         f"t = {sim_time:.3f} s  revolution {revolution:.2f}  "
                         f"{self.rate / 1e3:.1f} k steps/s  ETA {int(eta) // 60}:{int(eta) % 60:02d}"
                         f"{end}")
        sys.stderr.flush()

    def finish(self, steps, sim_time):
        """The last line, at 100 %."""
        self.total = steps
        self.draw(steps, sim_time)
        if self.tty:
            sys.stderr.write("\n")


def run(args):
    """Runs the mill; returns the samples (time, power) and the summary."""
    t_wall = time.monotonic()
    world, drum = build(args.time_step, args.threads)
    n = len(world.particles)
    mass = world.particles.masses.sum()
    omega = args.speed / 100 * drum.critical_speed
    period = 2 * math.pi / omega
    sample = max(1, round(SAMPLE / args.time_step))
    total = math.ceil((SETTLE + args.revolutions * period) / args.time_step)
    print(f"mill.py: {n} balls ({mass:.3f} kg) in a {drum.diameter:.3f} m drum, "
          f"{drum.lifter_count} lifters, {args.speed:.0f} % of critical ({omega:.4f} rad/s), "
          f"{args.revolutions} revolutions, about {total} steps", file=sys.stderr)

    times, power = [], []
    bar = ProgressBar(drum, total)
    world.on_progress(bar, every=sample)
    series = world.vtk_series(args.vtk) if args.vtk else None
    vtk_steps = max(1, round(VTK_EVERY / args.time_step))
    t, steps = 0.0, 0
    t_rev = math.nan  # start of the measurement (last) revolution
    while drum.revolutions < args.revolutions:
        if not bar.turning and t >= SETTLE - 0.5 * args.time_step:
            drum.speed_fraction = args.speed / 100
            bar.turning = True
        world.step(sample)
        steps += sample
        bar.done = steps
        t = world.time
        if bar.turning and math.isnan(t_rev) and drum.revolutions + 1 >= args.revolutions:
            t_rev = t
        times.append(t)
        power.append(drum.power)
        if series and steps % vtk_steps < sample:
            series.write()
    world.on_progress(None)
    bar.finish(steps, t)
    if series:
        series.close()
    summary = {
        "particles": n, "mass": mass, "time": t, "steps": steps,
        "mean_power": drum.power_mean, "mean_power_cm": drum.power_cm_mean,
        "toe": math.degrees(drum.toe_angle_mean),
        "shoulder": math.degrees(drum.shoulder_angle_mean),
        "rev_start": t_rev, "wall": time.monotonic() - t_wall,
    }
    world.close()
    return np.array(times), np.array(power), summary


def plot(path, t, p, s):
    """Power against time (a 10 ms running mean, as examples/mill draws it)
    with the measurement revolution and its mean."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    win = 10
    smooth = np.convolve(p, np.ones(win), "full")[:len(p)] / np.minimum(np.arange(1, len(p) + 1),
                                                                          win)
    fig, ax = plt.subplots(figsize=(9, 4.5), dpi=120)
    ax.plot(t, p, color="0.8", lw=0.5, label="power draw, every 1 ms")
    ax.plot(t, smooth, color="C0", lw=1.2, label="10 ms running mean")
    ax.axvspan(s["rev_start"], t[-1], color="C1", alpha=0.12, label="last revolution")
    ax.hlines(s["mean_power"], s["rev_start"], t[-1], color="C1", lw=2,
              label=f"its mean, {s['mean_power']:.2f} W")
    ax.axvline(SETTLE, color="0.4", ls=":", lw=1)
    # the start-up transient (the charge set moving) is off the top
    top = 1.2 * max(smooth[t > SETTLE + 0.05].max(initial=0), s["mean_power"])
    ax.set(xlabel="time, s", ylabel="power draw, W", xlim=(0, t[-1]), ylim=(min(0, p.min()), top),
           title=f"libdemill mill from Python: {s['particles']} balls, mean power "
                 f"{s['mean_power']:.2f} W")
    ax.legend(loc="upper left", fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main(argv=None):
    args = parse_args(argv)
    t, p, s = run(args)
    plot(args.out, t, p, s)
    print(f"mill.py: done in {s['wall']:.1f} s. Mean power over the last revolution "
          f"{s['mean_power']:.2f} W (from the centre of mass {s['mean_power_cm']:.2f} W);\n"
          f"         toe {s['toe']:.1f}°, shoulder {s['shoulder']:.1f}°; plot in {args.out}")


if __name__ == "__main__":
    main()
