#!/usr/bin/python3
"""Wall-impact pressure of finished sluice runs (perf/impact/README.md), from their probe files
alone.

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

This is the study's analysis (its folder layout, sensor heights, Buchner's records); for
runs of a case of your own use `scripts/loads` (docs/IMPACT_LOADS.md), built on the same
definitions. The generic pieces are the product's package scripts/sluice_loads (signals on
irregular samples, the first-impact figures of one signal, tables); beside this file are the
study's: metrics.py (the study's scales, RMS against a record), experiment.py (Buchner's
digitised records), records.py (the reference data), run_folders.py (which runs, with which
dx, c0 and probe heights) and convergence.py (the changes between sound speeds and
resolutions). This file reads the runs' probes with them and prints and writes the tables.
"""
from __future__ import annotations

import argparse
import math
import sys
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import loads_package  # noqa: F401  (scripts/ on the path)
from convergence import CRITERION, convergence_pairs
from experiment import RMS_RANGE_STAR, digitisation_spread, experiment_metrics
from metrics import rms_against
from run_folders import DEFAULT_CASE, RunInfo, discover
from sluice_loads.impact import (CONTACT_FRACTION, DEFAULT_FILTER_S, DEFAULT_SMOOTH_S,
                                 DEFAULT_WINDOW_STAR, Scales, first_impact_window,
                                 impact_metrics)
from sluice_loads.runs import load_probe
from sluice_loads.signals import integral, moving_average
from sluice_loads.tables import format_cell as fmt, write_csv

HERE = Path(__file__).resolve().parent


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


def print_table(results: list[ProbeResult]) -> None:
    # The run column is as wide as the longest label (H240_c20_j0.002 and H240_c20_j0.005
    # must not print alike).
    rw = max([14] + [len(r.run.label) for r in results])
    head = (f"{'variant':10s} {'run':{rw}s} {'H/dx':>5s} {'c0*':>4s} {'probe':9s} {'y[m]':>6s} "
            f"{'t*c':>5s} {'raw':>6s} {'filt':>6s} {'t*pk':>5s} {'I*':>6s} {'min*':>7s} "
            f"{'<-.5 ms':>7s} {'tot ms':>6s} {'pk/exp':>6s} {'I/exp':>6s} {'rms':>5s} {'win':>3s}")
    print(head)
    print("-" * len(head))
    for r in results:
        row = r.row()
        rms = row["rms_2_7"] if math.isfinite(row["rms_2_7"]) else row["rms_2_end"]
        print(f"{row['variant'][:10]:10s} {row['run']:{rw}s} {row['H_over_dx']:5.0f} "
              f"{row['c0_factor']:4g} {row['probe'][:9]:9s} {row['probe_y']:6.3f} "
              f"{fmt(row['t_contact_star'], '5.2f')} {fmt(row['peak_raw_star'], '6.2f')} "
              f"{fmt(row['peak_filt_star'], '6.3f')} {fmt(row['t_peak_filt_star'], '5.2f')} "
              f"{fmt(row['impulse_star'], '6.3f')} {fmt(row['min_raw_star'], '7.2f')} "
              f"{fmt(row['neg_longest_ms'], '7.2f')} {fmt(row['neg_total_ms'], '6.1f')} "
              f"{fmt(row['ratio_peak_filt'], '6.2f')} {fmt(row['ratio_impulse'], '6.2f')} "
              f"{fmt(rms, '5.3f')} "
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


def print_convergence(pairs: list[dict]) -> None:
    print("\n== convergence: relative change of the filtered first-impact peak (and of the peak "
          "after the longer average, and of the impulse), (fine - coarse) / fine; the study's "
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
            # RECOMMENDED_PRACTICE.md); the study's criterion stays the filtered peak's.
            smooth = q["rel_change_smooth"]
            if math.isfinite(smooth):
                flag += f" (longer average {'PASS' if abs(smooth) < CRITERION else 'FAIL'})"
        print(f"      {q['what']:24s} peak {fmt(q['peak_a'], '6.3f')} -> {fmt(q['peak_b'], '6.3f')}"
              f"  {fmt(100 * q['rel_change_peak'], '+7.1f')} %"
              f"   longer average {fmt(100 * q['rel_change_smooth'], '+7.1f')} %"
              f"   impulse {fmt(100 * q['rel_change_impulse'], '+7.1f')} %{flag}")


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
        window = first_impact_window(t, ff, CONTACT_FRACTION * scale, window_star * r.scales.t)
        if window is None:
            continue
        tc, te = window
        w = (t >= tc) & (t <= te)
        rows.append({"variant": r.variant, "run": r.label, "H_over_dx": r.scales.H / r.dx,
                     "c0_factor": r.c0_factor, "t_contact_star": tc / r.scales.t,
                     "peak_raw": float(fx[w].max() / scale), "peak_filt": float(ff[w].max() / scale),
                     "peak_smooth": float(fs[w].max() / scale),
                     "impulse_star": integral(t, fx, tc, te) / (scale * r.scales.t)})
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
