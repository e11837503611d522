"""The impact study's part of the first-impact figures: the Zhou/Buchner column's scales and
the RMS difference from a digitised record. The figures themselves (contact, window, raw and
filtered peaks, impulse, stretches below -0.5 rho g H; README.md, "Definitions") are the
product's: scripts/sluice_loads/impact.py, which `scripts/loads` uses too."""
from __future__ import annotations

import math

import numpy as np

import loads_package  # noqa: F401  (scripts/ on the path)
from sluice_loads.impact import Scales


def zhou_scales() -> Scales:
    """The scales of zhou_2d.toml: H = 0.6 m, g = 9.81 m/s^2, rho0 = 1000 kg/m^3."""
    return Scales(H=0.6, g=9.81, rho0=1000.0)


def rms_against(t_sim_star: np.ndarray, p_sim_star: np.ndarray, t_exp: np.ndarray,
                p_exp: np.ndarray, lo: float, hi: float) -> float:
    """RMS of (sim - exp) at the experiment's times in [lo, hi] (sim interpolated linearly)."""
    m = (t_exp >= lo) & (t_exp <= hi) & (t_exp <= t_sim_star[-1]) & (t_exp >= t_sim_star[0])
    if not m.any():
        return float("nan")
    d = np.interp(t_exp[m], t_sim_star, p_sim_star) - p_exp[m]
    return float(math.sqrt(np.mean(d * d)))
