"""Operations on irregularly sampled probe records (time [s], value; NaN = a dry probe): the
centred moving average, integrals over a time range and the stretches below a threshold. The
signal is taken as piecewise linear between samples. A probe sampled every step has the
solver's variable time step between samples, so nothing here assumes a regular spacing."""
from __future__ import annotations

import numpy as np


def dry_as_zero(p: np.ndarray) -> np.ndarray:
    return np.where(np.isfinite(p), p, 0.0)


def cumulative_trapezoid(t: np.ndarray, p: np.ndarray) -> np.ndarray:
    c = np.empty_like(t, dtype=float)
    c[0] = 0.0
    np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(t), out=c[1:])
    return c


def moving_average(t: np.ndarray, p: np.ndarray, width: float) -> np.ndarray:
    """Centred moving average over `width` of time on irregular samples: the integral of the
    piecewise-linear signal over [t - w/2, t + w/2] (cumulative trapezoid, interpolated at the
    window ends) divided by the window's length; near the ends of the record the window is cut
    to the record and divided by its cut length. NaN counts as 0."""
    p = dry_as_zero(p)
    if width <= 0 or len(t) < 2:
        return p.copy()
    c = cumulative_trapezoid(t, p)
    lo = np.maximum(t - 0.5 * width, t[0])
    hi = np.minimum(t + 0.5 * width, t[-1])
    span = hi - lo
    out = p.copy()
    ok = span > 0
    out[ok] = (np.interp(hi[ok], t, c) - np.interp(lo[ok], t, c)) / span[ok]
    return out


def integral(t: np.ndarray, p: np.ndarray, a: float, b: float) -> float:
    """Trapezoidal integral of the piecewise-linear signal over [a, b] (clipped to the record)."""
    a, b = max(a, t[0]), min(b, t[-1])
    if b <= a:
        return 0.0
    c = cumulative_trapezoid(t, p)
    return float(np.interp(b, t, c) - np.interp(a, t, c))


def runs_below(t: np.ndarray, p: np.ndarray, threshold: float, t_from: float) -> list[float]:
    """Durations of the continuous stretches with p < threshold after t_from; each stretch's
    ends are the linearly interpolated crossings (or the record's ends)."""
    m = t >= t_from
    tt, pp = t[m], p[m]
    below = pp < threshold
    if not below.any():
        return []
    edges = np.diff(below.astype(np.int8))
    starts = list(np.nonzero(edges == 1)[0] + 1)
    ends = list(np.nonzero(edges == -1)[0])
    if below[0]:
        starts.insert(0, 0)
    if below[-1]:
        ends.append(len(pp) - 1)

    def crossing(i: int, j: int) -> float:  # between samples i and j, one above, one below
        f = (threshold - pp[i]) / (pp[j] - pp[i])
        return float(tt[i] + f * (tt[j] - tt[i]))

    out = []
    for s, e in zip(starts, ends):
        t0 = crossing(s - 1, s) if s > 0 else float(tt[s])
        t1 = crossing(e, e + 1) if e + 1 < len(pp) else float(tt[e])
        out.append(t1 - t0)
    return out
