"""Bodies and fixed particles through the binding, against numbers derived
here: the spring-mounted box's natural frequency √(k/m)/(2π), its energy
kept undamped, the energy balance with a driven, damped box, a fixed particle
that never moves, and bad input raised with the world unchanged."""

import math
import unittest

import numpy as np
from helpers import linear_world

import demill
from demill import BodyAxis, Energy, Normal


def box(w, m, body, half=(0.021, 0.012, 0.021)):
    """Six planes facing inwards about the origin, attached to body."""
    walls = []
    for a in range(3):
        for s in (-1, 1):
            p, n = np.zeros(3), np.zeros(3)
            p[a], n[a] = s * half[a], -s
            wall = w.add_plane(m, p, n)
            body.attach(wall)
            walls.append(wall)
    return walls


class SpringMountedBox(unittest.TestCase):
    def test_natural_frequency_and_energy(self):
        """The empty 0.3 kg box on k = 9720 N/m, released 1 mm from rest:
        10 periods of 2π√(m/k), its energy ½kx0² kept within 1e-6."""
        k, mass, x0, dt = 9720.0, 0.3, 1e-3, 5e-6
        period = 2 * math.pi * math.sqrt(mass / k)
        with demill.World(3, time_step=dt) as w:
            m = w.material()
            w.pair(m, m, normal=Normal.LINEAR)
            b = w.add_body(mass, (0, 0, 0), BodyAxis.Y, gravity=False)
            b.set_spring(BodyAxis.Y, k, rest=-x0)
            box(w, m, b)
            self.assertEqual(w.bodies, [b])
            self.assertEqual(demill.id_kind(b), demill.Kind.BODY)
            e0 = 0.5 * k * x0 * x0
            self.assertAlmostEqual(w.energy(Energy.TOTAL), e0, delta=1e-15)
            prev, crossings = x0, []
            for i in range(1, int(10.5 * period / (10 * dt)) + 1):
                w.step(10)
                y = b.position[1] + x0
                if prev < 0 <= y:
                    crossings.append((i - 1 + -prev / (y - prev)) * 10 * dt)
                prev = y
                self.assertLessEqual(abs(w.energy(Energy.TOTAL) - e0), 1e-6 * e0)
            self.assertEqual(len(crossings), 10)
            self.assertAlmostEqual((crossings[-1] - crossings[0]) / 9 / period, 1.0, delta=1e-4)
            kinetic = b.energy(Energy.BODY_KINETIC) + b.energy(Energy.BODY_ELASTIC)
            self.assertAlmostEqual(kinetic / e0, 1.0, delta=1e-6)

    def test_driven_box_balance(self):
        """Driven at 20 Hz with a damper: the external force's work is the
        box's energy plus the damper's dissipation (a conservation law)."""
        with demill.World(3, time_step=1e-5) as w:
            m = w.material()
            w.pair(m, m, normal=Normal.LINEAR)
            b = w.add_body(0.3, (0, 0, 0), BodyAxis.Y, gravity=False)
            b.set_spring(BodyAxis.Y, 9720.0, damping=5.4)
            b.set_force((0, 9.72, 0), 20.0)
            w.step(20000)
            work = w.energy(Energy.BODY_WORK)
            self.assertGreater(work, 0)
            held = sum(w.energy(t) for t in (Energy.BODY_KINETIC, Energy.BODY_ELASTIC,
                                             Energy.BODY_DISSIPATED))
            self.assertAlmostEqual(held / work, 1.0, delta=1e-6)
            np.testing.assert_allclose(b.force_spring, [0, -9720.0 * b.position[1], 0],
                                       rtol=1e-14)
            np.testing.assert_array_equal(b.force_particles, np.zeros(3))
            s = math.sin(2 * math.pi * 20.0 * w.time)
            np.testing.assert_allclose(b.force_external, [0, 9.72 * s, 0], rtol=1e-12)

    def test_bad_input_leaves_the_world_unchanged(self):
        with demill.World(2) as w:
            m = w.material()
            w.pair(m, m, normal=Normal.LINEAR)
            b = w.add_body(1.0, (0, 0, 0), BodyAxis.X)
            wall = w.add_plane(m, (0, 0, 0), (0, 1, 0))
            b.attach(wall)
            w.step(10)

            def observed():
                return (b.position.tobytes(), b.velocity.tobytes(), wall.point.tobytes(),
                        len(w.bodies), w.energies())
            before = observed()
            with self.assertRaises(demill.InvalidValue):
                w.add_body(0.0, (0, 0, 0), BodyAxis.X)
            with self.assertRaises(demill.DimensionError):
                w.add_body(1.0, (0, 0, 0), BodyAxis.Z)
            with self.assertRaises(demill.InvalidValue):
                b.set_spring(BodyAxis.X, -1.0)
            with self.assertRaises(demill.InvalidValue):
                b.set_spring(BodyAxis.Y, 1.0)  # not a free axis
            with self.assertRaises(demill.NotFinite):
                b.set_force((math.nan, 0, 0), 10.0)
            with self.assertRaises(demill.InvalidValue):
                b.attach(wall)  # attached already
            self.assertEqual(observed(), before)
            b.remove()
            self.assertEqual(w.bodies, [])


class FixedParticles(unittest.TestCase):
    def test_fixed_particle_stays_and_stops_a_ball(self):
        """A ball hits a fixed ball head-on: the fixed one stays bitwise where
        it was, the ball rebounds at the pair's restitution."""
        w, m = linear_world()
        with w:
            w.time_step = 1e-5
            a, f = w.particles.add(m, [(-0.0105, 0, 0), (0, 0.0, 0)], 0.005,
                                   velocities=[(1, 0, 0), (0, 0, 0)])
            fixed = w.particle(f)
            fixed.fixed = True
            self.assertTrue(fixed.fixed)
            np.testing.assert_array_equal(w.particles.fixed, [0, 1])
            x = fixed.position.copy()
            w.step(3000)
            np.testing.assert_array_equal(fixed.position, x)
            np.testing.assert_array_equal(fixed.velocity, np.zeros(3))
            self.assertAlmostEqual(w.particle(a).velocity[0], -0.5, delta=0.005)
            with self.assertRaises(demill.InvalidValue):
                fixed.velocity = (1, 0, 0)


if __name__ == "__main__":
    unittest.main()
