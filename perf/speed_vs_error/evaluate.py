"""Error of a finished sluice run, computed from its output files alone (probes/*.csv,
snapshots/*.h5), with the same definitions as the validation tests in tests/validation/:

* dam break     test_dam_break_2d.cpp:   RMS relative deviation of the surge front Z = x/a
                from Martin & Moyce (1952), n^2 = 2, over their points with T = t sqrt(2g/a) <= 3
                (tests/data/martin_moyce_1952_n2_2.csv), the simulated front interpolated
                linearly in T and starting at (T, Z) = (0, 1).
* hydrostatic   test_hydrostatic_2d.cpp: worst relative deviation of the bottom-centre pressure
                probe from rho0 g (H - y_probe) over the samples with t >= 1 s.
* taylor-green  relative error of the decay rate of the kinetic energy, against the exact
                16 pi^2 nu / L^2 of KE(t)/KE(0) = exp(-16 pi^2 nu t / L^2): the rate is the
                least-squares slope of -ln(KE/KE0) against t through the origin, over every
                snapshot. Not the error at one instant (test_taylor_green_2d.cpp): at the
                sweep's resolutions KE carries an acoustic oscillation of up to 16 % of KE0
                between snapshots 0.02 s apart, so an error at one time ranks runs by the
                oscillation's phase, not by the decay.
* impact        perf/impact/analyse.py:  relative deviation of the 1 ms filtered first-impact
                peak at sensor P1 of the Zhou/Buchner dam break (its 2 cm wall panel) from the
                digitised experiment.
* poiseuille    test_poiseuille_2d.cpp:  L2 relative error of the fluid x-velocity against the
                Morris et al. (1997, eq. 21) start-up series at the final time.
"""
from __future__ import annotations

import csv
import math
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _probe(out_dir: Path, name: str) -> tuple[list[float], list[float]]:
    ts, vs = [], []
    with open(out_dir / "probes" / f"{name}.csv") as f:
        rows = csv.reader(f)
        next(rows)
        for r in rows:
            ts.append(float(r[0]))
            vs.append(float(r[1]))
    return ts, vs


def _interp(xs: list[float], ys: list[float], x: float) -> float:
    if x <= xs[0]:
        return ys[0]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            w = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + w * (ys[k] - ys[k - 1])
    return ys[-1]


def _snapshots(out_dir: Path) -> list[Path]:
    return sorted((out_dir / "snapshots").glob("snap_*.h5"))


def dam_break_front(out_dir: Path, case: dict) -> float:
    block = case["blocks"][0]
    a = block["hi"][0] - block["lo"][0]
    g = abs(case["fluid"].get("gravity", [0, -9.81])[-1])
    t_scale = math.sqrt(2 * g / a)
    ts, xs = _probe(out_dir, "front")
    Ts = [0.0] + [t * t_scale for t in ts if t > 0]
    Zs = [1.0] + [x / a for t, x in zip(ts, xs) if t > 0]
    sum2, n = 0.0, 0
    with open(ROOT / "tests" / "data" / "martin_moyce_1952_n2_2.csv") as f:
        rows = csv.reader(line for line in f if not line.startswith("#"))
        next(rows)
        for r in rows:
            T, Z = float(r[1]), float(r[2])
            if T > 3.0:
                continue
            rel = (_interp(Ts, Zs, T) - Z) / Z
            sum2 += rel * rel
            n += 1
    return math.sqrt(sum2 / n)


def hydrostatic_pressure(out_dir: Path, case: dict) -> float:
    probe = case["probes"][0]
    y = probe["position"][1]
    g = abs(case["fluid"].get("gravity", [0, -9.81])[-1])
    H = case["blocks"][0]["hi"][1]
    p_ref = case["fluid"]["rho0"] * g * (H - y)
    ts, ps = _probe(out_dir, probe["name"])
    devs = [abs(p - p_ref) / p_ref for t, p in zip(ts, ps) if t >= 1.0 - 1e-9]
    if not devs or any(math.isnan(d) for d in devs):
        return float("nan")
    return max(devs)


def taylor_green_decay(out_dir: Path, case: dict) -> float:
    import h5py
    import numpy as np

    snaps = _snapshots(out_dir)

    def ke(path: Path) -> tuple[float, float]:
        with h5py.File(path, "r") as f:
            v = np.asarray(f["velocity"])
            m = np.asarray(f["mass"]).reshape(-1)
            return float(0.5 * np.sum(m * np.sum(v * v, axis=1))), float(f.attrs["time"])

    samples = [ke(p) for p in snaps]
    ke0, t0 = samples[0]
    assert t0 == 0.0, "the first snapshot must be the initial state"
    if len(samples) < 3:
        raise ValueError("the decay fit needs snapshots during the run (time.output_interval)")
    nu = case["fluid"]["viscosity"] / case["fluid"]["rho0"]
    L = case["domain"]["hi"][0] - case["domain"]["lo"][0]
    exact = 16 * math.pi**2 * nu / L**2
    t = np.array([s[1] for s in samples[1:]])
    y = -np.log(np.array([s[0] for s in samples[1:]]) / ke0)
    rate = float(np.dot(t, y) / np.dot(t, t))
    return abs(rate - exact) / exact


def poiseuille_series(y, t: float, F: float, nu: float, L: float):
    import numpy as np

    u = F / (2 * nu) * y * (L - y)
    for n in range(200):
        k = 2 * n + 1
        u = u - 4 * F * L * L / (nu * math.pi**3 * k**3) * np.sin(k * math.pi * y / L) * math.exp(
            -k * k * math.pi**2 * nu * t / L**2)
    return u


def poiseuille_profile(out_dir: Path, case: dict) -> float:
    import h5py
    import numpy as np

    with h5py.File(_snapshots(out_dir)[-1], "r") as f:
        x = np.asarray(f["position"])
        v = np.asarray(f["velocity"])
        kind = np.asarray(f["kind"]).reshape(-1)
        t = float(f.attrs["time"])
    fluid = kind == 0
    F = case["fluid"]["gravity"][0]
    nu = case["fluid"]["viscosity"] / case["fluid"]["rho0"]
    L = case["walls"]["tank_hi"][1] - case["walls"]["tank_lo"][1]
    ua = poiseuille_series(x[fluid, 1], t, F, nu, L)
    return float(np.sqrt(np.sum((v[fluid, 0] - ua) ** 2) / np.sum(ua**2)))


def impact_pressure(out_dir: Path, case: dict) -> float:
    """Relative deviation of the 1 ms filtered first-impact peak at sensor P1 (0.16 m on the
    downstream wall of the Zhou/Buchner dam break), read as the wall panel P1_panel (under the
    projection scheme its interpolated force with its wall collisions; a run without the
    panel, from a binary before d930776 under that scheme: the area sensor P1_area), from
    the experiment's, with the definitions of perf/impact/analyse.py (contact at 0.05 rho g
    H, window 0.5 t*)."""
    import sys

    sys.path.insert(0, str(ROOT / "perf" / "impact"))
    import experiment  # noqa: E402 (numpy; the impact study's own definitions)
    import loads_package  # noqa: E402, F401 (scripts/ on the path)
    from sluice_loads import impact  # noqa: E402, PLC0415 (the first-impact figures)

    sc = impact.Scales(H=case["blocks"][0]["hi"][1] - case["blocks"][0]["lo"][1],
                       g=abs(case["fluid"]["gravity"][-1]), rho0=case["fluid"]["rho0"])
    # The wall panel at P1 (force on the 2 cm strip 0.15-0.17 m / 0.02 m): the load the wall
    # carries, which spray cannot fake (perf/impact/STUDY.md, "Read as wall loads").
    import numpy as np  # noqa: PLC0415

    panel = out_dir / "probes" / "P1_panel.csv"
    if panel.exists():
        d = np.genfromtxt(panel, delimiter=",", names=True)
        p = d["Fx_N"] / 0.02
    else:
        # Binaries before d930776 refused force probes under the projection scheme: its P1
        # is then the 9 mm area sensor P1_area, which that scheme reads by interpolation.
        d = np.genfromtxt(out_dir / "probes" / "P1_area.csv", delimiter=",", names=True)
        p = d["pressure_Pa"]
    sim = impact.impact_metrics(d["time_s"], p, sc)["peak_filt_star"]
    exp = experiment.experiment_metrics(0.160, sc)[0]["peak_filt_star"]
    return abs(sim - exp) / exp


EVALUATORS = {
    "dam_break": (dam_break_front, "RMS relative front deviation from Martin & Moyce (T <= 3)"),
    "hydrostatic": (hydrostatic_pressure, "worst relative bottom-pressure error (t >= 1 s)"),
    "taylor_green": (taylor_green_decay, "relative error of the fitted KE decay rate"),
    "poiseuille": (poiseuille_profile, "L2 relative velocity-profile error at the end time"),
    "impact": (impact_pressure,
               "relative deviation of the 1 ms filtered first-impact peak at P1 (Buchner 2002)"),
}
