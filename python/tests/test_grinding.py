"""The grinding binding (demill.Grinding) against numbers derived without
it: one class decays as e^(-S t), the JKMRC t10 = A (1 - exp(-b E_cs)), the
P80 of a two-class product worked by hand, mass conserved through a model's
appearance function, the rate of impacts at one energy S = c/(N T)
P(E); errors raise with the library's message and change
nothing; the Grinding section of docs/getting-started-python.md runs and
prints what it says."""

import math
import os
import re
import subprocess
import sys
import unittest

import numpy as np
from helpers import REPO, linear_world  # noqa: F401 - makes demill importable

import demill

# A t-family table made up for the tests: rows of t10, t2, t4, t25, t50, t75 (%).
TABLE = [[10, 30, 18, 4.5, 2.5, 2.0], [20, 50, 33, 9.0, 5.0, 4.0], [30, 65, 46, 13.5, 7.5, 6.0]]


class GrindingTest(unittest.TestCase):
    def test_one_class_decays_exponentially(self):
        with demill.Grinding(0.01, 2) as g:
            g.set_feed([1.0, 0.0])
            g.rates = [0.3, 0.0]
            g.appearance = [[0, 0], [1, 0]]
            g.run(2.5)
            g.run(2.5)
            self.assertAlmostEqual(g.time, 5.0, places=14)
            self.assertAlmostEqual(g.product[0], math.exp(-1.5), delta=1e-12)

    def test_jk_t10_and_appearance(self):
        with demill.Grinding(0.004, 12) as g:
            g.set_jk(60, 1.2, TABLE)
            # E_cs = 1 kWh/t = 3600 J/kg: 60 (1 - e^-1.2) %
            self.assertAlmostEqual(g.t10(0.001, 3600), 60 * (1 - math.exp(-1.2)), places=12)
            np.testing.assert_allclose(g.tn(20), TABLE[1][1:], rtol=0, atol=1e-12)
            g.set_appearance_energy(900)
            b = g.appearance
            self.assertEqual(b.shape, (12, 12))
            np.testing.assert_allclose(b[:, :-1].sum(axis=0), 1.0, atol=1e-12)
            feed = np.zeros(12)
            feed[0] = 2.0
            g.set_feed(feed)
            g.rates = [0.05 * 0.8 ** i for i in range(11)] + [0.0]
            for _ in range(50):
                g.run(10)
                self.assertAlmostEqual(g.product.sum(), 2.0, delta=2e-12)
            self.assertAlmostEqual(g.specific_energy(50, 2.0), 50 * 500 / 2.0 / 3600, places=12)

    def test_passing_and_p80(self):
        with demill.Grinding(0.008, 8) as g:
            limits = g.sizes
            self.assertEqual(len(limits), 9)
            self.assertEqual(g.classes, 8)
            g.set_feed([0, 0, 1, 0, 1, 0, 0, 0])
            self.assertAlmostEqual(g.passing(limits[3]), 0.5, places=15)
            # 0.8 lies 0.6 of the way from 0.5 to 1 across class 2, in ln x
            self.assertAlmostEqual(g.p80, limits[3] * 2 ** 0.3, delta=1e-15)

    def test_tavares_median(self):
        with demill.Grinding(0.02, 8) as g:
            g.set_tavares(100, 0.005, 1, 0.8, 0, 5, 50, 1, TABLE)
            # E50(5 mm) = 100 (1 + 1) J/kg: half break
            self.assertAlmostEqual(g.broken_fraction(0.005, 200), 0.5, places=12)
            self.assertGreater(g.broken_fraction(0.005, 100, 10), g.broken_fraction(0.005, 100))

    def test_rates_from_impacts(self):
        with demill.Grinding(0.02, 8) as g:
            g.set_tavares(100, 0.005, 1, 0.8, 0, 5, 30, 1, TABLE)
            # 40 impacts on 4 particles of class 2 in 2 s, all in one bin
            # whose midpoint is E50 of class 2's geometric mean size: half
            # of them break, so S_2 = 40 / (4 * 2) * 0.5 = 2.5 1/s.
            d = 0.02 * 2 ** -1.25
            e50 = 100 * (1 + 0.005 / d)
            counts = np.zeros((8, 1))
            counts[2, 0] = 40
            g.rates_from_impacts([0.5 * e50, 1.5 * e50], counts, [4] * 8, 2.0)
            self.assertAlmostEqual(g.rates[2], 2.5, places=12)
            self.assertEqual(g.rates[1], 0.0)  # no impacts
            self.assertAlmostEqual(g.appearance[:, 2].sum(), 1.0, places=12)
            g.set_jk(55, 0.9, TABLE)
            with self.assertRaises(demill.InvalidValue) as cm:
                g.rates_from_impacts([0.5 * e50, 1.5 * e50], counts, [4] * 8, 2.0)
            self.assertIn("JKMRC", cm.exception.message)

    def test_damage_and_extension(self):
        with demill.Grinding(0.02, 8) as g:
            # Tavares and King (2002) with gamma = 2.5: the thresholds of
            # impacts of E are E_1 = E, E_(k+1) = (E + sqrt(E^2 + 4 E_k^2))/2
            # (the damage equation solved in closed form); two impacts at
            # E = E50 break Phi(ln(E_2/E50)/sigma) = Phi(ln(1.618)/0.8).
            g.set_tavares(100, 0.005, 1, 0.8, 0, 2.5, 30, 1, TABLE)
            f2 = 0.5 * math.erfc(-math.log((1 + 5 ** 0.5) / 2) / 0.8 / 2 ** 0.5)
            self.assertAlmostEqual(g.broken_fraction(0.005, 200, 2), f2, places=12)
            self.assertEqual(g.damage_time, 0)
            g.damage_time = 0.4
            self.assertEqual(g.damage_time, 0.4)
            # one bin at E50 of class 2, 40 impacts on 4 particles in 2 s:
            # lambda = 5 /s, K = 5 × 0.4 = 2 impacts in the damage time,
            # S = lambda F_2 / (1 + 1 - F_1), F_1 = 1/2
            d = 0.02 * 2 ** -1.25
            e50 = 100 * (1 + 0.005 / d)
            counts = np.zeros((8, 1))
            counts[2, 0] = 40
            g.rates_from_impacts([0.5 * e50, 1.5 * e50], counts, [4] * 8, 2.0)
            self.assertAlmostEqual(g.rates[2], 5 * f2 / 1.5, delta=1e-12)
            # Austin's power law through classes 0 and 1 (S ~ x^0.5): classes
            # 2 to 6 follow it
            g.rates = [0.02, 0.02 * 2 ** -0.25, 0, 0, 0, 0, 0, 0]
            g.appearance = np.tril(np.full((8, 8), 1.0), -1) / np.arange(7, -1, -1).clip(1)
            a, alpha = g.extend_rates()
            self.assertAlmostEqual(alpha, 0.5, places=12)
            self.assertAlmostEqual(g.rates[5], 0.02 * 2 ** -1.25, places=14)
            with self.assertRaises(demill.InvalidValue):
                g.extend_rates(mu=-1)

    def test_rates_from_drum(self):
        # Two ore balls of 10 mm meet head-on at 1 m/s in a drum, no
        # gravity, restitution 0.5: each absorbs half of 0.375 m* v² with
        # m* = m/2, 0.09375 J/kg, which lands in bin 49 of 100 from 1e-3 to
        # 10 J/kg (log10 0.09375 = -1.028: (−1.028 + 3) / 4 × 100 = 49.3).
        with demill.World(3) as w:
            w.gravity = (0, 0, 0)
            ore = w.material(density=2500)
            w.pair(ore, ore, normal=demill.Normal.LINEAR, damping=demill.Damping.RESTITUTION,
                   restitution=0.5)
            drum = w.add_drum(ore, diameter=2.0, length=0.5)
            drum.spectrum_start([], 4, 1e-6, 1e-2)
            drum.impacts_start(ore, 0.02, 4, 100, 1e-3, 10)
            w.particles.add(ore, [(-0.0055, 0, 0), (0.0055, 0, 0)], radii=0.005,
                            velocities=[(0.5, 0, 0), (-0.5, 0, 0)])
            w.step(400)
            counts, time = drum.impacts()
            self.assertEqual(counts.shape, (4, 100))
            self.assertAlmostEqual(time, 400 * w.time_step, places=12)
            np.testing.assert_array_equal(drum.impacts_particles(), [0, 0, 2, 0])
            self.assertEqual(counts[2, 49], 2)
            self.assertEqual(counts.sum(), 2)
            with demill.Grinding(0.02, 4) as g:
                with self.assertRaises(demill.InvalidValue) as cm:
                    g.rates_from_drum(drum)  # no model
                self.assertIn("model", cm.exception.message)
                g.set_tavares(0.1, 0.005, 1, 0.8, 0, 5, 30, 1, TABLE)
                g.rates_from_drum(drum)
                # S_2 = 2 impacts / (2 particles × T) × P(bin 49's midpoint)
                lo, hi = 10 ** (-3 + 4 * 0.49), 10 ** (-3 + 4 * 0.50)
                d = 0.02 * 2 ** -1.25
                p = g.broken_fraction(d, 0.5 * (lo + hi))
                self.assertAlmostEqual(g.rates[2], p / time, delta=1e-12 * p / time)

    def test_errors_carry_the_message_and_change_nothing(self):
        with demill.Grinding(0.01, 4) as g:
            g.set_feed([1, 1, 0, 0])
            g.rates = [0.1, 0.1, 0.1, 0]
            before = (g.product, g.rates, g.appearance)
            with self.assertRaises(demill.InvalidValue) as cm:
                g.rates = [0.1, -0.1, 0.1, 0]
            self.assertIn("rates[1]", cm.exception.message)
            with self.assertRaises(demill.InvalidValue):
                g.set_jk(101, 1, TABLE)
            with self.assertRaises(demill.InvalidValue):
                g.run(0)
            with self.assertRaises(demill.NotFinite):
                g.set_feed([1, float("nan"), 0, 0])
            with self.assertRaises(demill.InvalidValue) as cm:
                g.appearance = np.eye(4)
            self.assertIn("appearance", str(cm.exception))
            for old, new in zip(before, (g.product, g.rates, g.appearance)):
                np.testing.assert_array_equal(old, new)
        with self.assertRaises(demill.InvalidHandle):
            g.run(1)
        with self.assertRaises(demill.InvalidValue):
            demill.Grinding(-1, 4)


    def test_guide_programs(self):
        # Each program of the guide's Grinding section runs, and the output
        # the guide quotes after "It prints" is what it prints.
        guide = (REPO / "docs" / "getting-started-python.md").read_text(encoding="utf-8")
        section = guide.split("\n## Grinding\n")[1].split("\n## ")[0]
        programs = re.findall(r"```python\n(.*?)```", section, re.S)
        self.assertEqual(len(programs), 2)
        env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
        out = subprocess.run([sys.executable, "-c", programs[1]], env=env, check=True,
                             capture_output=True, text=True).stdout
        quoted = re.search(r"It prints (.*?), in under", section, re.S).group(1)
        for text in re.findall(r"`(.*?)`", quoted, re.S):
            self.assertIn(" ".join(text.split()), " ".join(out.split()))
        subprocess.run([sys.executable, "-c", programs[0]], env=env, check=True,
                       capture_output=True)


if __name__ == "__main__":
    unittest.main()
