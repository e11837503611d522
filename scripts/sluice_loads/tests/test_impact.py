"""impact.py on a triangle pulse whose figures are known exactly: contact, raw peak, the peak
after a centred moving average shorter than the pulse, impulse over the window."""
import math
import sys
import unittest
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from sluice_loads.impact import (Scales, first_impact_window, impact_metrics,  # noqa: E402
                                 window_peaks)
from sluice_loads.signals import moving_average  # noqa: E402

A, C, B, P = 0.2, 0.25, 0.3, 6000.0  # triangle from A to B, peak P [Pa] at C
W = 0.004                            # moving-average width [s]


def pulse(extra=()):
    """Irregular samples of the triangle, with its vertices and C +- W/2 among them."""
    rng = np.random.default_rng(7)
    t = np.unique(np.concatenate([np.cumsum(rng.uniform(2e-4, 2e-3, 600)),
                                  [0.0, A, C, B, C - W / 2, C + W / 2], extra]))
    t = t[t <= 0.6]
    return t, np.interp(t, [0.0, A, C, B, 0.6], [0.0, 0.0, P, 0.0, 0.0])


class FirstImpact(unittest.TestCase):
    def test_window_peaks_of_a_triangle(self):
        t, p = pulse()
        sc = Scales(H=0.6, g=9.81, rho0=1000.0)  # window 0.124 s: the whole pulse
        window = first_impact_window(t, p, 0.05 * sc.p, 0.5 * sc.t)
        tc, te = window
        first = t[np.nonzero(p > 0.05 * sc.p)[0][0]]
        self.assertEqual(tc, first)
        self.assertAlmostEqual(te, tc + 0.5 * math.sqrt(0.6 / 9.81), places=14)
        pf = moving_average(t, p, W)
        f = window_peaks(t, p, pf, pf, tc, te)
        self.assertEqual((f["peak_raw"], f["t_peak_raw"]), (P, C))
        # the mean of a triangle of half-width h over W centred on its apex: P (1 - W / (4 h))
        self.assertAlmostEqual(f["peak_filt"], P * (1 - W / (4 * (C - A))), places=8)
        self.assertEqual(f["t_peak_filt"], C)
        # impulse from contact: the whole triangle less the part before the first sample
        before = 0.5 * (tc - A) * np.interp(tc, t, p)
        self.assertAlmostEqual(f["impulse"], P * (B - A) / 2 - before, places=9)
        self.assertTrue(f["window_complete"])

    def test_search_range_and_a_cut_window(self):
        t, p = pulse(extra=[0.27])
        self.assertIsNone(first_impact_window(t, p, 1.0, 0.1, t_min=0.31))
        self.assertIsNone(first_impact_window(t, p, 1.0, 0.1, t_max=0.19))
        tc, te = first_impact_window(t, p, 1.0, 0.1, t_max=0.27)
        self.assertEqual(te, 0.27)  # the window ends at t_max
        f = window_peaks(t[t <= 0.26], p[t <= 0.26], p[t <= 0.26], p[t <= 0.26], tc, te)
        self.assertFalse(f["window_complete"])  # the record ends inside the window

    def test_impact_metrics_in_rho_g_h(self):
        t, p = pulse()
        sc = Scales(H=0.3, g=9.81, rho0=1000.0)
        m = impact_metrics(t, p, sc, filter_s=W, smooth_s=W)
        self.assertAlmostEqual(m["peak_raw_star"], P / (1000 * 9.81 * 0.3), places=12)
        self.assertAlmostEqual(m["peak_filt_star"] * sc.p, P * (1 - W / (4 * (C - A))),
                               places=8)
        self.assertEqual(m["neg_count"], 0)
        dry = impact_metrics(t, np.full_like(t, np.nan), sc)
        self.assertTrue(math.isnan(dry["peak_raw_star"]))

    def test_scales(self):
        sc = Scales(H=0.5, g=10.0, rho0=1000.0)
        self.assertEqual(sc.p, 5000.0)
        self.assertAlmostEqual(sc.t, math.sqrt(0.05), places=15)
        self.assertEqual(sc.force(2), 1250.0)   # rho g H^2 / 2 per metre
        self.assertEqual(sc.force(3), 625.0)    # on a wall H wide


if __name__ == "__main__":
    unittest.main()
