"""Snapshots, checkpoints (files, bytes, pickle) and object listing through
the binding: a state taken, stepped from and brought back gives bitwise the
same run; bad checkpoints raise FormatError or FileError with the
library's message."""

import os
import pickle
import tempfile
import unittest

import numpy as np
from helpers import linear_world

import demill
from demill import Kind


def scene():
    """A small 2D box of bouncing, rubbing discs: contacts with history."""
    w, m = linear_world(2, 0.6, gravity=(0, -9.81, 0))
    w.pair(m, m, tangential=demill.Tangential.SPRING)
    w.time_step = 2e-5
    for point, normal in (((0, 0, 0), (0, 1, 0)), ((-0.05, 0, 0), (1, 0, 0)),
                          ((0.05, 0, 0), (-1, 0, 0))):
        w.add_plane(m, point, normal)
    rng = np.random.default_rng(4)
    x = np.zeros((40, 3))
    x[:, 0] = np.tile(np.linspace(-0.04, 0.04, 8), 5) + rng.uniform(-1e-4, 1e-4, 40)
    x[:, 1] = np.repeat(np.linspace(0.006, 0.06, 5), 8)
    w.particles.add(m, x, 0.0045, velocities=rng.normal(0, 0.2, (40, 3)) * [1, 1, 0])
    w.step(500)
    return w


def state(w):
    """Positions and velocities as bytes, for bitwise comparison."""
    return w.particles.positions.tobytes() + w.particles.velocities.tobytes()


class Snapshots(unittest.TestCase):
    def test_restore_repeats_the_run_bitwise(self):
        with scene() as w, w.snapshot() as snap:
            w.step(1000)
            after, t = state(w), w.time
            snap.restore()
            self.assertNotEqual(state(w), after)
            w.step(1000)
            self.assertEqual(state(w), after)
            self.assertEqual(w.time, t)
            with demill.World(3) as other:  # another world takes its dimension
                snap.restore(other)
                self.assertEqual(other.dimension, 2)
                other.step(1000)
                self.assertEqual(state(other), after)
        self.assertTrue(snap.closed)
        with self.assertRaises(ValueError):
            snap.restore()


class Checkpoints(unittest.TestCase):
    def test_file_restart_is_bitwise(self):
        """2n steps, or n steps, save, load into a new world, n steps."""
        with scene() as a, scene() as b, tempfile.TemporaryDirectory() as d:
            a.step(2000)
            b.step(1000)
            path = os.path.join(d, "run.dmc")
            b.save(path)
            with demill.World.load(path) as c:
                c.step(1000)
                self.assertEqual(state(c), state(a))
                self.assertEqual(c.step_count, a.step_count)
                self.assertEqual(c.energy(demill.Energy.TOTAL), a.energy(demill.Energy.TOTAL))

    def test_bytes_and_pickle(self):
        with scene() as w:
            data = w.to_bytes()
            self.assertIsInstance(data, bytes)
            copy = pickle.loads(pickle.dumps(w))
            with copy:
                self.assertEqual(copy.to_bytes(), data)
                self.assertEqual(len(copy.materials), 1)
                self.assertEqual(len(copy.walls), 3)
                self.assertEqual(copy.materials[0].density, w.materials[0].density)
                np.testing.assert_array_equal(copy.ids(Kind.PARTICLE), copy.particles.ids())
                w.step(300)
                copy.step(300)
                self.assertEqual(state(copy), state(w))
                copy.load_bytes(data)
                self.assertEqual(copy.to_bytes(), data)

    def test_bad_checkpoints(self):
        with scene() as w, tempfile.TemporaryDirectory() as d:
            data = bytearray(w.to_bytes())
            before = w.to_bytes()
            for bad in (data[: len(data) // 2], data[:10], b"", b"not a checkpoint" * 10):
                with self.assertRaises(demill.FormatError) as cm:
                    w.load_bytes(bad)
                self.assertTrue(cm.exception.message)
            data[len(data) // 2] ^= 0xFF
            with self.assertRaises(demill.FormatError):
                w.load_bytes(data)
            self.assertEqual(w.to_bytes(), before, "a failed load changes nothing")
            missing = os.path.join(d, "missing.dmc")
            with self.assertRaises(demill.FileError) as cm:
                demill.World.load(missing)
            self.assertIn(missing, cm.exception.message)
            with self.assertRaises(demill.FileError):
                w.save(os.path.join(d, "no", "such", "folder.dmc"))


class Listing(unittest.TestCase):
    def test_objects_are_listed(self):
        with demill.World(3) as w:
            a, b = w.material(), w.material()
            wall = w.add_plane(a, (0, 0, 0), (0, 1, 0))
            self.assertIsNone(w.drum)
            drum = w.add_drum(b)
            ids = w.particles.add(a, [(0, 0.1, 0), (0, 0.2, 0)], 0.01)
            self.assertEqual(w.materials, [a, b])
            self.assertEqual(w.walls, [wall])
            self.assertEqual(w.drum, drum)
            np.testing.assert_array_equal(w.ids(Kind.PARTICLE), ids)
            with self.assertRaises(demill.UnknownKey):
                w.ids(99)


if __name__ == "__main__":
    unittest.main()
