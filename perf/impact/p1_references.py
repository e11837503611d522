#!/usr/bin/python3
"""sluice's pressure at Buchner's sensor P1 against the record and against published simulations.

    perf/impact/p1_references.py RUN_OR_STUDY [...] [--probes P1_area,P1] [--smooth-ms 10]
                                 [--case CASE.toml] [--out PREFIX] [--png OUT.png]

Buchner's P1 record (two digitisations) sits three times above what sluice reads at the nominal
sensor height, 0.16 m, in every scheme and at every resolution (docs/IMPACT_LOADS.md). Is that
sluice, or the sensor's position? This script sets sluice's signal beside the record and beside
three other codes' simulations of the same case (data/README in ../README.md):

* Marrone et al. (2011), delta-SPH at H/40, H/80, H/320: "P1", where sampled not stated;
* De Courcy et al. (2024), incompressible delta-SPH via artificial compressibility, H/400,
  sampled at 0.16 m (an 8.4 mm segment centred there);
* TrixiParticles.jl's own validation references at H/400, WCSPH (c0 = 20 sqrt(gH)) and EDAC
  (50 sqrt(gH)), sampled at 0.16 m the same way.

sluice's probes and TrixiParticles' series (signals) are averaged over --smooth-ms (centred
moving average, analyse.py's); the digitised curves are left as they are (already smooth).
For every series it prints the mean p/(rho g H) over windows of t* = t sqrt(g/H) (the first
rise, the quasi-static plateau, the second impact), the first maximum before t* = 3.4 (the
0.85 s runs of the convergence studies end at t* = 3.44) and when the second impact peaks, and the RMS
difference from the record and from De Courcy et al. over t* in [2.4, 7.0] where both exist
(the column "to t*" says where that comparison ends).
A window a series does not cover is left empty. --out writes PREFIX.csv and PREFIX.txt.
"""
from __future__ import annotations

import argparse
import math
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import experiment
import loads_package  # noqa: F401  (scripts/ on the path)
import records
import run_folders
from sluice_loads import impact, signals, tables
from sluice_loads.runs import load_probe

WINDOWS = [(2.5, 3.0), (3.0, 3.4), (3.4, 5.0), (5.0, 6.2), (6.2, 7.0)]
FIRST_PEAK_RANGE = (2.4, 3.4)  # the 0.85 s runs end at t* = 3.44
SECOND_PEAK_RANGE = (5.5, 7.0)
RMS_RANGE = (2.4, 7.0)
GRID_STEP = 0.002  # t*: the common grid on which windows and differences are evaluated


@dataclass
class Series:
    label: str
    kind: str        # "record", "code" or "sluice"
    height: str      # where it was sampled, as text
    t: np.ndarray    # t*
    p: np.ndarray    # p / (rho g H)


def references(sc: impact.Scales, smooth_s: float) -> list[Series]:
    out = []
    for label, name in experiment.EXPERIMENT[0.160]:
        t, p = records.load_experiment(name)
        out.append(Series(label, "record", "0.16 m (nominal)", t, p))
    m = records.read_data_columns("marrone2011_P1_sim.csv")
    for col in ("h320", "h80"):
        out.append(Series(f"Marrone et al. 2011, H/{col[1:]}", "code", "not stated",
                          m["time"], m[col]))
    d = records.read_data_columns("decourcy2024_y160mm_sim.csv")
    out.append(Series("De Courcy et al. 2024, H/400", "code", "0.16 m", d["time"], d["P4"]))
    tp = records.read_data_columns("trixiparticles_y160mm_H400.csv")
    for col, what in (("wcsph_Pa", "WCSPH"), ("edac_Pa", "EDAC")):
        p = signals.moving_average(tp["time_s"], tp[col], smooth_s)
        out.append(Series(f"TrixiParticles {what}, H/400", "code", "0.16 m",
                          tp["time_s"] / sc.t, p / sc.p))
    return out


def sluice_series(runs: list[run_folders.RunInfo], probes: list[str],
                  smooth_s: float) -> list[Series]:
    out = []
    for run in runs:
        sc = run.scales
        for name in probes:
            path = run.folder / "probes" / f"{name}.csv"
            if name not in run.probes or not path.exists():
                continue
            t, p = load_probe(path)
            q = signals.moving_average(t, p, smooth_s)
            label = f"sluice {run.variant} {run.label} {name}"
            out.append(Series(label, "sluice", f"{run.probes[name]:.3f} m", t / sc.t, q / sc.p))
    return out


def on_grid(s: Series, lo: float, hi: float) -> tuple[np.ndarray, np.ndarray]:
    """The series interpolated on the common grid over [lo, hi] clipped to where it exists."""
    a, b = max(lo, s.t[0]), min(hi, s.t[-1])
    if b <= a:
        return np.empty(0), np.empty(0)
    g = np.arange(math.ceil(a / GRID_STEP), math.floor(b / GRID_STEP) + 1) * GRID_STEP
    return g, np.interp(g, s.t, s.p)


def window_mean(s: Series, lo: float, hi: float) -> float:
    """Mean over [lo, hi], only when the series covers the whole window."""
    if s.t[0] > lo + GRID_STEP or s.t[-1] < hi - GRID_STEP:
        return math.nan
    _, p = on_grid(s, lo, hi)
    return float(p.mean()) if len(p) else math.nan


def maximum(s: Series, lo: float, hi: float) -> tuple[float, float]:
    """(p, t*) of the largest value over [lo, hi]; NaN if the series ends before hi."""
    if s.t[-1] < hi - GRID_STEP:
        return math.nan, math.nan
    g, p = on_grid(s, lo, hi)
    if not len(p):
        return math.nan, math.nan
    i = int(np.argmax(p))
    return float(p[i]), float(g[i])


def rms_between(a: Series, b: Series) -> tuple[float, float]:
    """(RMS of a - b, the t* where the comparison ends) over RMS_RANGE where both exist."""
    lo, hi = max(RMS_RANGE[0], a.t[0], b.t[0]), min(RMS_RANGE[1], a.t[-1], b.t[-1])
    g, pa = on_grid(a, lo, hi)
    if len(g) < 2:
        return math.nan, math.nan
    return float(math.sqrt(np.mean((pa - np.interp(g, b.t, b.p)) ** 2))), float(g[-1])


def table(series: list[Series], record: Series, decourcy: Series) -> list[dict]:
    rows = []
    for s in series:
        r = {"series": s.label, "kind": s.kind, "sampled_at": s.height,
             "t_end_star": float(s.t[-1])}
        for lo, hi in WINDOWS:
            r[f"mean_{lo:g}_{hi:g}"] = window_mean(s, lo, hi)
        r["first_max"], r["t_first_max"] = maximum(s, *FIRST_PEAK_RANGE)
        r["second_max"], r["t_second_max"] = maximum(s, *SECOND_PEAK_RANGE)
        r["rms_vs_record"], r["rms_to_star"] = rms_between(s, record)
        r["rms_vs_decourcy"], _ = rms_between(s, decourcy)
        rows.append(r)
    return rows


def _f(v: float, spec: str = "5.2f") -> str:
    return "-" if not isinstance(v, float) or v != v else format(v, spec)


def report(rows: list[dict], smooth_ms: float) -> str:
    w = [f"{lo:g}-{hi:g}" for lo, hi in WINDOWS]
    lines = [f"== Buchner's sensor P1: the record, three other codes and sluice's probes (column "
             f"'sampled'); sluice and TrixiParticles averaged over {smooth_ms:g} ms",
             f"   mean p/(rho g H) over t* windows; first max over t* {FIRST_PEAK_RANGE[0]:g}-"
             f"{FIRST_PEAK_RANGE[1]:g}; second max over {SECOND_PEAK_RANGE[0]:g}-"
             f"{SECOND_PEAK_RANGE[1]:g}; RMS over t* {RMS_RANGE[0]:g}-{RMS_RANGE[1]:g} where both exist",
             f"{'series':50s} {'sampled':>11s} " + " ".join(f"{x:>8s}" for x in w)
             + f" {'1st max':>7s} {'at t*':>5s} {'2nd max':>7s} {'at t*':>5s}"
             + f" {'rms rec':>7s} {'rms DeC':>7s} {'to t*':>5s}"]
    lines.append("-" * len(lines[-1]))
    for r in rows:
        lines.append(f"{r['series'][:50]:50s} {r['sampled_at']:>11s} "
                     + " ".join(f"{_f(r[f'mean_{lo:g}_{hi:g}']):>8s}" for lo, hi in WINDOWS)
                     + f" {_f(r['first_max']):>7s} {_f(r['t_first_max']):>5s}"
                     + f" {_f(r['second_max']):>7s} {_f(r['t_second_max']):>5s}"
                     + f" {_f(r['rms_vs_record'], '7.3f'):>7s} {_f(r['rms_vs_decourcy'], '7.3f'):>7s}"
                     + f" {_f(r['rms_to_star']):>5s}")
    return "\n".join(lines)


def plot(series: list[Series], png: Path, smooth_ms: float) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(11, 5.5))
    # references in dark tones (records dotted, codes dashed), sluice in the colour cycle
    dark = iter(["black", "dimgray", "saddlebrown", "darkmagenta", "darkcyan", "darkolivegreen",
                 "navy", "maroon"])
    cycle = iter(plt.rcParams["axes.prop_cycle"].by_key()["color"] * 4)
    for s in series:
        m = (s.t >= 2.2) & (s.t <= 7.1)
        if s.kind == "record":
            kw = dict(ls="none", marker="o", ms=2.5, color=next(dark))
        elif s.kind == "code":
            kw = dict(lw=1.4, ls="--", color=next(dark))
        else:
            kw = dict(lw=1.2, color=next(cycle))
        ax.plot(s.t[m], s.p[m], label=f"{s.label} ({s.height})", **kw)
    ax.set_xlabel("t* = t sqrt(g/H)")
    ax.set_ylabel("p / (rho g H)")
    ax.set_title(f"Zhou/Buchner P1: record, three other codes, sluice ({smooth_ms:g} ms average)")
    ax.set_xlim(2.2, 7.1)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    fig.savefig(png, dpi=130)
    plt.close(fig)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dirs", nargs="+", type=Path, help="run folders or study folders")
    ap.add_argument("--probes", default="P1_area,P1", help="sluice probes at 0.16 m")
    ap.add_argument("--smooth-ms", type=float, default=10.0)
    ap.add_argument("--case", type=Path, default=run_folders.DEFAULT_CASE,
                    help="the case whose probe heights a run folder without study_run.json "
                         "takes (default perf/impact/zhou_2d.toml)")
    ap.add_argument("--out", type=Path, help="write PREFIX.csv and PREFIX.txt")
    ap.add_argument("--png", type=Path)
    a = ap.parse_args(argv)
    with open(a.case, "rb") as f:
        case = tomllib.load(f)
    runs = run_folders.discover(a.dirs, case, {}, "default")
    if not runs:
        print("no runs found", file=sys.stderr)
        return 2
    sc = runs[0].scales
    if any(abs(r.scales.H - sc.H) > 1e-12 or abs(r.scales.g - sc.g) > 1e-12 for r in runs):
        print("runs of different H or g cannot share one reference set", file=sys.stderr)
        return 2
    smooth_s = a.smooth_ms * 1e-3
    refs = references(sc, smooth_s)
    series = refs + sluice_series(runs, [p for p in a.probes.split(",") if p], smooth_s)
    record = refs[0]
    decourcy = next(s for s in refs if s.label.startswith("De Courcy"))
    rows = table(series, record, decourcy)
    text = report(rows, a.smooth_ms)
    print(text)
    if a.out:
        a.out.parent.mkdir(parents=True, exist_ok=True)
        tables.write_csv(a.out.with_suffix(".csv"), rows, list(rows[0].keys()))
        a.out.with_suffix(".txt").write_text(text + "\n")
    if a.png:
        plot(series, a.png, a.smooth_ms)
    return 0


if __name__ == "__main__":
    sys.exit(main())
