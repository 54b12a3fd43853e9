"""The binding's API: errors carry the library's code and message, NumPy
arrays go in and out without loss, parameters match the library's
metadata, and object lifetimes are safe."""

import gc
import unittest
import weakref

import numpy as np
from helpers import linear_world

import demill
from demill import (DrumKey, Energy, Integrator, Kind, MaterialKey, Normal, PairKey,
                    ParticleField, Tangential, WorldKey)


class Errors(unittest.TestCase):
    def setUp(self):
        self.w, self.m = linear_world(3)

    def tearDown(self):
        self.w.close()

    def assertFails(self, exc, *words):
        """A context checking the exception class and words of the message."""
        test = self

        class Check:
            def __enter__(self):
                return self

            def __exit__(self, kind, value, tb):
                test.assertIsNotNone(value, f"{exc.__name__} not raised")
                test.assertIs(type(value), exc, value)
                for word in words:
                    test.assertIn(word, value.message)
                test.assertEqual(value.code, demill.errors.ERRORS_BY_CLASS[exc])
                test.assertIn(value.message, str(value))
                return True
        return Check()

    def test_parameter_errors_name_the_parameter(self):
        w = self.w
        with self.assertFails(demill.InvalidValue, "world.time_step", "-1"):
            w.time_step = -1
        with self.assertFails(demill.NotFinite, "world.skin"):
            w.skin = float("nan")
        with self.assertFails(demill.ReadOnly, "world.particle_count"):
            w.particle_count = 3
        with self.assertFails(demill.UnknownKey, "199"):
            w.get(199)
        with self.assertFails(demill.UnknownKey, "world.integrator"):
            w.integrator = 7
        with self.assertFails(demill.InvalidValue, "world.integrator", "whole"):
            w.integrator = 1.5
        with self.assertFails(demill.InvalidValue, "material.poisson_ratio"):
            self.m.poisson_ratio = 0.5
        with self.assertFails(demill.InvalidValue, "pair.restitution"):
            w.pair(self.m, self.m).restitution = -0.5
        with self.assertFails(demill.UnknownKey, "pair.tangential"):
            w.pair(self.m, self.m, tangential=9)
        self.assertEqual(w.time_step, 1e-5, "a failed call changes nothing")

    def test_vector_parameters_are_all_or_nothing(self):
        with demill.World(2) as w:
            with self.assertFails(demill.DimensionError, "gravity"):
                w.gravity = (1.0, -2.0, 3.0)
            np.testing.assert_array_equal(w.gravity, [0, -9.81, 0])
            w.gravity = (1.0, -2.0, 0.0)
            np.testing.assert_array_equal(w.gravity, [1, -2, 0])

    def test_particle_errors_name_the_particle(self):
        w, m = self.w, self.m
        with self.assertFails(demill.InvalidValue, "particle 1", "radius"):
            w.particles.add(m, [(0, 0, 0), (1, 0, 0)], [0.01, -0.01])
        self.assertEqual(len(w.particles), 0)
        with self.assertFails(demill.NotFinite, "particle 0"):
            w.particles.add(m, [(np.inf, 0, 0)], 0.01)
        ids = w.particles.add(m, [(0, 0, 0), (0.05, 0, 0)], 0.01)
        with self.assertFails(demill.Overlap):
            w.particles.add(m, (0.005, 0, 0), 0.01, no_overlap=True)
        with self.assertFails(demill.ReadOnly):
            w.particles.masses = [1.0, 2.0]
        with self.assertFails(demill.InvalidValue):
            w.particles.write(ParticleField.POSITION, np.zeros((3, 3)))
        with self.assertFails(demill.UnknownKey):
            w.particles.read(77)
        with self.assertFails(demill.DimensionError):
            w.particles.angles
        w.particles.remove(ids[0])
        with self.assertFails(demill.InvalidHandle):
            w.particle(ids[0]).position
        with self.assertFails(demill.InvalidHandle):
            w.particles.remove(ids)  # nothing removed
        self.assertEqual(len(w.particles), 1)
        with demill.World(2) as w2:
            m2 = w2.material()
            with self.assertFails(demill.DimensionError):
                w2.particles.add(m2, (0, 0, 0.1), 0.01)
            with self.assertFails(demill.InvalidHandle, "material"):
                w2.particles.add(m, (0, 0, 0), 0.01)  # a material of another world

    def test_run_errors(self):
        with demill.World(3) as w:
            a, b = w.material(), w.material()
            w.pair(a, a, normal=Normal.LINEAR)
            w.particles.add(a, (0, 0, 0), 0.01)
            w.particles.add(b, (1, 0, 0), 0.01)
            with self.assertFails(demill.NoContactModel):
                w.step()
            self.assertEqual(w.step_count, 0)

    def test_rigid_materials(self):
        """A rigid wall gives the pair the ball's own stiffness in full (not
        half, as two equal springs in series would); a rigid ball on it is
        refused, with the world unchanged."""
        w, m = linear_world(3)
        steel = w.material(rigid=True)
        self.assertIs(steel.rigid, True)
        w.pair(m, steel, normal=Normal.LINEAR)
        self.assertEqual(w.pair(m, steel).normal_stiffness, m.stiffness)
        w.add_plane(steel, (0, 0, 0), (0, 1, 0))
        w.particles.add(m, [(0, 0.0099, 0)], 0.01)
        w.step(10)
        w.particles.add(steel, [(0.1, 0.0099, 0)], 0.01)
        with self.assertFails(demill.NoContactModel, "both rigid", "deformable"):
            w.step()
        self.assertEqual(w.step_count, 10)
        steel.rigid = False
        w.pair(steel, steel, normal=Normal.LINEAR)
        w.step()
        w.close()

    def test_cohesion_keys(self):
        """The work of adhesion is derived from the surface energies, 2√(γ_a
        γ_b); the cohesion law comes back as its enum."""
        w, m = linear_world(3)
        m.surface_energy = 0.04
        other = w.material(surface_energy=0.09)
        self.assertAlmostEqual(w.pair(m, m).adhesion_work, 0.08, places=15)
        self.assertAlmostEqual(w.pair(m, other).adhesion_work, 0.12, places=15)
        pair = w.pair(m, other, normal=Normal.HERTZ, cohesion=demill.Cohesion.CAPILLARY,
                      liquid_volume=2e-12, contact_angle=0.2)
        self.assertIs(pair.cohesion, demill.Cohesion.CAPILLARY)
        self.assertEqual((pair.liquid_volume, pair.surface_tension, pair.contact_angle),
                         (2e-12, 0.072, 0.2))
        w.close()

    def test_unstable_run_is_reported_and_rolled_back(self):
        """A time step beyond a pair's stability limit is refused before the
        run starts, naming the pair and the limit; a chain of particles
        pressed between two walls, whose fastest mode is √2 times one
        pair's, blows up within that limit, and the watchdog stops the run
        with a message naming a particle and the time."""
        w, m = linear_world(3, gravity=(0, -9.81, 0))
        w.add_plane(m, (0, 0, 0), (0, 1, 0))
        w.particles.add(m, [(0, 0.0099, 0)], 0.01)
        w.time_step = 5 * w.suggest_time_step().critical
        with self.assertFails(demill.Unstable, "particle-wall", "largest stable time step"):
            w.step(5000)
        self.assertEqual(w.step_count, 0)
        w.close()

        w, m = linear_world(2, restitution=1.0)
        r, n = 0.005, 10
        x = [((r - 0.01 * r) + i * (1.99 * r), 0, 0) for i in range(n)]
        v = [(0.01 if i % 2 else -0.01, 0, 0) for i in range(n)]
        w.particles.add(m, x, r, velocities=v)
        w.add_plane(m, (0, 0, 0), (1, 0, 0))
        w.add_plane(m, (x[-1][0] + 0.99 * r, 0, 0), (-1, 0, 0))
        w.time_step = 0.9 * w.suggest_time_step().critical
        with self.assertFails(demill.Unstable, "particle", "back at t ="):
            w.step(5000)
        self.assertTrue(np.all(np.isfinite(w.particles.positions)))
        w.close()

    def test_python_side_checks(self):
        w, m = self.w, self.m
        with self.assertRaises(ValueError):
            w.step(-1)  # ctypes would wrap it to 2^64 - 1
        with self.assertRaises(TypeError):
            w.step(1.5)
        with self.assertRaises(ValueError):
            w.particles.add(m, np.zeros((2, 2)), 0.01)
        with self.assertRaises(ValueError):
            w.particles.add(m, np.zeros((2, 3)), [0.01] * 3)
        with self.assertRaises(TypeError):
            w.material(densty=3)
        with self.assertRaises(ValueError):
            w.particles.read(ParticleField.POSITION, out=np.empty((0, 2)))
        with self.assertFails(demill.InvalidValue, "create"):
            demill.World(4)
        with self.assertFails(demill.UnknownKey, "999"):
            demill.param_info(999)


class Arrays(unittest.TestCase):
    def test_positions_round_trip_bitwise(self):
        rng = np.random.default_rng(1)
        with demill.World(3) as w:
            m = w.material()
            x = rng.uniform(-1, 1, (500, 3))
            r = rng.uniform(1e-4, 1e-3, 500)
            ids = w.particles.add(m, x, r)
            self.assertEqual(ids.dtype, np.uint64)
            self.assertTrue(all(demill.id_kind(i) == Kind.PARTICLE for i in ids))
            np.testing.assert_array_equal(w.particles.ids(), ids)
            np.testing.assert_array_equal(w.particles.material_ids(), np.full(500, m.id))
            np.testing.assert_array_equal(w.particles.positions, x)
            np.testing.assert_array_equal(w.particles.radii, r)
            y = rng.uniform(-1, 1, (500, 3))
            w.particles.positions = y
            out = np.empty((500, 3))
            self.assertIs(w.particles.read(ParticleField.POSITION, out=out), out)
            self.assertEqual(out.tobytes(), y.tobytes())
            v = np.asfortranarray(rng.normal(size=(500, 3)))  # copied to C order
            w.particles.velocities = v
            np.testing.assert_array_equal(w.particles.velocities, v)
            p = w.particle(ids[7])
            np.testing.assert_array_equal(p.position, y[7])
            p.velocity = (1, 2, 3)
            np.testing.assert_array_equal(w.particles.velocities[7], [1, 2, 3])
            self.assertEqual(p.radius, r[7])
            self.assertIsInstance(p.radius, float)
            w.particles.remove(ids[:100])
            self.assertEqual(len(w.particles), 400)
            self.assertEqual(set(w.particles.ids().tolist()), set(ids[100:].tolist()))

    def test_2d_angles(self):
        with demill.World(2) as w:
            m = w.material()
            (pid,) = w.particles.add(m, (0, 0, 0), 0.01)
            w.particle(pid).angle = 0.25
            np.testing.assert_array_equal(w.particles.angles, [0.25])
            w.particle(pid).angular_velocity = (0, 0, 3)
            with self.assertRaises(demill.DimensionError):
                w.particle(pid).angular_velocity = (1, 0, 0)
            with self.assertRaises(ValueError):
                w.particle(pid).position = (0, 0)
            with self.assertRaises(demill.DimensionError):
                w.particle(pid).orientation

    def test_3d_orientations(self):
        with demill.World(3) as w:
            m = w.material()
            ids = w.particles.add(m, [(0, 0, 0), (1, 0, 0)], 0.01)
            np.testing.assert_array_equal(w.particles.orientations, [(1, 0, 0, 0)] * 2)
            p = w.particle(ids[1])
            p.orientation = (0, 0, 3, 4)  # normalised: (0, 0, 0.6, 0.8)
            np.testing.assert_allclose(p.orientation, (0, 0, 0.6, 0.8), rtol=0, atol=1e-16)
            w.particles.orientations = [(0.5, 0.5, 0.5, 0.5), (0, 1, 0, 0)]
            np.testing.assert_array_equal(w.particles.orientations[1], (0, 1, 0, 0))
            with self.assertRaises(ValueError):
                p.orientation = (1, 0, 0)
            with self.assertRaises(demill.InvalidValue):
                p.orientation = (0, 0, 0, 0)
            np.testing.assert_array_equal(p.orientation, (0, 1, 0, 0))


class Parameters(unittest.TestCase):
    CLASSES = ((demill.World, WorldKey, "world"), (demill.Material, MaterialKey, "material"),
               (demill.Pair, PairKey, "pair"), (demill.Drum, DrumKey, "drum"))

    def test_every_key_is_a_property_named_after_it(self):
        for cls, keys, prefix in self.CLASSES:
            props = {p.key: name for name, p in vars(cls).items()
                     if isinstance(p, demill._core.Param)}
            for key in keys:
                with self.subTest(key=key):
                    info = demill.param_info(key)
                    self.assertEqual(f"{prefix}.{props[key]}", info.name)

    def test_defaults_and_bounds_match_the_metadata(self):
        """A fresh world, material, pair of default materials and drum hold
        the defaults demill_param_bounds gives; the bounds are enforced."""
        with demill.World(3) as w:
            a, b = w.material(), w.material()
            objects = {"world": w, "material": a, "pair": w.pair(a, b),
                       "drum": w.add_drum(a)}
            for _cls, keys, prefix in self.CLASSES:
                obj = objects[prefix]
                for key in keys:
                    info = demill.param_info(key)
                    with self.subTest(key=info.name):
                        self.assertLessEqual(info.lo, info.hi)
                        if key in (DrumKey.CRITICAL_SPEED,) or key >= 450 or (
                                prefix == "world" and key >= 150):
                            continue  # measurements
                        self.assertEqual(obj.get(key), info.default)
                        self.assertTrue(info.lo <= info.default <= info.hi)
                        if info.hi < 1e6 and info.unit not in ("enum", "bool"):
                            with self.assertRaises(demill.InvalidValue) as cm:
                                obj.set(key, info.hi * 1.5 + 1)
                            self.assertIn(info.name, cm.exception.message)
        self.assertEqual(demill.param_info(WorldKey.TIME_STEP).unit, "s")

    def test_enums_come_back_as_enums(self):
        w, m = linear_world(3)
        w.integrator = Integrator.SYMPLECTIC_EULER
        self.assertIs(w.integrator, Integrator.SYMPLECTIC_EULER)
        pair = w.pair(m, m, tangential=Tangential.MINDLIN, clamp_normal=False)
        self.assertIs(pair.tangential, Tangential.MINDLIN)
        self.assertIs(pair.normal, Normal.LINEAR)
        self.assertIs(pair.clamp_normal, False)
        self.assertIs(w.energy_tracking, True)
        self.assertEqual(w.dimension, 3)
        self.assertIsInstance(w.step_count, int)
        w.close()


class Lifetime(unittest.TestCase):
    def test_handles_keep_the_world_alive(self):
        w = demill.World(3)
        m = w.material(density=1234)
        ref = weakref.ref(w)
        del w
        gc.collect()
        self.assertIsNotNone(ref())
        self.assertEqual(m.density, 1234)
        del m
        gc.collect()
        self.assertIsNone(ref(), "the world is freed with its last handle")

    def test_closed_world_raises(self):
        with demill.World(3) as w:
            m = w.material()
            ps = w.particles
        self.assertTrue(w.closed)
        self.assertEqual(repr(w), "<demill.World closed>")
        for use in (lambda: w.step(), lambda: w.time_step, lambda: m.density,
                    lambda: ps.positions, lambda: w.material()):
            with self.assertRaises(demill.WorldClosed) as cm:
                use()
            self.assertIsInstance(cm.exception, demill.InvalidHandle)
            self.assertIn("closed", str(cm.exception))
        w.close()  # again: harmless

    def test_handles_compare_by_world_and_id(self):
        with demill.World(3) as w:
            m = w.material()
            self.assertEqual(m, demill.Material(w, m.id))
            self.assertEqual(len({m, demill.Material(w, int(m))}), 1)
            self.assertNotEqual(m, w.material())
            self.assertEqual(demill.id_kind(m), Kind.MATERIAL)


class Drum(unittest.TestCase):
    def test_speeds_fill_and_lifters(self):
        """ω_c = √(2 g / (D - d)); the speed keys are views of one value; a
        fill by count adds that many; power is -T ω."""
        D, d, g = 0.2, 0.01, 9.81
        with demill.World(2, time_step=2e-5) as w:
            steel = w.material(density=7800, restitution=0.5)
            w.pair(steel, steel, normal=Normal.LINEAR,
                   damping=demill.Damping.RESTITUTION, tangential=Tangential.COULOMB)
            drum = w.add_drum(steel, diameter=D, lifters=4, lifter_height=0.01,
                              lifter_width=0.01)
            self.assertEqual(drum.lifter_count, 4)
            ids = drum.fill(steel, demill.Sizes.CLASSES, [d, 1.0], demill.Fill.COUNT, 60, seed=3)
            self.assertEqual(len(ids), 60)
            np.testing.assert_array_equal(np.sort(w.particles.ids()), np.sort(ids))
            np.testing.assert_allclose(w.particles.radii, d / 2)
            wc = (2 * g / (D - d)) ** 0.5
            self.assertAlmostEqual(drum.critical_speed, wc, delta=1e-12)
            drum.speed_fraction = 0.6
            self.assertAlmostEqual(drum.speed, 0.6 * wc, delta=1e-12)
            self.assertAlmostEqual(drum.speed_rpm, 0.6 * wc * 60 / (2 * np.pi), delta=1e-9)
            lifter = drum.add_lifter(1.0, 0.01, 0.01)
            self.assertEqual((lifter.index, drum.lifter_count), (4, 5))
            self.assertAlmostEqual(lifter.angle, 1.0, delta=1e-12)
            drum.spectrum_start([0.005], 8, 1e-9, 1e-3)
            w.step(5000)
            self.assertAlmostEqual(drum.current_speed, 0.6 * wc, delta=1e-12)
            self.assertAlmostEqual(drum.angle, 0.6 * wc * 0.1, delta=1e-9)
            self.assertAlmostEqual(drum.power, -drum.torque * drum.current_speed,
                                   delta=1e-12 * (1 + abs(drum.power)))
            self.assertEqual(lifter.force.shape, (3,))
            self.assertIsInstance(lifter.energy, float)
            counts = drum.spectrum(8)
            classes = 2
            self.assertEqual(counts.shape, (classes * (classes + 1) // 2 + 2 * classes, 8))
            self.assertGreater(counts.sum(), 0)
            self.assertTrue(np.isnan(drum.power_mean), "no revolution yet")
            e = w.energies()
            self.assertGreater(e[Energy.WALL_WORK], 0)
            self.assertAlmostEqual(drum.energy_in, e[Energy.WALL_WORK],
                                   delta=1e-9 * e[Energy.WALL_WORK])
            drum.remove()
            with self.assertRaises(demill.InvalidHandle):
                drum.power

    def test_part_materials_and_force(self):
        """Each part has a material; the force on the drum is what its
        contacts take from the particles, M g - Σ f_i (Newton's third law:
        the particles' own contacts cancel in Σ f_i)."""
        with demill.World(2, time_step=2e-5) as w:
            steel, rubber = w.material(density=7800), w.material(density=1200)
            for m in (steel, rubber):
                w.pair(steel, m, normal=Normal.LINEAR, damping=demill.Damping.RESTITUTION,
                       tangential=Tangential.COULOMB)
            drum = w.add_drum(steel, diameter=0.2, lifters=4)
            self.assertEqual(drum.material(demill.DrumPart.LIFTERS), steel)
            drum.set_material(demill.DrumPart.LIFTERS, rubber)
            self.assertEqual(drum.material(demill.DrumPart.LIFTERS), rubber)
            self.assertEqual(drum.material(demill.DrumPart.SHELL), steel)
            with self.assertRaises(demill.DimensionError):
                drum.material(demill.DrumPart.CAPS)
            drum.fill(steel, demill.Sizes.CLASSES, [0.01, 1.0], demill.Fill.COUNT, 60, seed=3)
            weight = w.particles.masses.sum() * 9.81
            w.step(2000)
            taken = [0.0, -weight, 0.0] - w.particles.forces.sum(axis=0)
            np.testing.assert_allclose(drum.force, taken, rtol=0, atol=1e-12 * weight)


if __name__ == "__main__":
    unittest.main()
