#!/usr/bin/env python3
"""mill --ore on a tiny, short case (a 0.1 m drum, 128 balls of 8 mm and
0.02 kg of the example ore, one revolution: about 3 s): the files exist,
the product's mass is the feed's (the population balance conserves mass:
every column of its matrix sums to zero, Austin, Klimpel and Luckie 1984),
the feed's mass is the ore file's, the cumulative passing never falls as
the size grows, and the product is finer than the feed (P80 < F80).

usage: mill_ore.py MILL ORE_FILE WORK_DIR"""

import os
import re
import subprocess
import sys

from outputs import assert_png, read_summary


def main():
    mill, ore_file, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    with open(ore_file) as f:
        text = f.read()
    # the example's ore, 0.02 kg of it so that it fits the small drum
    small = re.sub(r"(?m)^mass .*$", "mass 0.02", text)
    ore = os.path.join(work, "ore.txt")
    with open(ore, "w") as f:
        f.write(small)
    out = os.path.join(work, "out")
    subprocess.run([mill, "--diameter", "0.1", "--length", "0.03", "--radius", "0.004",
                    "--revolutions", "1", "--lifters", "4", "--lifter-height", "0.008",
                    "--fill", "25", "--vtk-every", "0", "--ore", ore, "--grind-minutes", "10",
                    "--out", out], check=True)
    summary = read_summary(os.path.join(out, "summary.txt"))
    assert_png(os.path.join(out, "product.png"))
    with open(os.path.join(out, "product.csv")) as f:
        rows = [line.strip().split(",") for line in f][1:]
    feed = sum(float(r[4]) for r in rows)
    product = sum(float(r[5]) for r in rows)
    assert abs(feed - 0.02) <= 1e-12, f"feed {feed!r} kg, the file says 0.02"
    assert abs(product - feed) <= 1e-12 * feed, f"product {product!r} kg, feed {feed!r} kg"
    for col in (6, 7):
        passing = [float(r[col]) for r in rows]  # coarsest class first
        assert all(a >= b for a, b in zip(passing, passing[1:])), f"column {col} not monotone"
    f80, p80 = float(summary["F80_m"]), float(summary["P80_m"])
    assert p80 < f80, f"P80 {p80} m is not below F80 {f80} m"
    assert float(summary["specific_energy_kWh_t"]) > 0
    print(f"mill --ore: F80 {f80 * 1e3:.3f} mm, P80 {p80 * 1e3:.3f} mm, "
          f"{summary['specific_energy_kWh_t']} kWh/t, mass {product!r} kg of {feed!r}")


if __name__ == "__main__":
    main()
