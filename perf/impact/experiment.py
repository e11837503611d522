"""Buchner's (2002) records of the Zhou/Buchner dam break, digitised (data/, README.md "Sensor
height"), by sensor height, and their first-impact figures with the definitions of
scripts/sluice_loads/impact.py."""
from __future__ import annotations

import loads_package  # noqa: F401  (scripts/ on the path)
from metrics import rms_against
from records import load_experiment
from sluice_loads.impact import DEFAULT_FILTER_S, DEFAULT_WINDOW_STAR, Scales, impact_metrics

EXP_T_MIN_STAR = 2.0         # contact search in the digitised records starts here (the PySPH
                             # copy has +-0.16 p* digitisation noise before t* = 1.9)
RMS_RANGE_STAR = (2.0, 7.0)  # sim - experiment RMS range
HEIGHT_TOL = 1.0e-3          # a probe within 1 mm of a sensor height is compared with it

# Experimental records by sensor height [m]: (label, file); the first is the reference.
EXPERIMENT = {
    0.160: [("Buchner 2002 (Trixi digitisation)", "buchner2002_P1.csv"),
            ("Buchner 2002 (PySPH digitisation)", "buchner2002_P1_pysph.csv")],
    0.584: [("Buchner 2002 (Trixi digitisation)", "buchner2002_P2.csv")],
    # P1's record once more at 0.12 m = 0.2 H, where PySPH and erdc/proteus sample their
    # simulations to compare with it (README: sensor height)
    0.120: [("Buchner 2002 P1 (Trixi digitisation)", "buchner2002_P1.csv")],
}
SENSOR_NAMES = {0.160: "P1", 0.584: "P2", 0.120: "P1 at 0.12 m"}


def experiment_metrics(height: float, sc: Scales, window_star: float = DEFAULT_WINDOW_STAR,
                       filter_s: float = DEFAULT_FILTER_S) -> list[dict]:
    """The same figures from the digitised records at this sensor height (in seconds and Pa
    through the study's H, g, rho0), the first record being the reference; [] when none."""
    out = []
    for key, records in EXPERIMENT.items():
        if abs(key - height) > HEIGHT_TOL:
            continue
        for label, name in records:
            ts, ps = load_experiment(name)
            m = impact_metrics(ts * sc.t, ps * sc.p, sc, window_star, filter_s,
                               t_min=EXP_T_MIN_STAR * sc.t)
            m.update({"label": label, "file": name, "t_star": ts, "p_star": ps,
                      "sensor": SENSOR_NAMES[key]})
            out.append(m)
    return out


def digitisation_spread(sc: Scales) -> dict:
    """How far the two independent digitisations of P1 differ: the only handle on the
    experimental uncertainty we have (no repeat tests are published)."""
    a, b = experiment_metrics(0.160, sc)
    lo, hi = RMS_RANGE_STAR
    return {
        "peak_a": a["peak_raw_star"], "peak_b": b["peak_raw_star"],
        "t_peak_a": a["t_peak_raw_star"], "t_peak_b": b["t_peak_raw_star"],
        "t_contact_a": a["t_contact_star"], "t_contact_b": b["t_contact_star"],
        "impulse_a": a["impulse_star"], "impulse_b": b["impulse_star"],
        "rms_ab": rms_against(b["t_star"], b["p_star"], a["t_star"], a["p_star"], lo, hi),
    }
