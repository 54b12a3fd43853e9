"""Clumps through the binding, against numbers derived here: a dumbbell of
two spheres apart has the mass 2 (4/3 π r³ ρ), its centre midway and its
principal moments 2 (2/5 m r²) about the line of centres and
2 (2/5 m r² + m d²) across it (the parallel-axis theorem); a free clump
falls as x0 + g t²/2 keeping its spin; its members are particles that name
it; bad input raises with the clump unchanged. A template filled into a
regular octahedron |x| + |y| + |z| <= a with one sphere is its inscribed
ball, of radius a/sqrt(3) about its centre, and the fit reports the
octahedron's volume (4/3) a³; an ASCII STL file of it gives the same
template, bitwise; an open mesh raises. A checkpoint in bytes of a clump bouncing on a plane
goes on to the same bits."""

import math
import os
import tempfile
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

    def test_checkpoint_in_bytes(self):
        # a spinning dumbbell falling onto a plane (it hits it between steps
        # 200 and 300 and bounces on), saved to bytes after 300 steps and
        # loaded into a new world: both run 700 steps more to the same bits
        g, dt = -9.81, 1e-4
        w, m = linear_world(gravity=(0, g, 0))
        with w:
            w.time_step = dt
            w.add_plane(m, (0, 0, 0), (0, 1, 0))
            t = w.clump_template(m, [(0, 0, 0), (0.015, 0, 0)], 0.01)
            c = w.add_clump(t, (0, 0.02, 0), (1, 0.1, 0.2, 0.3))
            c.angular_velocity = (1.0, 2.0, 3.0)
            w.step(300)
            with demill.World.from_bytes(w.to_bytes()) as v:
                self.assertEqual(len(v.clumps), 1)
                d = v.clumps[0]
                w.step(700)
                v.step(700)
                for field in ("position", "orientation", "velocity", "angular_velocity",
                              "angular_momentum"):
                    np.testing.assert_array_equal(getattr(d, field), getattr(c, field), field)
                self.assertEqual(v.to_bytes(), w.to_bytes())

    def test_spheres_of_a_template(self):
        r, d = 0.01, 0.03
        w, m = linear_world()
        with w:
            t = w.clump_template(m, [(-d, 0, 1), (d, 0, 1)], r)
            centres, radii = t.spheres()
            np.testing.assert_allclose(radii, (r, r), rtol=0)
            # the line of centres is the axis of the least moment, the first
            np.testing.assert_allclose(np.abs(centres[:, 0]), (d, d), rtol=1e-15)
            np.testing.assert_allclose(centres[:, 1:], 0, atol=1e-15)
            np.testing.assert_allclose(t.centre + centres @ t.principal_axes,
                                       [(-d, 0, 1), (d, 0, 1)], atol=1e-15)
            with self.assertRaises(demill.InvalidValue):
                t.mesh_volume

    def test_template_from_mesh(self):
        a, rho = 0.02, 2700.0
        v = np.array([(a, 0, 0), (-a, 0, 0), (0, a, 0), (0, -a, 0), (0, 0, a), (0, 0, -a)])
        tri = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5),
               (0, 3, 5)]
        w, m = linear_world()
        with w:
            m.density = rho
            t = w.clump_template_from_mesh(m, v, tri, 1, cells=64)
            r_in = a / math.sqrt(3)
            self.assertEqual(t.count, 1)
            centres, radii = t.spheres()
            self.assertAlmostEqual(radii[0] / r_in, 1.0, delta=1e-4)
            self.assertAlmostEqual(t.mass / (4 / 3 * math.pi * radii[0] ** 3 * rho), 1.0,
                                   places=12)
            np.testing.assert_allclose(t.centre, 0, atol=1e-4 * a)
            self.assertAlmostEqual(t.mesh_volume / (4 / 3 * a ** 3), 1.0, places=12)
            self.assertAlmostEqual(t.fit_volume_error,
                                   1 - math.pi / math.sqrt(3) ** 3, delta=1e-3)
            self.assertAlmostEqual(t.fit_cell, 2 * a / 64, places=15)
            self.assertGreater(t.fit_deviation_out, 0)
            self.assertGreater(t.fit_deviation_in, 0)
            with tempfile.TemporaryDirectory() as d:
                path = os.path.join(d, "octahedron.stl")
                with open(path, "w") as f:
                    f.write("solid octahedron\n")
                    for c in tri:
                        f.write("facet normal 0 0 0\nouter loop\n")
                        f.writelines("vertex %r %r %r\n" % tuple(v[k]) for k in c)
                        f.write("endloop\nendfacet\n")
                    f.write("endsolid octahedron\n")
                s = w.clump_template_from_stl(m, path, 1, cells=64)
                self.assertEqual(s.mass, t.mass)
                np.testing.assert_array_equal(s.spheres()[0], centres)
                with self.assertRaisesRegex(demill.InvalidValue, "not closed"):
                    w.clump_template_from_mesh(m, v, tri[:-1], 1)
                with self.assertRaisesRegex(demill.FileError, "nothing.stl"):
                    w.clump_template_from_stl(m, os.path.join(d, "nothing.stl"), 1)
            self.assertEqual(len(w.ids(demill.Kind.TEMPLATE)), 2)


if __name__ == "__main__":
    unittest.main()
