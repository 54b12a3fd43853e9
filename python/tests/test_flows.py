"""Fills, feeds and outlets through the binding: Bond's 285-ball charge
fits its 305 mm mill; a feed of 1 kg/s has inserted 1 kg/s × t within one
ball; an outlet below the stream removes every ball that crosses it, so
that counted + present = inserted; bad input raises with the library's
message; feeds and outlets are listed and survive a checkpoint in bytes."""

import math
import unittest

import numpy as np

import demill
from demill import Fill, Kind, Region, Sizes


def steel_world():
    w = demill.World(3)
    m = w.material(density=7800)
    w.pair(m, m, normal=demill.Normal.LINEAR)
    return w, m


class Flows(unittest.TestCase):
    def test_bond_charge_fits(self):
        # Bond (1961), Crushing and grinding calculations: 43 balls of 36.8 mm,
        # 67 of 29.7, 10 of 25.4, 71 of 19.1, 94 of 15.5
        w, m = steel_world()
        w.add_drum(m, diameter=0.305, length=0.305)
        d = np.array([0.0368, 0.0297, 0.0254, 0.0191, 0.0155])
        n = np.array([43, 67, 10, 71, 94])
        ids = w.drum.fill(m, Sizes.CLASSES, np.column_stack((d, n * d**3)).ravel(), Fill.COUNT,
                          285)
        self.assertEqual(ids.size, 285)
        diam = np.round(2 * w.particles.radii, 6)
        for dk, nk in zip(d, n):
            self.assertEqual(int(np.sum(diam == round(dk, 6))), nk)

    def test_feed_and_outlet(self):
        w, m = steel_world()
        box = (-0.05, 0, -0.05, 0.05, 0.05, 0.05)
        feed = w.add_feed(Region.BOX, box, m, Sizes.CLASSES, (0.006, 1.0), 1.0)
        outlet = w.add_outlet(Region.HALF_SPACE, (0, -0.2, 0, 0, 1, 0), edges=(0.005,),
                              interval=0.05)
        self.assertEqual(w.feeds, [feed])
        self.assertEqual(w.outlets, [outlet])
        w.step(30000)
        one = 7800 * math.pi / 6 * 0.006**3
        f = feed.totals
        self.assertTrue(0 <= 1.0 * w.time - f.mass < one)
        o = outlet.totals
        self.assertEqual(o.counts[0], 0)
        self.assertGreater(o.counts[1], 0)
        self.assertEqual(int(o.counts.sum()) + len(w.particles), f.count)
        self.assertAlmostEqual(o.masses.sum() + w.particles.masses.sum(), f.mass, places=12)
        # a checkpoint in bytes carries both, and the run goes on the same
        v = demill.World.from_bytes(w.to_bytes())
        w.step(1000)
        v.step(1000)
        self.assertEqual(v.feeds[0].totals, feed.totals)
        np.testing.assert_array_equal(v.particles.positions, w.particles.positions)
        feed.remove()
        self.assertEqual(w.ids(Kind.FEED).size, 0)

    def test_bad_input(self):
        w, m = steel_world()
        with self.assertRaises(demill.InvalidValue) as e:
            w.add_feed(Region.BOX, (0, 0, 0, 1, 1, 1), m, Sizes.CLASSES, (0.01, 1), 0.0)
        self.assertIn("mass rate", str(e.exception))
        with self.assertRaises(demill.NotFinite):
            w.fill_region(Region.BOX, (0, 0, 0, math.nan, 1, 1), m, Sizes.CLASSES, (0.01, 1),
                          Fill.COUNT, 10)
        self.assertEqual(len(w.particles), 0)


if __name__ == "__main__":
    unittest.main()
