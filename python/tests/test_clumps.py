"""Clumps through the binding, against numbers derived here: a dumbbell of
two spheres apart has the mass 2 (4/3 π r³ ρ), its centre midway and its
principal moments 2 (2/5 m r²) about the line of centres and
2 (2/5 m r² + m d²) across it (the parallel-axis theorem); a free clump
falls as x0 + g t²/2 keeping its spin; its members are particles that name
it; bad input raises with the clump unchanged."""

import math
import unittest

import numpy as np
from helpers import linear_world

import demill


class Clumps(unittest.TestCase):
    def test_dumbbell_template(self):
        r, d, rho = 0.01, 0.03, 1000.0  # centres 2d apart: no overlap
        w, m = linear_world()
        with w:
            m.density = rho
            t = w.clump_template(m, [(-d, 0, 1), (d, 0, 1)], r)
            ms = 4 / 3 * math.pi * r ** 3 * rho
            self.assertAlmostEqual(t.mass / (2 * ms), 1.0, places=13)
            self.assertAlmostEqual(t.volume * rho / t.mass, 1.0, places=13)
            np.testing.assert_allclose(t.centre, (0, 0, 1), atol=1e-15)
            want = (2 * 0.4 * ms * r * r, 2 * (0.4 * ms * r * r + ms * d * d))
            np.testing.assert_allclose(t.principal_moments, (want[0], want[1], want[1]),
                                       rtol=1e-12)
            self.assertAlmostEqual(abs(t.principal_axes[0, 0]), 1.0, places=14)
            self.assertEqual(t.count, 2)

    def test_fill(self):
        # 50 clumps in a box by count, every member inside it (each clump's
        # members 2 of the 100 particles)
        w, m = linear_world()
        with w:
            t = w.clump_template(m, [(0, 0, 0), (0.01, 0, 0)], 0.01)
            box = (0, 0, 0, 0.2, 0.2, 0.2)
            clumps = w.fill_clumps(demill.Region.BOX, box, t, demill.Fill.COUNT, 50, seed=3)
            self.assertEqual(len(clumps), 50)
            x, r = w.particles.positions, w.particles.radii
            self.assertEqual(len(x), 100)
            self.assertTrue(np.all(x - r[:, None] >= 0) and np.all(x + r[:, None] <= 0.2))
            self.assertEqual(len(clumps[0].members()), 2)

    def test_free_fall_and_members(self):
        g, dt, steps = -9.81, 1e-4, 1000
        w, m = linear_world(gravity=(0, g, 0))
        with w:
            w.time_step = dt
            t = w.clump_template(m, [(0, 0, 0), (0.015, 0, 0)], 0.01)
            c = w.add_clump(t, (0, 1, 0))
            c.angular_velocity = (0, 0, 2.0)
            spin = c.angular_momentum
            ids = c.members()
            self.assertEqual(len(ids), 2)
            self.assertEqual(w.clump_of(ids[1]), c)
            self.assertEqual(w.clumps, [c])
            np.testing.assert_array_equal(w.ids(demill.Kind.TEMPLATE), [t.id])
            np.testing.assert_array_equal(w.particles.clump_ids(), [c.id, c.id])
            w.step(steps)
            time = steps * dt
            np.testing.assert_allclose(c.position, (0, 1 + 0.5 * g * time * time, 0),
                                       rtol=0, atol=1e-12)
            np.testing.assert_allclose(c.angular_momentum, spin, rtol=1e-15)
            # a member moves with its clump
            x = w.particle(ids[0]).position
            q = c.orientation
            self.assertAlmostEqual(q[0] ** 2 + q[3] ** 2, 1.0, places=14)
            self.assertAlmostEqual(float(np.linalg.norm(x - c.position)),
                                   0.0075, places=12)
            with self.assertRaises(demill.InvalidValue):
                w.particle(ids[0]).position = (0, 0, 0)
            with self.assertRaises(demill.ReadOnly):
                c._set(demill.ClumpField.MASS, [1.0])
            with self.assertRaises(demill.InvalidValue):
                w.clump_template(m, np.zeros((0, 3)), [])
            np.testing.assert_array_equal(w.particle(ids[0]).position, x)
            c.remove()
            self.assertEqual(len(w.particles), 0)
            self.assertEqual(w.clumps, [])


if __name__ == "__main__":
    unittest.main()
