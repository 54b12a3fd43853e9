"""The progress callback (reports, stopping, exceptions raised through it)
and VTK output through the binding."""

import os
import re
import tempfile
import unittest

from helpers import linear_world
from test_state import scene, state

import demill


class ProgressCallback(unittest.TestCase):
    def test_reports(self):
        """Every `every` steps and at the end, with the step count asked
        for and the world's time."""
        with scene() as w:
            seen = []
            w.on_progress(lambda p: seen.append(p), every=300)
            t0, dt = w.time, w.time_step
            w.step(1000)
            self.assertEqual([p.steps_done for p in seen], [300, 600, 900, 1000])
            self.assertTrue(all(p.steps_total == 1000 for p in seen))
            for p in seen:
                self.assertAlmostEqual(p.time, t0 + p.steps_done * dt, delta=1e-12)
                self.assertGreaterEqual(p.steps_per_second, 0)
            self.assertEqual(seen[-1].fraction, 1.0)
            self.assertEqual(seen[-1].eta, 0.0)
            self.assertIsInstance(seen[0], demill.Progress)
            w.on_progress(None)
            w.step(100)
            self.assertEqual(len(seen), 4)
            with self.assertRaises(demill.InvalidValue):
                w.on_progress(print, every=0)

    def test_stop_and_go_on_is_the_whole_run(self):
        """A true return stops the run (Interrupted) after that step; the
        remaining steps give bitwise the state of the whole run."""
        with scene() as a, scene() as b:
            a.step(1000)
            b.on_progress(lambda p: p.steps_done == 400, every=200)
            with self.assertRaises(demill.Interrupted) as cm:
                b.step(1000)
            self.assertTrue(cm.exception.message)
            self.assertEqual(b.step_count, a.step_count - 600)
            b.on_progress(None)
            b.step(600)
            self.assertEqual(state(b), state(a))

    def test_exception_in_the_callback_is_raised_from_step(self):
        with scene() as w:
            n0 = w.step_count

            def fail(p):
                if p.steps_done == 200:
                    raise ZeroDivisionError("from the callback")
            w.on_progress(fail, every=100)
            with self.assertRaises(ZeroDivisionError) as cm:
                w.step(1000)
            self.assertEqual(str(cm.exception), "from the callback")
            self.assertEqual(w.step_count, n0 + 200)
            w.step(100)  # the world goes on; the next error is its own
            self.assertEqual(w.step_count, n0 + 300)

    def test_callback_may_read_the_world(self):
        w, m = linear_world(3, gravity=(0, -9.81, 0))
        w.particles.add(m, (0, 0, 0), 0.01)
        heights = []
        w.on_progress(lambda p: heights.append(w.particles.positions[0, 1]), every=100)
        w.step(300)
        t = [0.001, 0.002, 0.003]
        for h, ti in zip(heights, t):
            self.assertAlmostEqual(h, -0.5 * 9.81 * ti * ti, delta=1e-12)
        w.close()


class Vtk(unittest.TestCase):
    def points(self, path):
        with open(path, "rb") as f:
            head = f.read(4096).decode("latin-1")
        self.assertIn("<VTKFile", head)
        return int(re.search(r'NumberOfPoints="(\d+)"', head)[1])

    def test_files_and_series(self):
        with scene() as w, tempfile.TemporaryDirectory() as d:
            w.write_vtk_particles(os.path.join(d, "p.vtu"))
            self.assertEqual(self.points(os.path.join(d, "p.vtu")), len(w.particles))
            w.write_vtk_walls(os.path.join(d, "w.vtp"))
            self.assertGreater(self.points(os.path.join(d, "w.vtp")), 0)
            prefix = os.path.join(d, "run")
            with w.vtk_series(prefix) as series:
                for _ in range(3):
                    w.step(10)
                    series.write()
            self.assertTrue(series.closed)
            with self.assertRaises(ValueError):
                series.write()
            pvd = [f for f in os.listdir(d) if f.endswith(".pvd")]
            self.assertEqual(len(pvd), 1)
            with open(os.path.join(d, pvd[0])) as f:
                self.assertEqual(f.read().count("<DataSet"), 6)  # particles and walls, 3 frames
            bad = os.path.join(d, "no", "such", "p.vtu")
            with self.assertRaises(demill.FileError) as cm:
                w.write_vtk_particles(bad)
            self.assertIn(bad, cm.exception.message)


if __name__ == "__main__":
    unittest.main()
