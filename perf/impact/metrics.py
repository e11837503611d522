"""The first-impact figures of one wall-pressure signal, as issue 18 defines them (README.md,
"Definitions"): contact, raw and filtered peak, the longer average's peak, the impulse over
the first-impact window and the time below -0.5 rho g H; and the RMS against a record."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from signals import dry_as_zero, integral, moving_average, runs_below

CONTACT_FRACTION = 0.05      # contact: p > 0.05 rho g H
NEGATIVE_FRACTION = -0.5     # "below -0.5 rho g H"
DEFAULT_WINDOW_STAR = 0.5    # first-impact window length in t* units
DEFAULT_FILTER_S = 1.0e-3    # moving-average width in seconds
DEFAULT_SMOOTH_S = 10.0e-3   # the second, longer average: WCSPH's peaks after it do not depend
                             # on c0 (perf/impact/STUDY.md, "The sound-speed ladder")


@dataclass
class Scales:
    H: float = 0.6
    g: float = 9.81
    rho0: float = 1000.0

    @property
    def p(self) -> float:  # rho0 g H [Pa]
        return self.rho0 * self.g * self.H

    @property
    def t(self) -> float:  # sqrt(H/g) [s]; t* = t / self.t
        return math.sqrt(self.H / self.g)


def first_impact_window(t: np.ndarray, signal: np.ndarray, threshold: float, window_s: float,
                        t_min: float = -math.inf) -> tuple[float, float] | None:
    """The first impact's window [tc, tc + window_s]: tc is the first sample at or after t_min
    where the signal exceeds the contact threshold; None when it never does."""
    hit = np.nonzero((signal > threshold) & (t >= t_min))[0]
    if len(hit) == 0:
        return None
    tc = float(t[hit[0]])
    return tc, tc + window_s


def impact_metrics(t: np.ndarray, p: np.ndarray, sc: Scales,
                   window_star: float = DEFAULT_WINDOW_STAR,
                   filter_s: float = DEFAULT_FILTER_S, t_min: float = -math.inf,
                   smooth_s: float = DEFAULT_SMOOTH_S) -> dict:
    """The first-impact figures of one pressure signal (t [s], p [Pa], NaN = dry)."""
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
    w = (t >= tc) & (t <= te)
    ir = np.argmax(np.where(w, q, -np.inf))
    jf = np.argmax(np.where(w, pf, -np.inf))
    imp = integral(t, q, tc, te)
    after = t >= tc
    neg = runs_below(t, q, NEGATIVE_FRACTION * sc.p, tc)
    res.update({
        "t_contact_s": tc, "t_contact_star": tc / sc.t,
        "peak_raw_star": float(q[ir] / sc.p), "t_peak_raw_star": float(t[ir] / sc.t),
        "peak_filt_star": float(pf[jf] / sc.p), "t_peak_filt_star": float(t[jf] / sc.t),
        "peak_raw_Pa": float(q[ir]), "peak_filt_Pa": float(pf[jf]),
        "peak_smooth_star": float(ps[w].max() / sc.p), "peak_smooth_Pa": float(ps[w].max()),
        "impulse_Pa_s": imp, "impulse_star": imp / (sc.p * sc.t),
        "window_complete": bool(t[-1] >= te),
        "min_raw_star": float(q[after].min() / sc.p),
        "min_filt_star": float(pf[after].min() / sc.p),
        "neg_longest_ms": 1e3 * max(neg) if neg else 0.0,
        "neg_total_ms": 1e3 * sum(neg), "neg_count": len(neg),
    })
    return res


def rms_against(t_sim_star: np.ndarray, p_sim_star: np.ndarray, t_exp: np.ndarray,
                p_exp: np.ndarray, lo: float, hi: float) -> float:
    """RMS of (sim - exp) at the experiment's times in [lo, hi] (sim interpolated linearly)."""
    m = (t_exp >= lo) & (t_exp <= hi) & (t_exp <= t_sim_star[-1]) & (t_exp >= t_sim_star[0])
    if not m.any():
        return float("nan")
    d = np.interp(t_exp[m], t_sim_star, p_sim_star) - p_exp[m]
    return float(math.sqrt(np.mean(d * d)))
