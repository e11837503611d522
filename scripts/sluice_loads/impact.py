"""The first impact of one load signal (docs/IMPACT_LOADS.md, "Running an impact study"): the
contact time, the first-impact window after it, and in that window the raw peak, the peaks
after two centred moving averages (1 ms and 10 ms by default) with their times, and the
impulse. `Scales` gives the units rho g H (pressure), rho g H^2/2 (force) and sqrt(H/g)
(time) that make these figures comparable between cases."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .signals import dry_as_zero, integral, moving_average, runs_below

CONTACT_FRACTION = 0.05      # contact: the first sample above 0.05 of the scale (rho g H)
NEGATIVE_FRACTION = -0.5     # suction: stretches below -0.5 rho g H
DEFAULT_WINDOW_STAR = 0.5    # first-impact window length in units of sqrt(H/g)
DEFAULT_FILTER_S = 1.0e-3    # the short moving average [s], as transducers and their filters
DEFAULT_SMOOTH_S = 10.0e-3   # the long moving average [s]: WCSPH's peaks after it do not
                             # depend on c0 from 20 sqrt(gH) up (docs/RECOMMENDED_PRACTICE.md)


@dataclass
class Scales:
    H: float       # the fluid column's height [m]
    g: float       # |gravity| [m/s^2]
    rho0: float    # reference density [kg/m^3]

    @property
    def p(self) -> float:  # rho0 g H [Pa]
        return self.rho0 * self.g * self.H

    @property
    def t(self) -> float:  # sqrt(H/g) [s]; t* = t / self.t
        return math.sqrt(self.H / self.g)

    def force(self, dimension: int) -> float:
        """rho0 g H^2 / 2: the hydrostatic force of the column on a wall, per metre of width in
        2-D [N/m]; in 3-D on a wall H wide [N]."""
        return 0.5 * self.p * self.H * (1.0 if dimension == 2 else self.H)


def first_impact_window(t: np.ndarray, signal: np.ndarray, threshold: float, window_s: float,
                        t_min: float = -math.inf,
                        t_max: float = math.inf) -> tuple[float, float] | None:
    """The first impact's window [tc, min(tc + window_s, t_max)]: tc is the first sample in
    [t_min, t_max] where the signal exceeds the contact threshold; None when it never does."""
    hit = np.nonzero((signal > threshold) & (t >= t_min) & (t <= t_max))[0]
    if len(hit) == 0:
        return None
    tc = float(t[hit[0]])
    return tc, min(tc + window_s, t_max)


def window_peaks(t: np.ndarray, q: np.ndarray, pf: np.ndarray, ps: np.ndarray, tc: float,
                 te: float) -> dict:
    """In [tc, te]: the largest raw (q), short-average (pf) and long-average (ps) values and
    their times, and the impulse of q (trapezoid, window ends interpolated); in q's units.
    window_complete is False when the record ends inside the window (impulse of a cut window)."""
    w = (t >= tc) & (t <= te)
    ir = int(np.argmax(np.where(w, q, -np.inf)))
    jf = int(np.argmax(np.where(w, pf, -np.inf)))
    js = int(np.argmax(np.where(w, ps, -np.inf)))
    return {"t_contact": tc, "t_window_end": te,
            "peak_raw": float(q[ir]), "t_peak_raw": float(t[ir]),
            "peak_filt": float(pf[jf]), "t_peak_filt": float(t[jf]),
            "peak_smooth": float(ps[js]), "t_peak_smooth": float(t[js]),
            "impulse": integral(t, q, tc, te), "window_complete": bool(t[-1] >= te)}


def impact_metrics(t: np.ndarray, p: np.ndarray, sc: Scales,
                   window_star: float = DEFAULT_WINDOW_STAR,
                   filter_s: float = DEFAULT_FILTER_S, t_min: float = -math.inf,
                   smooth_s: float = DEFAULT_SMOOTH_S) -> dict:
    """The first-impact figures of one pressure signal (t [s], p [Pa], NaN = dry) in rho g H
    and sqrt(H/g) units (*_star) and in Pa: contact, peaks, impulse over window_star after
    contact, the lowest value after contact and the stretches below -0.5 rho g H."""
    nan = float("nan")
    q = dry_as_zero(p)
    pf = moving_average(t, q, filter_s)
    ps = moving_average(t, q, smooth_s)
    res = {"t_end_s": float(t[-1]), "t_end_star": float(t[-1] / sc.t), "samples": int(len(t)),
           "wet_fraction": float(np.mean(np.isfinite(p))) if len(p) else nan}
    keys = ["t_contact_s", "t_contact_star", "peak_raw_star", "t_peak_raw_star",
            "peak_filt_star", "t_peak_filt_star", "peak_raw_Pa", "peak_filt_Pa",
            "peak_smooth_star", "peak_smooth_Pa", "impulse_Pa_s", "impulse_star",
            "window_complete", "min_raw_star", "min_filt_star", "neg_longest_ms", "neg_total_ms",
            "neg_count"]
    res.update({k: nan for k in keys})
    window = first_impact_window(t, q, CONTACT_FRACTION * sc.p, window_star * sc.t, t_min)
    if window is None:
        return res
    tc, te = window
    f = window_peaks(t, q, pf, ps, tc, te)
    imp = f["impulse"]
    after = t >= tc
    neg = runs_below(t, q, NEGATIVE_FRACTION * sc.p, tc)
    res.update({
        "t_contact_s": tc, "t_contact_star": tc / sc.t,
        "peak_raw_star": f["peak_raw"] / sc.p, "t_peak_raw_star": f["t_peak_raw"] / sc.t,
        "peak_filt_star": f["peak_filt"] / sc.p, "t_peak_filt_star": f["t_peak_filt"] / sc.t,
        "peak_raw_Pa": f["peak_raw"], "peak_filt_Pa": f["peak_filt"],
        "peak_smooth_star": f["peak_smooth"] / sc.p, "peak_smooth_Pa": f["peak_smooth"],
        "impulse_Pa_s": imp, "impulse_star": imp / (sc.p * sc.t),
        "window_complete": f["window_complete"],
        "min_raw_star": float(q[after].min() / sc.p),
        "min_filt_star": float(pf[after].min() / sc.p),
        "neg_longest_ms": 1e3 * max(neg) if neg else 0.0,
        "neg_total_ms": 1e3 * sum(neg), "neg_count": len(neg),
    })
    return res
