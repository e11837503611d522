"""gci.py on synthetic ladders f = f0 + C h^p, whose order and limit are known, and on ladders
that oscillate, diverge or do not move; ensemble.py's statistics."""
import math
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from sluice_loads import ensemble, gci  # noqa: E402


def ladder(f0, c, p, hs):
    return [f0 + c * h**p for h in hs]  # fine first: hs ascending


class ThreeGrid(unittest.TestCase):
    def test_constant_ratio_gives_back_order_and_limit(self):
        for p in (0.7, 1.0, 1.6, 2.0):
            f1, f2, f3 = ladder(2.5, 40.0, p, [0.01, 0.02, 0.04])
            r = gci.three_grid(f1, f2, f3, 2.0, 2.0)
            self.assertEqual(r["kind"], "monotone")
            self.assertAlmostEqual(r["order"], p, places=10)
            self.assertAlmostEqual(r["f_ext"], 2.5, places=10)
            # Roache's index: 1.25 |e21 / f1| / (r^p - 1)
            self.assertAlmostEqual(r["gci_fine"],
                                   1.25 * abs((f2 - f1) / f1) / (2.0**p - 1.0), places=12)

    def test_unequal_ratios_iterate_to_the_order(self):
        hs = [0.0125, 0.02, 0.03]  # r21 = 1.6, r32 = 1.5
        f1, f2, f3 = ladder(-1.0, 30.0, 1.4, hs)
        r = gci.three_grid(f1, f2, f3, hs[1] / hs[0], hs[2] / hs[1])
        self.assertAlmostEqual(r["order"], 1.4, places=9)
        self.assertAlmostEqual(r["f_ext"], -1.0, places=9)
        self.assertAlmostEqual(gci.observed_order(f2 - f1, f3 - f2, 1.6, 1.5), 1.4, places=9)

    def test_order_above_the_formal_order_is_capped_in_the_index_only(self):
        f1, f2, f3 = ladder(1.0, 1e4, 3.0, [0.01, 0.02, 0.04])
        r = gci.three_grid(f1, f2, f3, 2.0, 2.0, formal_order=2.0)
        self.assertAlmostEqual(r["order"], 3.0, places=9)
        self.assertAlmostEqual(r["f_ext"], 1.0, places=10)
        self.assertAlmostEqual(r["gci_fine"], 1.25 * abs((f2 - f1) / f1) / 3.0, places=12)
        self.assertIn("GCI with p = 2", gci.verdict(r))

    def test_failures_are_named(self):
        osc = gci.three_grid(1.0, 1.2, 0.9)
        self.assertEqual(osc["kind"], "oscillatory")
        self.assertTrue(math.isnan(osc["gci_fine"]))
        self.assertIn("oscillates", gci.verdict(osc))
        grow = gci.three_grid(1.0, 1.4, 1.5)  # changes 0.4 then 0.1: growing with refinement
        self.assertEqual(grow["kind"], "diverging")
        self.assertAlmostEqual(grow["order"], -2.0, places=12)
        self.assertIn("not in the asymptotic range", gci.verdict(grow))
        flat = gci.three_grid(1.0, 1.005, 0.996)
        self.assertEqual(flat["kind"], "flat")
        self.assertIn("converged", gci.verdict(flat))
        slow = gci.three_grid(*ladder(1.0, 1.0, 0.2, [0.01, 0.02, 0.04]))
        self.assertIn("far from the formal order", gci.verdict(slow))


class Ensemble(unittest.TestCase):
    def test_median_range_spread(self):
        s = ensemble.summary([4.0, 1.0, float("nan"), 2.0])
        self.assertEqual((s["n"], s["median"], s["min"], s["max"]), (3, 2.0, 1.0, 4.0))
        self.assertAlmostEqual(s["spread_pct"], 150.0)
        self.assertEqual(ensemble.summary([float("nan")])["n"], 0)
        self.assertEqual(ensemble.half_range([1.0, 3.0, 2.0]), 1.0)
        self.assertTrue(math.isnan(ensemble.half_range([1.0])))


if __name__ == "__main__":
    unittest.main()
