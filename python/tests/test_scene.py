"""demill.run_scene(): a scene file run by the demill program, with
overrides, a sweep and a restart, and a refused scene. The scene is
scenes/hopper.yaml, cut to a few milliseconds. Numbers checked against the
scene's own definition (the steps a stop time makes at the file's time
step) and against the unbroken run (a restart goes on bitwise)."""

import os
import tempfile
import unittest
from pathlib import Path

import helpers  # noqa: F401 - makes demill importable
import demill

HOPPER = str(helpers.REPO / "scenes" / "hopper.yaml")
SHORT = {"outputs.vtk_every": 0}


@unittest.skipUnless(os.environ.get("DEMILL_PROGRAM"), "DEMILL_PROGRAM not set (CTest sets it)")
class RunScene(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.out = Path(self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def test_run_sweep_restart(self):
        # 2 ms at the hopper's 4e-5 s: 50 steps
        s = demill.run_scene(HOPPER, out=self.out / "one", set={**SHORT, "stop.time": 0.002},
                             quiet=True)
        self.assertEqual(s["steps"], 50)
        self.assertEqual(s["time_step_s"], 4e-5)
        self.assertEqual(s["particles"], 2500)
        # a sweep: one summary per value, in order, each at its own time
        runs = demill.run_scene(HOPPER, out=self.out / "sweep",
                                set={**SHORT, "stop.time": [0.001, 0.002]}, quiet=True)
        self.assertEqual([r["sweep_value"] for r in runs], [0.001, 0.002])
        self.assertEqual([r["steps"] for r in runs], [25, 50])
        self.assertTrue((self.out / "sweep" / "sweep.csv").is_file())
        # the restart from 2 ms to 4 ms ends where the unbroken run to 4 ms does
        whole = demill.run_scene(HOPPER, out=self.out / "whole",
                                 set={**SHORT, "stop.time": 0.004}, quiet=True)
        then = demill.run_scene(restart=self.out / "one" / "checkpoint",
                                set={"stop.time": 0.004}, quiet=True)
        self.assertEqual(then["simulated_s"], 0.004)
        self.assertEqual((self.out / "one" / "restart" / "checkpoint").read_bytes(),
                         (self.out / "whole" / "checkpoint").read_bytes())
        self.assertEqual(then["particles"], whole["particles"])

    def test_refused(self):
        with self.assertRaises(demill.SceneError) as e:
            demill.run_scene(HOPPER, out=self.out / "bad", set={"world.time_stepp": 1},
                             quiet=True)
        self.assertIn("time_stepp", e.exception.message)
        self.assertFalse((self.out / "bad" / "summary.txt").exists())
        with self.assertRaises(ValueError):
            demill.run_scene()

    def test_program_from_environment(self):
        self.assertEqual(demill.scene_program(), os.environ["DEMILL_PROGRAM"])


if __name__ == "__main__":
    unittest.main()
