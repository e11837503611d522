"""signals.py against exact answers: the centred moving average of a linear signal on irregular
samples, its cut window at the record's ends, integrals of a triangle pulse, stretches below a
threshold."""
import sys
import unittest
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
from sluice_loads.signals import integral, moving_average, runs_below  # noqa: E402


def irregular(n, t0, t1, seed):
    """n sample times from t0 to t1 with spacings varying by a factor of 10."""
    rng = np.random.default_rng(seed)
    dt = rng.uniform(0.1, 1.0, n - 1)
    return t0 + np.concatenate([[0.0], np.cumsum(dt)]) * (t1 - t0) / dt.sum()


class MovingAverage(unittest.TestCase):
    def test_linear_signal_is_reproduced_where_the_window_ends_are_samples(self):
        # The integral of a piecewise-linear signal between samples is exact (trapezoid), so
        # with both window ends on samples the mean of a + b t over [t - w/2, t + w/2] is
        # a + b t exactly.
        w = 0.01
        base = irregular(60, 0.1, 0.4, seed=1)
        t = np.unique(np.concatenate([base, base - w / 2, base + w / 2, [0.0, 0.5]]))
        p = 2.0 + 3.0 * t
        ma = moving_average(t, p, w)
        idx = np.searchsorted(t, base)
        np.testing.assert_allclose(ma[idx], 2.0 + 3.0 * base, rtol=0, atol=1e-12)

    def test_linear_signal_elsewhere_within_the_interpolation_bound(self):
        # Between samples the cumulative integral (quadratic) is interpolated linearly: its
        # error is at most b D^2 / 8 at each end (D the longest spacing), so the mean is off
        # by at most b D^2 / (4 w).
        w, b = 0.01, 3.0
        t = irregular(4000, 0.0, 1.0, seed=2)
        ma = moving_average(t, 2.0 + b * t, w)
        inner = (t > w) & (t < 1.0 - w)
        bound = b * np.diff(t).max() ** 2 / (4 * w)
        self.assertLess(np.abs(ma[inner] - (2.0 + b * t[inner])).max(), bound + 1e-12)

    def test_window_is_cut_at_the_record_ends(self):
        # At the first sample the window is [t0, t0 + w/2]: the mean of a + b t there is
        # a + b (t0 + w/4).
        w = 0.02
        t = np.array([0.0, 0.003, 0.01, 0.017, 0.03, 0.04, 0.05])  # w/2 from each end: samples
        ma = moving_average(t, 1.0 + 4.0 * t, w)
        self.assertAlmostEqual(ma[0], 1.0 + 4.0 * (w / 4), places=14)
        self.assertAlmostEqual(ma[-1], 1.0 + 4.0 * (0.05 - w / 4), places=14)

    def test_dry_samples_count_as_zero(self):
        t = np.linspace(0.0, 1.0, 11)
        p = np.where(t < 0.5, np.nan, 1.0)
        ma = moving_average(t, p, 0.2)  # window of two spacings, ends on samples
        # over [0.4, 0.6]: a ramp from 0 (dry) to 1 over 0.1 s, then 1 for 0.1 s: 0.15 / 0.2
        self.assertAlmostEqual(ma[5], 0.75, places=14)
        self.assertTrue(np.all(np.isfinite(ma)))

    def test_no_width_leaves_the_signal(self):
        t = np.array([0.0, 1.0, 2.0])
        np.testing.assert_array_equal(moving_average(t, np.array([1.0, np.nan, 3.0]), 0.0),
                                      [1.0, 0.0, 3.0])


class Integrals(unittest.TestCase):
    def test_impulse_of_a_triangle_pulse(self):
        # A triangle from 0.2 s to 0.3 s, peak 500 at 0.23 s, sampled irregularly with its
        # vertices among the samples: impulse = 500 * 0.1 / 2 = 25.
        t = np.unique(np.concatenate([irregular(300, 0.0, 0.6, seed=3), [0.2, 0.23, 0.3]]))
        p = np.interp(t, [0.0, 0.2, 0.23, 0.3, 0.6], [0.0, 0.0, 500.0, 0.0, 0.0])
        self.assertAlmostEqual(integral(t, p, 0.0, 0.6), 25.0, places=10)
        self.assertAlmostEqual(integral(t, p, 0.2, 0.23), 500 * 0.03 / 2, places=10)
        self.assertAlmostEqual(integral(t, p, -1.0, 9.0), 25.0, places=10)  # clipped
        self.assertEqual(integral(t, p, 0.5, 0.4), 0.0)

    def test_stretches_below_a_threshold_end_at_the_crossings(self):
        t = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
        p = np.array([1.0, -1.0, 1.0, 1.0, -3.0, -3.0])
        # below 0: from 0.5 to 1.5, and from 3.25 to the end (5)
        np.testing.assert_allclose(runs_below(t, p, 0.0, 0.0), [1.0, 1.75])
        self.assertEqual(runs_below(t, p, -5.0, 0.0), [])


if __name__ == "__main__":
    unittest.main()
