"""examples/python/mill.py: its scene is the C example's (the charge of the
drum3d mass in balls of 5 mm radius, inside the drum) and its plot is written."""

import importlib.util
import math
import tempfile
import unittest
from pathlib import Path

import numpy as np
from helpers import REPO, sphere_mass

spec = importlib.util.spec_from_file_location("mill_example",
                                              REPO / "examples" / "python" / "mill.py")
mill = importlib.util.module_from_spec(spec)
spec.loader.exec_module(mill)


class MillExample(unittest.TestCase):
    def test_scene(self):
        world, drum = mill.build(1e-5, 1)
        with world:
            ball = sphere_mass(mill.BALL_DIAMETER / 2, 7800)
            self.assertEqual(len(world.particles), round(mill.CHARGE_MASS / ball))
            x = world.particles.positions
            rim = np.hypot(x[:, 0], x[:, 1]) + world.particles.radii
            self.assertLess(rim.max(), drum.diameter / 2)
            self.assertLess(np.abs(x[:, 2]).max() + mill.BALL_DIAMETER / 2, drum.length / 2)
            self.assertEqual(drum.lifter_count, 8)
            self.assertAlmostEqual(drum.critical_speed, math.sqrt(2 * 9.81 / (0.3 - 0.01)),
                                   delta=1e-12)

    def test_plot(self):
        t = np.arange(1, 1001) * 1e-3
        p = 30 + np.sin(50 * t)
        summary = {"particles": 10, "mean_power": 30.0, "rev_start": 0.6}
        with tempfile.TemporaryDirectory() as d:
            out = Path(d) / "power.png"
            mill.plot(out, t, p, summary)
            self.assertEqual(out.read_bytes()[:8], b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
