#!/usr/bin/python3
"""Wall-impact pressure of finished sluice runs (issue 18), from their probe files alone.

    perf/impact/analyse.py DIR [DIR ...] [--out DIR] [--case CASE.toml] [--probe NAME=Y ...]
                           [--window 0.5] [--filter-ms 1.0] [--smooth-ms 10] [--no-plots]

DIR is a study folder written by study.py (every run folder below it that holds a
study_run.json is analysed) or a single run folder (one with probes/). For a run folder that
study.py did not write, the probe heights come from --probe NAME=Y, else from --case (the
case file the run was made from; probes matched by name), else from the name (P1 = 0.16 m,
P2 = 0.584 m, yNNNmm = NNN mm, pNNN = NNN cm as in the first trials); dx is inferred from the
fluid particle count in summary.json and c0 from the first time step (dt = cfl h / c0 at
rest), both with the case's block, cfl and h/dx (--case, default perf/impact/zhou_2d.toml).

Definitions (all in README.md): rho g H and sqrt(H/g) scale pressure and time
(p* = p/(rho0 g H), t* = t sqrt(g/H)); a dry probe (NaN) reads 0; the contact time is the
first sample with p > 0.05 rho0 g H; the first-impact window is [t_c, t_c + WINDOW/sqrt(g/H)];
the filtered signal is the centred moving average over FILTER_MS of time, from the
trapezoidal cumulative integral of the irregularly sampled signal; the smooth peak is the
filtered peak once more with the longer SMOOTH_MS (default 10 ms); the impulse is the
trapezoidal integral of p dt over the window. Writes OUT/impact_convergence.csv (one row per
run x probe), OUT/impact_convergence_pairs.csv (the convergence section) and, unless
--no-plots, the PNGs of plot.py.
"""
from __future__ import annotations

import argparse
import csv
import dataclasses
import json
import math
import re
import statistics
import sys
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
DATA = HERE / "data"
DEFAULT_CASE = HERE / "zhou_2d.toml"

CONTACT_FRACTION = 0.05      # contact: p > 0.05 rho g H
NEGATIVE_FRACTION = -0.5     # "below -0.5 rho g H"
DEFAULT_WINDOW_STAR = 0.5    # first-impact window length in t* units
DEFAULT_FILTER_S = 1.0e-3    # moving-average width in seconds
DEFAULT_SMOOTH_S = 10.0e-3   # the second, longer average: WCSPH's peaks after it do not depend
                             # on c0 (docs/IMPACT_LOADS.md, "The sound-speed ladder")
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


# ----------------------------------------------------------------------------- signals

def load_probe(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """time_s, pressure_Pa of a probe CSV; NaN (dry) kept as NaN."""
    d = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return d[:, 0], d[:, 1]


def read_data_columns(name: str) -> dict[str, np.ndarray]:
    """The columns of a CSV in data/ ('#' header lines, then a row of column names), keyed by
    name, rows sorted by the first column (stable: digitisations such as the PySPH copy have
    a few rows out of time order, as in their sources)."""
    with open(DATA / name) as f:
        rows = list(csv.reader(ln for ln in f if not ln.startswith("#")))
    body = np.array([[float(x) for x in r] for r in rows[1:] if r])
    body = body[np.argsort(body[:, 0], kind="stable")]
    return {h: body[:, i] for i, h in enumerate(rows[0])}


def load_experiment(name: str) -> tuple[np.ndarray, np.ndarray]:
    """(t*, p*) of a digitised record in data/ (its first two columns), sorted by time."""
    cols = list(read_data_columns(name).values())
    return cols[0], cols[1]


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
    hit = np.nonzero((q > CONTACT_FRACTION * sc.p) & (t >= t_min))[0]
    if len(hit) == 0:
        return res
    i0 = hit[0]
    tc = float(t[i0])
    te = tc + window_star * sc.t
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


# ----------------------------------------------------------------------------- runs

@dataclass
class RunInfo:
    folder: Path
    variant: str
    label: str
    dx: float
    c0: float
    c0_factor: float
    end_time: float
    scales: Scales
    probes: dict[str, float]                 # pressure probe name -> height y [m]
    probe_x: dict[str, float] = field(default_factory=dict)
    wall_s: float = float("nan")
    steps: int = 0
    inferred: str = ""                       # what was guessed (old runs)


def _legacy_height(name: str) -> float | None:
    m = re.fullmatch(r"y(\d+)mm", name)
    if m:
        return int(m.group(1)) / 1000.0
    m = re.fullmatch(r"p(\d{3})", name)
    if m:
        return int(m.group(1)) / 100.0
    return {"P1": 0.16, "P2": 0.584}.get(name)


def _case_scales(case: dict) -> Scales:
    b = case["blocks"][0]
    H = float(b["hi"][1] - b["lo"][1])
    g = abs(float(case["fluid"].get("gravity", [0.0, -9.81])[-1]))
    return Scales(H=H, g=g, rho0=float(case["fluid"].get("rho0", 1000.0)))


def run_from_study(folder: Path) -> RunInfo:
    with open(folder / "study_run.json") as f:
        j = json.load(f)
    sc = Scales(**j["scales"])
    summ = {}
    if (folder / "summary.json").exists():
        with open(folder / "summary.json") as f:
            summ = json.load(f)
    probes = {n: float(v["position"][1]) for n, v in j["probes"].items()}
    px = {n: float(v["position"][0]) for n, v in j["probes"].items()}
    note = "" if j.get("returncode", 0) == 0 else \
        f"run FAILED (exit {j.get('returncode')}): its probe files stop where it stopped"
    return RunInfo(folder=folder, variant=j["variant"], label=j["label"], dx=j["dx"], c0=j["c0"],
                   c0_factor=j["c0_factor"], end_time=summ.get("simulated_time", j["end_time"]),
                   scales=sc, probes=probes, probe_x=px, wall_s=summ.get("wall_seconds", math.nan),
                   steps=summ.get("steps", 0), inferred=note)


def run_from_folder(folder: Path, case: dict, heights: dict[str, float],
                    variant: str) -> RunInfo:
    """A run folder without study_run.json (made by hand): guess what is not written."""
    sc = _case_scales(case)
    with open(folder / "summary.json") as f:
        summ = json.load(f)
    notes = []
    # dx from the fluid particle count and the case's block area (lattice fill)
    b = case["blocks"][0]
    area = float(np.prod(np.subtract(b["hi"], b["lo"])))
    dim = int(case["case"]["dimension"])
    dx = (area / summ["fluid_particles"]) ** (1.0 / dim)
    dx = float(f"{dx:.4g}")
    notes.append(f"dx={dx:g} from particle count")
    probe_case = {p["name"]: p for p in case.get("probes", [])}
    probes, px = {}, {}
    for f in sorted((folder / "probes").glob("*.csv")):
        with open(f) as fh:
            head = fh.readline().strip()
        if not head.startswith("time_s,pressure_Pa"):
            continue
        n = f.stem
        if n in heights:
            y = heights[n]
        elif n in probe_case and "position" in probe_case[n]:
            y = float(probe_case[n]["position"][1])
            px[n] = float(probe_case[n]["position"][0])
        else:
            y = _legacy_height(n)
            if y is None:
                print(f"   {folder}: no height for probe {n} (use --probe {n}=Y); skipped")
                continue
            notes.append(f"{n}: y={y:g} from its name")
        probes[n] = y
    # c0 from the first step: at rest dt = cfl * h / c0 (the acoustic limit governs)
    num = case.get("numerics", {})
    c0 = float(case["fluid"]["sound_speed"])
    first = next(iter(probes), None)
    if first is not None:
        t, _ = load_probe(folder / "probes" / f"{first}.csv")
        if len(t) > 1 and t[1] > 0:
            h = float(num.get("h_over_dx", 1.0)) * dx
            c0 = float(num.get("cfl", 0.25)) * h / float(t[1])
            notes.append(f"c0={c0:.4g} from first dt")
    factor = c0 / math.sqrt(sc.g * sc.H)
    return RunInfo(folder=folder, variant=variant, label=folder.name, dx=dx, c0=c0,
                   c0_factor=round(factor, 2), end_time=summ.get("simulated_time", math.nan),
                   scales=sc, probes=probes, probe_x=px, wall_s=summ.get("wall_seconds", math.nan),
                   steps=summ.get("steps", 0), inferred="; ".join(notes))


def discover(dirs: list[Path], case: dict, heights: dict[str, float],
             variant: str) -> list[RunInfo]:
    runs = []
    for d in dirs:
        if (d / "study_run.json").exists():
            runs.append(run_from_study(d))
        elif (d / "probes").is_dir():
            runs.append(run_from_folder(d, case, heights, variant))
        else:
            found = sorted(p.parent for p in d.rglob("study_run.json"))
            if not found:
                print(f"   {d}: no run folder (probes/) or study_run.json below it")
            runs.extend(run_from_study(p) for p in found)
    return [r for r in runs if (r.folder / "probes").is_dir()]


# ----------------------------------------------------------------------------- analysis

COLUMNS = ["variant", "run", "dx", "H_over_dx", "c0", "c0_factor", "end_time", "probe",
           "probe_x", "probe_y", "t_contact_s", "t_contact_star", "peak_raw_star",
           "t_peak_raw_star", "peak_filt_star", "t_peak_filt_star", "peak_raw_Pa", "peak_filt_Pa",
           "peak_smooth_star", "peak_smooth_Pa", "impulse_Pa_s", "impulse_star",
           "window_complete", "min_raw_star", "min_filt_star", "neg_longest_ms", "neg_total_ms",
           "neg_count", "wet_fraction", "samples",
           "exp_t_contact_star", "exp_peak_raw_star", "exp_t_peak_raw_star", "exp_peak_filt_star",
           "exp_impulse_star", "ratio_peak_raw", "ratio_peak_filt", "ratio_impulse",
           "dt_peak_star", "rms_2_7", "rms_2_end", "rms_hi_star", "wall_s", "steps", "inferred"]


@dataclass
class ProbeResult:
    run: RunInfo
    probe: str
    y: float
    t: np.ndarray
    p: np.ndarray            # NaN kept
    pf: np.ndarray           # filtered, dry = 0
    metrics: dict
    exp: list[dict]

    def row(self) -> dict:
        r, m = self.run, self.metrics
        row = {"variant": r.variant, "run": r.label, "dx": r.dx, "H_over_dx": r.scales.H / r.dx,
               "c0": r.c0, "c0_factor": r.c0_factor, "end_time": r.end_time, "probe": self.probe,
               "probe_x": r.probe_x.get(self.probe, float("nan")), "probe_y": self.y,
               "wall_s": r.wall_s, "steps": r.steps, "inferred": r.inferred}
        row.update({k: v for k, v in m.items() if k in COLUMNS})
        for k in ["exp_t_contact_star", "exp_peak_raw_star", "exp_t_peak_raw_star",
                  "exp_peak_filt_star", "exp_impulse_star", "ratio_peak_raw", "ratio_peak_filt",
                  "ratio_impulse", "dt_peak_star", "rms_2_7", "rms_2_end", "rms_hi_star"]:
            row[k] = float("nan")
        if self.exp:
            e = self.exp[0]
            sc = r.scales
            lo, hi = RMS_RANGE_STAR
            ts = self.t / sc.t
            ps = self.pf / sc.p
            hi_end = min(hi, float(ts[-1]))
            row.update({
                "exp_t_contact_star": e["t_contact_star"], "exp_peak_raw_star": e["peak_raw_star"],
                "exp_t_peak_raw_star": e["t_peak_raw_star"],
                "exp_peak_filt_star": e["peak_filt_star"], "exp_impulse_star": e["impulse_star"],
                "ratio_peak_raw": m["peak_raw_star"] / e["peak_raw_star"],
                "ratio_peak_filt": m["peak_filt_star"] / e["peak_filt_star"],
                "ratio_impulse": m["impulse_star"] / e["impulse_star"],
                "dt_peak_star": m["t_peak_filt_star"] - e["t_peak_raw_star"],
                "rms_2_7": (rms_against(ts, ps, e["t_star"], e["p_star"], lo, hi)
                            if ts[-1] >= hi else float("nan")),
                # only once the run has passed the experiment's contact (else it compares
                # two dry baselines)
                "rms_2_end": (rms_against(ts, ps, e["t_star"], e["p_star"], lo, hi_end)
                              if hi_end > e["t_contact_star"] else float("nan")),
                "rms_hi_star": hi_end,
            })
        return row


def analyse_run(run: RunInfo, window_star: float = DEFAULT_WINDOW_STAR,
                filter_s: float = DEFAULT_FILTER_S,
                smooth_s: float = DEFAULT_SMOOTH_S) -> list[ProbeResult]:
    out = []
    exp_cache: dict[float, list[dict]] = {}
    for name, y in sorted(run.probes.items(), key=lambda kv: kv[1]):
        f = run.folder / "probes" / f"{name}.csv"
        if not f.exists():
            continue
        t, p = load_probe(f)
        if len(t) < 2:
            continue
        m = impact_metrics(t, p, run.scales, window_star, filter_s, smooth_s=smooth_s)
        key = round(y, 4)
        if key not in exp_cache:
            exp_cache[key] = experiment_metrics(y, run.scales, window_star, filter_s)
        out.append(ProbeResult(run=run, probe=name, y=y, t=t, p=p,
                               pf=moving_average(t, p, filter_s), metrics=m, exp=exp_cache[key]))
    return out


def _fmt(v, spec: str) -> str:
    if isinstance(v, float) and not math.isfinite(v):
        width = re.match(r"[<>^]?(\d*)", spec.lstrip("+")).group(1)
        return "-".rjust(int(width) if width else 1)
    return format(v, spec)


def print_table(results: list[ProbeResult]) -> None:
    head = (f"{'variant':10s} {'run':14s} {'H/dx':>5s} {'c0*':>4s} {'probe':9s} {'y[m]':>6s} "
            f"{'t*c':>5s} {'raw':>6s} {'filt':>6s} {'t*pk':>5s} {'I*':>6s} {'min*':>7s} "
            f"{'<-.5 ms':>7s} {'tot ms':>6s} {'pk/exp':>6s} {'I/exp':>6s} {'rms':>5s} {'win':>3s}")
    print(head)
    print("-" * len(head))
    for r in results:
        row = r.row()
        rms = row["rms_2_7"] if math.isfinite(row["rms_2_7"]) else row["rms_2_end"]
        print(f"{row['variant'][:10]:10s} {row['run'][:14]:14s} {row['H_over_dx']:5.0f} "
              f"{row['c0_factor']:4g} {row['probe'][:9]:9s} {row['probe_y']:6.3f} "
              f"{_fmt(row['t_contact_star'], '5.2f')} {_fmt(row['peak_raw_star'], '6.2f')} "
              f"{_fmt(row['peak_filt_star'], '6.3f')} {_fmt(row['t_peak_filt_star'], '5.2f')} "
              f"{_fmt(row['impulse_star'], '6.3f')} {_fmt(row['min_raw_star'], '7.2f')} "
              f"{_fmt(row['neg_longest_ms'], '7.2f')} {_fmt(row['neg_total_ms'], '6.1f')} "
              f"{_fmt(row['ratio_peak_filt'], '6.2f')} {_fmt(row['ratio_impulse'], '6.2f')} "
              f"{_fmt(rms, '5.3f')} "
              f"{'' if not math.isfinite(row['t_contact_s']) else ('ok' if row['window_complete'] else 'cut'):>3s}")
    print("columns: t*c contact time; raw / filt first-impact peak p/(rho g H), unfiltered and "
          "1 ms moving average; t*pk time of the filtered peak; I* impulse over the window "
          "(p* t*); min* raw minimum after contact; <-.5 ms longest / tot total time below "
          "-0.5 rho g H after contact; pk/exp, I/exp filtered peak and impulse over the "
          "experiment's; rms of (filtered - exp) in p* over t* in [2, 7] (or [2, end]); win: "
          "cut when the run ends inside the first-impact window (impulse incomplete)")


def print_experiment(sc: Scales, window_star: float, filter_s: float) -> None:
    print("\n== experiment (digitised Buchner 2002 records, same definitions)")
    for y in (0.160, 0.584):
        for e in experiment_metrics(y, sc, window_star, filter_s):
            print(f"   {e['sensor']} y={y:.3f} {e['label']:36s} contact t*={e['t_contact_star']:.3f}"
                  f"  peak {e['peak_raw_star']:.3f} at t*={e['t_peak_raw_star']:.3f}"
                  f"  filtered {e['peak_filt_star']:.3f}  impulse* {e['impulse_star']:.4f}"
                  f"  min after contact {e['min_raw_star']:.3f}")
    s = digitisation_spread(sc)
    print(f"   P1 digitisations differ by: peak {abs(s['peak_a'] - s['peak_b']):.3f} "
          f"({100 * abs(s['peak_a'] - s['peak_b']) / s['peak_a']:.1f} %), peak time "
          f"{abs(s['t_peak_a'] - s['t_peak_b']):.3f} t*, contact {abs(s['t_contact_a'] - s['t_contact_b']):.3f} t*, "
          f"impulse {100 * abs(s['impulse_a'] - s['impulse_b']) / s['impulse_a']:.1f} %, "
          f"RMS (PySPH - Trixi) over t* in [2, 7] {s['rms_ab']:.3f} p*")


CRITERION = 0.15  # issue 18: the filtered peak changes by less than 15 %


def ensemble_medians(results: list[ProbeResult]) -> list[ProbeResult]:
    """One result per (dx, c0) of a variant and probe: the runs of an ensemble (study.py
    --jitters: labels ending in _j<jitter>) replaced by one whose peak and impulse are their
    medians. A single run stands for itself."""
    groups: dict[tuple, list[ProbeResult]] = {}
    for r in results:
        groups.setdefault((r.run.dx, r.run.c0_factor), []).append(r)
    out = []
    for g in groups.values():
        if len(g) == 1:
            out.append(g[0])
            continue
        med = dataclasses.replace(g[0], metrics=dict(g[0].metrics))
        for k in ("peak_filt_star", "peak_smooth_star", "impulse_star"):
            vals = [x.metrics[k] for x in g if math.isfinite(x.metrics[k])]
            med.metrics[k] = statistics.median(vals) if vals else math.nan
        out.append(med)
    return out


def _change(a: float, b: float) -> float:
    """(b - a) / b, the change from the coarse a to the fine b; NaN where undefined."""
    return (b - a) / b if b and math.isfinite(b) and math.isfinite(a) else math.nan


def convergence_pairs(results: list[ProbeResult]) -> list[dict]:
    """For each variant and probe: the relative change of the filtered peak (and of the
    smooth peak and the impulse) between successive c0 at each dx, and between successive dx
    at each c0, relative to the stiffer / finer run: (P_b - P_a) / P_b; ensembles by their
    medians."""
    by = {}
    for r in results:
        by.setdefault((r.run.variant, r.probe), []).append(r)
    pairs = []
    for (variant, probe), members in by.items():
        rs = ensemble_medians(members)
        for kind, group_key, step_key in (("c0", "dx", "c0_factor"), ("dx", "c0_factor", "dx")):
            groups = {}
            for r in rs:
                groups.setdefault(getattr(r.run, group_key), []).append(r)
            for gval, g in sorted(groups.items()):
                # coarse -> fine: c0 ascending, dx descending
                g = sorted(g, key=lambda r: getattr(r.run, step_key), reverse=(kind == "dx"))
                for a, b in zip(g, g[1:]):
                    pa, pb = a.metrics["peak_filt_star"], b.metrics["peak_filt_star"]
                    sa, sb = a.metrics["peak_smooth_star"], b.metrics["peak_smooth_star"]
                    ia, ib = a.metrics["impulse_star"], b.metrics["impulse_star"]
                    rel, rels, reli = _change(pa, pb), _change(sa, sb), _change(ia, ib)
                    if kind == "c0":
                        what = f"c0 {a.run.c0_factor:g}->{b.run.c0_factor:g} at H/{a.run.scales.H / gval:.0f}"
                        crit = (a.run.c0_factor, b.run.c0_factor) == (20, 40)
                    else:
                        what = (f"H/{a.run.scales.H / a.run.dx:.0f}->H/{b.run.scales.H / b.run.dx:.0f}"
                                f" at c0 {gval:g}")
                        crit = (round(a.run.scales.H / a.run.dx), round(b.run.scales.H / b.run.dx)) == (60, 120)
                    pairs.append({"variant": variant, "probe": probe, "y": a.y, "step": kind,
                                  "what": what, "peak_a": pa, "peak_b": pb, "rel_change_peak": rel,
                                  "smooth_a": sa, "smooth_b": sb, "rel_change_smooth": rels,
                                  "impulse_a": ia, "impulse_b": ib, "rel_change_impulse": reli,
                                  "criterion_pair": crit,
                                  "passes": (abs(rel) < CRITERION) if math.isfinite(rel) else None})
    return pairs


def print_convergence(pairs: list[dict]) -> None:
    print("\n== convergence: relative change of the filtered first-impact peak (and of the peak "
          "after the longer average, and of the impulse), (fine - coarse) / fine; issue 18 "
          "criterion |change| < 15 % of the filtered peak for c0 20->40 and H/60->H/120")
    if not pairs:
        print("   (no pairs: needs at least two c0 at one dx or two dx at one c0)")
        return
    last = None
    for q in sorted(pairs, key=lambda q: (q["variant"], q["y"], q["probe"], q["step"])):
        if (q["variant"], q["probe"]) != last:
            last = (q["variant"], q["probe"])
            print(f"   {q['variant']} / {q['probe']} (y = {q['y']:.3f} m)")
        flag = ""
        if q["criterion_pair"]:
            flag = {True: "  PASS", False: "  FAIL", None: "  n/a"}[q["passes"]]
            # The same 15 % on the longer average's peak, the load that converges (docs/
            # RECOMMENDED_PRACTICE.md); the issue's criterion stays the filtered peak's.
            smooth = q["rel_change_smooth"]
            if math.isfinite(smooth):
                flag += f" (longer average {'PASS' if abs(smooth) < CRITERION else 'FAIL'})"
        print(f"      {q['what']:24s} peak {_fmt(q['peak_a'], '6.3f')} -> {_fmt(q['peak_b'], '6.3f')}"
              f"  {_fmt(100 * q['rel_change_peak'], '+7.1f')} %"
              f"   longer average {_fmt(100 * q['rel_change_smooth'], '+7.1f')} %"
              f"   impulse {_fmt(100 * q['rel_change_impulse'], '+7.1f')} %{flag}")


def write_csv(path: Path, rows: list[dict], columns: list[str]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


def wall_force_table(runs: list[RunInfo], window_star: float, filter_s: float,
                     smooth_s: float = DEFAULT_SMOOTH_S) -> list[dict]:
    """First-impact figures of the horizontal force on the downstream wall (probe
    F_right_wall, N per metre of width), nondimensionalised by the hydrostatic force of the
    column rho g H^2 / 2: the load an engineer sizes a wall with, and one that spray cannot
    fake (a spray particle's pair forces are as small as its mass). Contact: the force exceeds
    0.05 of that scale."""
    rows = []
    for r in runs:
        f = r.folder / "probes" / "F_right_wall.csv"
        if not f.exists():
            continue
        d = np.genfromtxt(f, delimiter=",", names=True)
        t, fx = d["time_s"], d["Fx_N"]
        scale = 0.5 * r.scales.rho0 * r.scales.g * r.scales.H**2
        ff = moving_average(t, fx, filter_s)
        fs = moving_average(t, fx, smooth_s)
        hit = np.nonzero(ff > 0.05 * scale)[0]
        if len(hit) == 0:
            continue
        tc = t[hit[0]]
        w = (t >= tc) & (t <= tc + window_star * r.scales.t)
        rows.append({"variant": r.variant, "run": r.label, "H_over_dx": r.scales.H / r.dx,
                     "c0_factor": r.c0_factor, "t_contact_star": tc / r.scales.t,
                     "peak_raw": float(fx[w].max() / scale), "peak_filt": float(ff[w].max() / scale),
                     "peak_smooth": float(fs[w].max() / scale),
                     "impulse_star": integral(t, fx, tc, tc + window_star * r.scales.t)
                     / (scale * r.scales.t)})
    if rows:
        print(f"\n== horizontal force on the downstream wall (F_right_wall) over rho g H^2/2, "
              f"first {window_star:g} t* after contact, filter {1e3 * filter_s:g} ms "
              f"(smooth: {1e3 * smooth_s:g} ms)")
        print(f"{'variant':12s} {'run':10s} {'H/dx':>5s} {'c0*':>4s} {'t*c':>6s} {'raw':>7s} "
              f"{'filt':>7s} {'smooth':>7s} {'I*':>7s}")
        for x in rows:
            print(f"{x['variant']:12s} {x['run']:10s} {x['H_over_dx']:5.0f} {x['c0_factor']:4.0f} "
                  f"{x['t_contact_star']:6.2f} {x['peak_raw']:7.2f} {x['peak_filt']:7.2f} "
                  f"{x['peak_smooth']:7.2f} {x['impulse_star']:7.3f}")
    return rows


def analyse(runs: list[RunInfo], out: Path, window_star: float = DEFAULT_WINDOW_STAR,
            filter_s: float = DEFAULT_FILTER_S, plots: bool = True,
            smooth_s: float = DEFAULT_SMOOTH_S) -> list[ProbeResult]:
    """Analyses the runs, prints the tables, writes the CSVs and (optionally) the PNGs."""
    runs = sorted(runs, key=lambda r: (r.variant, -r.dx, r.c0_factor, r.label))
    results = []
    for r in runs:
        results.extend(analyse_run(r, window_star, filter_s, smooth_s))
    if not results:
        print("no pressure probe found")
        return results
    print(f"\n== first impact (window {window_star:g} t* after contact, filter {1e3 * filter_s:g} ms)")
    print_table(results)
    print_experiment(runs[0].scales, window_star, filter_s)
    pairs = convergence_pairs(results)
    print_convergence(pairs)
    forces = wall_force_table(runs, window_star, filter_s, smooth_s)
    if forces:
        write_csv(out / "impact_wall_force.csv", forces, list(forces[0].keys()))
    write_csv(out / "impact_convergence.csv", [r.row() for r in results], COLUMNS)
    write_csv(out / "impact_convergence_pairs.csv", pairs,
              ["variant", "probe", "y", "step", "what", "peak_a", "peak_b", "rel_change_peak",
               "smooth_a", "smooth_b", "rel_change_smooth", "impulse_a", "impulse_b",
               "rel_change_impulse", "criterion_pair", "passes"])
    print(f"\nwrote {out / 'impact_convergence.csv'} and {out / 'impact_convergence_pairs.csv'}")
    if plots:
        sys.path.insert(0, str(HERE))
        import plot  # noqa: PLC0415 (matplotlib only when plotting)
        for f in plot.all_plots(results, out, window_star):
            print(f"wrote {f}")
    return results


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dirs", nargs="+", type=Path, help="study folders or run folders")
    ap.add_argument("--out", type=Path, help="where the CSVs and PNGs go (default: the study "
                    "folder if one study folder is given, else perf/impact/results)")
    ap.add_argument("--case", type=Path, default=DEFAULT_CASE,
                    help="case file of runs not made by study.py (scales, probe heights)")
    ap.add_argument("--probe", action="append", default=[], metavar="NAME=Y",
                    help="height [m] of a pressure probe of runs not made by study.py")
    ap.add_argument("--variant", default="default",
                    help="variant label of runs not made by study.py (default: default)")
    ap.add_argument("--window", type=float, default=DEFAULT_WINDOW_STAR,
                    help="first-impact window after contact, in t* units (default 0.5)")
    ap.add_argument("--filter-ms", type=float, default=1e3 * DEFAULT_FILTER_S,
                    help="moving-average width in ms (default 1)")
    ap.add_argument("--smooth-ms", type=float, default=1e3 * DEFAULT_SMOOTH_S,
                    help="width in ms of the second, longer moving average whose peak is "
                    "reported beside the filtered one (default 10)")
    ap.add_argument("--no-plots", action="store_true")
    a = ap.parse_args(argv)
    heights = {}
    for s in a.probe:
        n, _, y = s.partition("=")
        if not y:
            ap.error(f"--probe {s}: expected NAME=Y")
        heights[n] = float(y)
    with open(a.case, "rb") as f:
        case = tomllib.load(f)
    runs = discover(a.dirs, case, heights, a.variant)
    if not runs:
        print("no runs found", file=sys.stderr)
        return 1
    out = a.out
    if out is None:
        out = a.dirs[0] if len(a.dirs) == 1 and (a.dirs[0] / "study.json").exists() \
            else HERE / "results"
    for r in runs:
        if r.inferred:
            print(f"   {r.folder}: {r.inferred}")
    analyse(runs, out, a.window, 1e-3 * a.filter_ms, plots=not a.no_plots,
            smooth_s=1e-3 * a.smooth_ms)
    return 0


if __name__ == "__main__":
    sys.exit(main())
