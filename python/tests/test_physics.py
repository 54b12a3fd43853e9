"""Physics through the binding, against numbers derived here: free fall,
binary collisions of known restitution, Hooke's law in a contact, the
energy account, masses and exact wall motion."""

import math
import os
import tempfile
import unittest

import numpy as np
from helpers import linear_contact_time, linear_world, sphere_mass

import demill
from demill import Damping, Energy, Integrator, Normal, Tangential


class FreeFall(unittest.TestCase):
    def test_verlet_is_exact_for_constant_acceleration(self):
        """x(t) = x0 + v0 t + g t²/2 and v(t) = v0 + g t, to round-off."""
        g = np.array([0.3, -9.81, 0.7])
        x0, v0 = np.array([0.1, 2.0, -0.3]), np.array([1.0, 3.0, -0.5])
        dt, n = 1e-4, 2000
        with demill.World(3, gravity=g, time_step=dt) as w:
            self.assertEqual(w.integrator, Integrator.VELOCITY_VERLET)
            m = w.material()
            w.pair(m, m, normal=Normal.LINEAR)
            (pid,) = w.particles.add(m, x0, 0.01, velocities=v0)
            w.step(n)
            t = n * dt
            self.assertAlmostEqual(w.time, t, delta=1e-15 * n)
            self.assertEqual(w.step_count, n)
            p = w.particle(pid)
            np.testing.assert_allclose(p.position, x0 + v0 * t + 0.5 * g * t * t, rtol=0,
                                       atol=1e-12)
            np.testing.assert_allclose(p.velocity, v0 + g * t, rtol=0, atol=1e-12)
            # the force is the weight
            np.testing.assert_allclose(p.force, p.mass * g, rtol=1e-14)

    def test_symplectic_euler_lags_by_half_a_step(self):
        """Symplectic Euler: x_n = x0 + g dt² n(n+1)/2 from rest."""
        dt, n, g = 1e-3, 100, -9.81
        with demill.World(2, time_step=dt, integrator=Integrator.SYMPLECTIC_EULER) as w:
            m = w.material()
            w.pair(m, m, normal=Normal.LINEAR)
            (pid,) = w.particles.add(m, (0, 0, 0), 0.01)
            w.step(n)
            y = w.particle(pid).position[1]
            self.assertAlmostEqual(y, g * dt * dt * n * (n + 1) / 2, delta=1e-13)

    def test_local_damping_slows_a_fall(self):
        """Local damping α opposes the weight of a falling ball by α m g: the
        first half kick, from rest (sign(v) = 0), is undamped, every later
        one accelerates at (1 - α) g, so velocity Verlet gives
        y_n = g dt² (n/2 + (1 - α) n(n - 1)/2), v_n = g dt (1/2 + (1 - α)(n - 1/2)).
        The damping's energy is booked at each of the n evaluations as
        dt α m |g| |v_k| (v_k the full-step speed g dt (1/2 + (1 - α)(k - 1/2))),
        α m g² dt² (n/2 + (1 - α) n²/2) in all: the weight's work less the
        kinetic energy gained, and the half kick the next step applies."""
        dt, n, g, alpha = 1e-3, 200, -9.81, 0.4
        with demill.World(3, time_step=dt) as w:
            m = w.material(local_damping=alpha)
            self.assertEqual(m.local_damping, alpha)
            w.pair(m, m, normal=Normal.LINEAR)
            (pid,) = w.particles.add(m, (0, 0, 0), 0.01)
            w.step(n)
            p = w.particle(pid)
            self.assertAlmostEqual(p.position[1], g * dt * dt * (n / 2 + (1 - alpha) * n * (n - 1) / 2),
                                   delta=1e-12)
            self.assertAlmostEqual(p.velocity[1], g * dt * (0.5 + (1 - alpha) * (n - 0.5)), delta=1e-12)
            booked = alpha * p.mass * g * g * dt * dt * (n / 2 + (1 - alpha) * n * n / 2)
            self.assertAlmostEqual(w.energy(Energy.DISSIPATED_LOCAL), booked, delta=1e-12 * booked)
            lost = p.mass * g * p.position[1] - 0.5 * p.mass * p.velocity[1] ** 2
            self.assertAlmostEqual(booked, lost, delta=1.0 / n * lost)
            with self.assertRaises(demill.InvalidValue):
                m.local_damping = 1.0

    def test_rolling_spring_holds_a_ball_on_a_slope(self):
        """Below its threshold (tan β = 0.05 < μ_r = 0.1) the rolling spring
        holds a ball still: after settling it moves less than 1e-9 m in 0.2 s;
        its stiffness reads back as set, and 0 (the default) asks for
        2.25 k_n μ_r² R*² per contact."""
        beta = math.atan(0.05)
        g = (9.81 * math.sin(beta), -9.81 * math.cos(beta), 0)
        with demill.World(3, gravity=g, time_step=2e-5) as w:
            m = w.material()
            pair = w.pair(m, m, normal=Normal.LINEAR, damping=Damping.RESTITUTION,
                          tangential=Tangential.SPRING, friction=1.0,
                          rolling=demill.Rolling.SPRING, rolling_friction=0.1)
            self.assertEqual(pair.rolling_stiffness, 0.0)
            self.assertEqual(pair.rolling_damping_ratio, 0.3)
            w.add_plane(m, (0, 0, 0), (0, 1, 0))
            (pid,) = w.particles.add(m, (0, 0.01, 0), 0.01)
            w.step(25000)
            x0 = w.particle(pid).position[0]
            w.step(10000)
            self.assertLess(abs(w.particle(pid).position[0] - x0), 1e-9)
            self.assertGreater(w.energy(Energy.ELASTIC_ROLLING), 0.0)
            pair.rolling_stiffness = 0.05
            self.assertEqual(pair.rolling_stiffness, 0.05)
            with self.assertRaises(demill.InvalidValue):
                pair.rolling_damping_ratio = -1.0


class Collisions(unittest.TestCase):
    def collide(self, w, m, r, v, dt, steps):
        """Two spheres meeting head-on at relative speed v: the rebound's
        relative speed divided by v."""
        gap = 1e-5
        pos = [(-r - gap / 2, 0, 0), (r + gap / 2, 0, 0)]
        w.time_step = dt
        ids = w.particles.add(m, pos, r, velocities=[(v / 2, 0, 0), (-v / 2, 0, 0)])
        w.step(steps)
        vel = w.particles.velocities
        self.assertEqual(w.contact_count, 0, "still in contact")
        w.particles.remove(ids)
        return (vel[1, 0] - vel[0, 0]) / v

    def test_linear_restitution(self):
        r, rho, k = 0.005, 2500.0, 5e4  # two default materials of 1e5 N/m in series
        mstar = sphere_mass(r, rho) / 2
        for e in (0.2, 0.5, 0.9):
            with self.subTest(e=e):
                w, m = linear_world(3, e)
                self.assertAlmostEqual(w.pair(m, m).normal_stiffness, k)
                tc = linear_contact_time(k, mstar, e)
                ratio = self.collide(w, m, r, 1.0, tc / 50, 120)
                self.assertAlmostEqual(ratio, e, delta=0.01 * e)
                w.close()

    def test_hertz_restitution(self):
        """Hertz with Tsuji damping rebounds with e; the step from the
        Hertz duration 2.94 δmax/v, δmax = (15 m* v² / (16 E* √R*))^(2/5)."""
        r, rho, E, nu, v = 0.005, 7800.0, 1e8, 0.3, 1.0
        mstar, rstar = sphere_mass(r, rho) / 2, r / 2
        estar = E / (2 * (1 - nu * nu))
        dmax = (15 * mstar * v * v / (16 * estar * math.sqrt(rstar))) ** 0.4
        tc = 2.94324 * dmax / v
        for e in (0.3, 0.8):
            with self.subTest(e=e), demill.World(3, gravity=(0, 0, 0)) as w:
                m = w.material(density=rho, youngs_modulus=E, poisson_ratio=nu, restitution=e)
                w.pair(m, m, normal=Normal.HERTZ, damping=Damping.RESTITUTION)
                self.assertAlmostEqual(w.pair(m, m).restitution, e)
                ratio = self.collide(w, m, r, v, tc / 50, 150)
                self.assertAlmostEqual(ratio, e, delta=0.01 * e)


class Contacts(unittest.TestCase):
    def test_hookes_law_in_a_resting_contact(self):
        """Two overlapping particles at rest: one contact, overlap 2r - d,
        normal force k δ along the line of centres, equal and opposite."""
        r, d, k = 0.01, 0.0195, 2e4
        w, m = linear_world(3, gravity=(0, 0, 0))
        w.pair(m, m, damping=Damping.NONE, normal_stiffness=k)
        a, b = w.particles.add(m, [(0, 0, 0), (0, d, 0)], r)
        w.step(0)
        c = w.contacts
        self.assertEqual(len(c), 1)
        ida, idb = c.ids()
        self.assertEqual({int(ida[0]), int(idb[0])}, {int(a), int(b)})
        self.assertAlmostEqual(c.overlaps[0], 2 * r - d, delta=1e-15)
        sign = 1.0 if ida[0] == a else -1.0   # the normal points from a to b
        np.testing.assert_allclose(c.normals[0], [0, sign, 0], atol=1e-15)
        np.testing.assert_allclose(c.normal_forces[0], [0, -sign * k * (2 * r - d), 0],
                                   rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(c.points[0], [0, d / 2, 0], atol=1e-15)
        np.testing.assert_allclose(c.tangential_forces[0], 0, atol=0)
        f = w.particles.forces
        np.testing.assert_allclose(f[0], -f[1], atol=1e-15)
        self.assertAlmostEqual(np.linalg.norm(f[0]), k * (2 * r - d), delta=1e-12)
        self.assertAlmostEqual(w.energy(Energy.ELASTIC_NORMAL), 0.5 * k * (2 * r - d) ** 2,
                               delta=1e-15)
        w.close()


class EnergyAndMass(unittest.TestCase):
    def test_masses(self):
        with demill.World(3) as w:
            m = w.material(density=7800)
            ids = w.particles.add(m, [(0, 0, 0), (1, 0, 0)], [0.01, 0.02])
            np.testing.assert_allclose(w.particles.masses,
                                       [sphere_mass(0.01, 7800), sphere_mass(0.02, 7800)],
                                       rtol=1e-14)
            w.particle(ids[0]).radius = 0.02   # the mass follows
            self.assertAlmostEqual(w.particle(ids[0]).mass, sphere_mass(0.02, 7800), delta=1e-12)
            m.density = 1000                   # so do the particles of a material
            self.assertAlmostEqual(w.particle(ids[1]).mass, sphere_mass(0.02, 1000), delta=1e-12)
        with demill.World(2, disc_thickness=0.003) as w:
            m = w.material(density=2000)
            w.particles.add(m, (0, 0, 0), 0.01)
            self.assertAlmostEqual(w.particles.masses[0], math.pi * 1e-4 * 0.003 * 2000,
                                   delta=1e-15)

    def test_bouncing_ball_keeps_its_energy_balance(self):
        """A ball dropped on a floor: the balance starts at m g h, stays
        there while contacts dissipate, and kinetic energy is ½ m v²."""
        r, h, rho = 0.01, 0.05, 7800.0
        with demill.World(3, time_step=2e-6) as w:
            steel = w.material(density=rho, youngs_modulus=1e8, restitution=0.7)
            w.pair(steel, steel, normal=Normal.HERTZ, damping=Damping.RESTITUTION)
            w.add_plane(steel, (0, 0, 0), (0, 1, 0))
            (pid,) = w.particles.add(steel, (0, h, 0), r)
            mass = sphere_mass(r, rho)
            e0 = w.energy(Energy.TOTAL)
            self.assertAlmostEqual(e0, mass * 9.81 * h, delta=1e-12)
            w.step(100000)  # 0.2 s: about three bounces
            e = w.energies()
            self.assertGreater(e[Energy.DISSIPATED], 0.3 * e0)
            self.assertAlmostEqual(e[Energy.TOTAL], e0, delta=1e-3 * e0)
            v = w.particle(pid).velocity
            self.assertAlmostEqual(e[Energy.KINETIC_TRANSLATIONAL], 0.5 * mass * v @ v,
                                   delta=1e-15)
            parts = (Energy.KINETIC_TRANSLATIONAL, Energy.KINETIC_ROTATIONAL, Energy.POTENTIAL,
                     Energy.ELASTIC_NORMAL, Energy.ELASTIC_TANGENTIAL, Energy.DISSIPATED)
            self.assertAlmostEqual(sum(e[k] for k in parts) - e[Energy.WALL_WORK],
                                   e[Energy.TOTAL], delta=1e-12)


class Walls(unittest.TestCase):
    def test_motion_is_exact(self):
        """A wall moving at v and turning at ω: its centre is at c + v t,
        its normal turned by ω t."""
        dt, n = 1e-4, 1000
        v, omega = np.array([0.1, 0.0, 0.0]), 2.0
        with demill.World(3, time_step=dt) as w:
            m = w.material()
            wall = w.add_plane(m, (0, 0, 0), (0, 2, 0))
            np.testing.assert_array_equal(wall.normal, [0, 1, 0])
            wall.set_motion(velocity=v, angular_velocity=(0, 0, omega), centre=(0, 0, 0))
            w.step(n)
            t = n * dt
            np.testing.assert_allclose(wall.centre, v * t, atol=1e-15)
            np.testing.assert_allclose(wall.velocity, v)
            np.testing.assert_allclose(wall.angular_velocity, [0, 0, omega])
            np.testing.assert_allclose(wall.normal, [-math.sin(omega * t), math.cos(omega * t), 0],
                                       atol=1e-12)
            self.assertEqual(w.walls, [wall])
            wall.remove()
            with self.assertRaises(demill.InvalidHandle):
                wall.point


class WallLoads(unittest.TestCase):
    def test_resting_ball_loads_one_triangle(self):
        """A ball of mass m at rest on a floor of two triangles of 0.02 m²
        each, placed at its equilibrium overlap m g / k: after T = 500
        steps the loaded triangle holds m g and m g T (statics), its mean
        pressure is m g / 0.02 m², the other nothing; a plane has no area;
        stopped, the loads are gone."""
        g, k, r, dt, n = 9.81, 1e5, 0.01, 1e-5, 500
        w, m = linear_world(3, gravity=(0, -g, 0))
        w.time_step = dt
        w.pair(m, m, normal_stiffness=k)
        floor = w.add_mesh(m, [(-0.1, 0, -0.1), (0.1, 0, -0.1), (0.1, 0, 0.1), (-0.1, 0, 0.1)],
                           [(0, 1, 2), (0, 2, 3)])
        plane = w.add_plane(m, (0, -1, 0), (0, 1, 0))
        m.density = 7800
        mg = sphere_mass(r, 7800) * g
        w.particles.add(m, [(0.03, r - mg / k, -0.02)], r)
        floor.loads_start()
        plane.loads_start()
        w.step(n)
        loads = floor.loads()
        self.assertAlmostEqual(loads.interval, n * dt, delta=1e-15)
        np.testing.assert_allclose(loads.normal, [mg, 0], rtol=1e-9)
        np.testing.assert_allclose(loads.impulse, [mg * n * dt, 0], rtol=1e-9)
        np.testing.assert_allclose(loads.area, [0.02, 0.02], rtol=1e-12)
        np.testing.assert_allclose(loads.mean_pressure, [mg / 0.02, 0], rtol=1e-9)
        self.assertTrue(math.isnan(plane.loads().area[0]))
        floor.loads_stop()
        with self.assertRaises(demill.InvalidValue):
            floor.loads()
        w.close()


class FiniteWalls(unittest.TestCase):
    def test_closest_points_and_motions(self):
        """A sphere of radius 0.01 held 0.007 from a face (the linear law,
        k = 5e4 N/m) feels k (r - d) = 150 N along the face's normal; 0.005
        from a rim along a 3-4-5 direction, 250 N along it. A harmonic
        translation puts the wall at A sin(2πft) and gives it the velocity
        2πfA cos(2πft); a surface velocity reads back as set."""
        w, m = linear_world(3)
        w.pair(m, m, damping=demill.Damping.NONE, tangential=Tangential.NONE)
        r, k = 0.01, 5e4
        walls = [w.add_cylinder(m, (0, 0, 0), (0, 0, 1), 0.1, 0.2, demill.Caps.END),
                 w.add_cone(m, (1, 0, 0), (0, 0, 1), 0.0, 0.1, 0.1),
                 w.add_disc(m, (2, 0, 0), (0, 0, 1), 0.1, 0.05),
                 w.add_rectangle(m, (3, 0, 0), (0, 1, 0), (1, 0, 0), 0.1, 0.05)]
        cases = [((0.05, 0, 0.2 - 0.007), (0, 0, -150)),         # the cylinder's cap
                 ((0.103, 0, 0.204), (150, 0, 200)),             # its convex rim
                 ((2.047, 0, 0.004), (-150, 0, 200)),            # the annulus's hole rim
                 ((3.02, 0.007, 0.01), (0, 150, 0))]             # the rectangle's face
        for x, f in cases:
            (pid,) = w.particles.add(m, [x], r)
            w.step(0)
            np.testing.assert_allclose(w.particle(pid).force, f, atol=1e-9 * k * r)
            w.particles.remove([pid])
        self.assertEqual(len(w.walls), 4)
        dt, n, a, freq = 1e-4, 37, 0.002, 5.0
        w.time_step = dt
        rect = walls[3]
        rect.set_harmonic(demill.Harmonic.TRANSLATION, (0, 2, 0), a, freq)
        rect.set_surface_velocity((0.5, 0, 0))
        w.step(n)
        t, om = n * dt, 2 * math.pi * freq
        np.testing.assert_allclose(rect.centre, (3, a * math.sin(om * t), 0), atol=1e-15)
        np.testing.assert_allclose(rect.velocity, (0, a * om * math.cos(om * t), 0), atol=1e-14)
        np.testing.assert_array_equal(rect.surface_velocity, (0.5, 0, 0))
        with self.assertRaises(demill.InvalidValue):
            w.add_disc(m, (0, 0, 0), (0, 0, 1), 0.1, 0.1)
        with self.assertRaises(demill.UnknownKey):
            rect.set_harmonic(7, (0, 1, 0), a, freq)
        w.close()
        w2, m2 = linear_world(2)
        with self.assertRaises(demill.DimensionError):
            w2.add_cylinder(m2, (0, 0, 0), (0, 1, 0), 0.1, 0.2)
        w2.close()


class DrumProfiles(unittest.TestCase):
    def test_four_lifters_from_one_profile(self):
        """One lifter's open profile (0.02 m high, 0.02 m wide at 6 o'clock
        in a drum 0.3 m across) repeated 4 times: a ball of radius 0.005
        pressed 1e-4 m onto each lifter's top (radius 0.13) feels k delta =
        10 N (k = 1e5 N/m) towards the axis, and the drum feels the
        reactions: no torque (they are radial), no net force (they
        cancel)."""
        w, m = linear_world(3)
        w.pair(m, m, damping=demill.Damping.NONE, tangential=Tangential.NONE,
               normal_stiffness=1e5)
        drum = w.add_drum(m, diameter=0.3, length=0.1)
        hw, rs, ri = 0.01, math.sqrt(0.15 ** 2 - 0.01 ** 2), 0.13
        profile = [(t, -r) for r, t in [(rs, -hw), (ri, -hw), (ri, hw), (rs, hw)]]
        wall = drum.add_profile(m, demill.DrumPart.LIFTERS, profile, copies=4)
        self.assertEqual(wall.mesh_size, (4 * 4 * 2, 4 * 3 * 2))
        r, delta = 0.005, 1e-4
        for k in range(4):
            a = 1.5 * math.pi + k * math.pi / 2
            rho = ri - r + delta
            (pid,) = w.particles.add(m, [(rho * math.cos(a), rho * math.sin(a), 0.01)], r)
            w.step(0)
            np.testing.assert_allclose(w.particle(pid).force,
                                       (-10 * math.cos(a), -10 * math.sin(a), 0), atol=1e-9)
        self.assertAlmostEqual(drum.torque, 0.0, delta=1e-12)
        with self.assertRaisesRegex(demill.InvalidValue, "outside the shell"):
            drum.add_profile(m, demill.DrumPart.LIFTERS, [(0, 0), (0.2, 0)])
        with self.assertRaises(demill.NotFinite):
            drum.add_profile(m, demill.DrumPart.LIFTERS, [(0, 0), (math.nan, 0)])
        self.assertEqual(len(w.walls), 1)
        w.close()

    def test_a_lifted_drum_does_the_work(self):
        """A drum raised at 0.5 m/s for 0.1 s with a ball of radius 0.01
        (7800 kg/m3) resting on its shell, the ball given the drum's
        velocity: the drum rises 0.05 m and does the work m g v t of lifting
        the ball, and its power is m g v."""
        w, m = linear_world(3, gravity=(0, -9.81, 0))
        w.pair(m, m, normal_stiffness=1e5)
        m.density = 7800
        mat = m
        drum = w.add_drum(mat, diameter=0.3)
        r = 0.01
        mass = 7800 * 4 / 3 * math.pi * r ** 3
        (pid,) = w.particles.add(mat, [(0, -(0.15 - r + mass * 9.81 / 1e5), 0)], r)
        w.step(5000)
        drum.velocity_y = 0.5
        w.particle(pid).velocity = (0, 0.5, 0)
        e0 = drum.energy_in
        w.step(10000)
        self.assertAlmostEqual(drum.center_y, 0.05, delta=1e-12)
        self.assertAlmostEqual(drum.current_velocity_y, 0.5, delta=1e-15)
        work = mass * 9.81 * 0.5 * 0.1
        self.assertAlmostEqual((drum.energy_in - e0) / work, 1.0, delta=1e-6)
        self.assertAlmostEqual(drum.power / (mass * 9.81 * 0.5), 1.0, delta=1e-6)
        w.close()


class TimeStepGuide(unittest.TestCase):
    def test_linear_suggestion(self):
        """For a linear pair: contact time π/ω (undamped: e = 1 is not
        allowed, so via the damped formula), stability limit 2/ω."""
        r, k = 0.005, 5e4
        w, m = linear_world(3, 1.0)
        w.particles.add(m, [(0, 0, 0), (1, 0, 0)], r)
        mstar = sphere_mass(r, 2500) / 2
        ts = w.suggest_time_step(1.0, 50)
        self.assertAlmostEqual(ts.critical, 2 / math.sqrt(k / mstar), delta=1e-9 * ts.critical)
        self.assertAlmostEqual(ts.contact_time, math.pi / math.sqrt(k / mstar),
                               delta=1e-9 * ts.contact_time)
        self.assertAlmostEqual(ts.suggested, ts.contact_time / 50, delta=1e-9 * ts.suggested)
        w.close()


if __name__ == "__main__":
    unittest.main()


class MeshWalls(unittest.TestCase):
    def settle_on(self, dim, add_floor):
        """A ball of 1 cm settles on a floor at y = 0 (0.1 s with e = 0.2):
        the floor then carries its weight m g."""
        w, m = linear_world(dim, 0.2, gravity=(0, -9.81, 0))
        w.time_step = 1e-5
        wall = add_floor(w, m)
        (pid,) = w.particles.add(m, (0.0013, 0.0101, 0.0007 if dim == 3 else 0.0), 0.01)
        w.step(10000)
        weight = w.particle(pid).mass * 9.81
        np.testing.assert_allclose(wall.force, (0, -weight, 0), rtol=0, atol=1e-9 * weight)
        self.assertEqual(w.wall_contact_count, 1)
        w.close()

    def test_mesh_floor_carries_the_weight(self):
        """Two triangles of a square, touched from above (their normal
        points down: a mesh has two sides)."""
        verts = [(-1, 0, -1), (1, 0, -1), (1, 0, 1), (-1, 0, 1)]
        tris = [(0, 1, 2), (0, 2, 3)]
        self.settle_on(3, lambda w, m: w.add_mesh(m, verts, tris))

    def test_stl_floor_carries_the_weight(self):
        """The same square as an ASCII STL file in mm (scale 0.001), from
        its path and from its bytes, shifted by the transform's t."""
        text = "solid floor\n"
        for tri in ((0, 1, 2), (0, 2, 3)):
            corners = [(-1000, -500, -1000), (1000, -500, -1000), (1000, -500, 1000),
                       (-1000, -500, 1000)]
            text += " facet normal 0 1 0\n  outer loop\n"
            text += "".join("   vertex %g %g %g\n" % corners[k] for k in tri)
            text += "  endloop\n endfacet\n"
        text += "endsolid floor\n"
        shift = (np.eye(3), (0, 0.5, 0))
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "floor.stl")
            with open(path, "w") as f:
                f.write(text)
            self.settle_on(3, lambda w, m: w.add_stl(m, path, 0.001, shift))
            with demill.World(3) as w:
                with self.assertRaisesRegex(demill.FileError, "nothing.stl"):
                    w.add_stl(w.material(), os.path.join(tmp, "nothing.stl"))
        self.settle_on(3, lambda w, m: w.add_stl(m, text.encode(), 0.001, shift))
        with demill.World(3) as w:
            with self.assertRaisesRegex(demill.FormatError, "line 3"):
                w.add_stl(w.material(), text.replace("outer", "inner").encode())

    def test_polyline_floor_carries_the_weight(self):
        pts = [(-1, 0), (0, 0), (1, 0)]
        self.settle_on(2, lambda w, m: w.add_polyline(m, pts))

    def test_mesh_size_and_errors(self):
        with demill.World(3) as w:
            m = w.material()
            wall = w.add_mesh(m, [(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)])
            self.assertEqual(wall.mesh_size, (3, 1))
            with self.assertRaisesRegex(demill.InvalidValue, "triangle 0.*zero area"):
                w.add_mesh(m, [(0, 0, 0), (1, 0, 0), (2, 0, 0)], [(0, 1, 2)])
            with self.assertRaisesRegex(demill.DimensionError, "2D"):
                w.add_polyline(m, [(0, 0), (1, 0)])
            self.assertEqual(len(w.walls), 1)
        with demill.World(2) as w:
            m = w.material()
            self.assertEqual(w.add_polyline(m, [(0, 0), (1, 0), (1, 1)], closed=True).mesh_size,
                             (3, 3))
            with self.assertRaisesRegex(demill.DimensionError, "3D"):
                w.add_mesh(m, [(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 1, 2)])
