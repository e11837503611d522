#!/usr/bin/python3
"""sluice and the peer (DualSPHysics) side by side on the wall-impact case, against Buchner's P1.

    perf/impact/peer/compare.py --run LABEL=DIR [--run LABEL=DIR ...] [--out DIR]

Each DIR is a run folder with probes/ as sluice writes it for perf/impact/zhou_2d.toml: a sluice
run (`sluice run perf/impact/zhou_2d.toml --out DIR`) or a peer run converted by
peer_metrics.py. Every figure is computed by perf/impact/analyse.py's functions (definitions in
perf/impact/README.md "Definitions") and panels.py's reading of a wall panel (Fx / 0.02 m):

* per signal (point probes P1, 3/15/30/80/120 mm; panels 0-20, 20-40, 70-90, 150-170 mm):
  contact t*, first-impact peak raw and 1 ms filtered (rho g H), impulse over 0.5 t* after
  contact (p* t*), longest time below -0.5 rho g H after contact (ms); at P1 the ratios to the
  experiment (Trixi digitisation) and, when the run reaches t* = 7, the RMS of the filtered
  signal against it over t* in [2, 7];
* the whole downstream wall (F_right_wall, over rho g H^2 / 2): analyse.wall_force_table;
* when the run reaches t* = 8: the 1 ms mean of the P1 panel and point probe over t* 3.2-5.0,
  5.0-6.5, 6.5-8.0 and the second peak (largest filtered value in t* 5-8) with its time.

Writes OUT/peer_vs_sluice.csv (one row per run x signal), OUT/peer_vs_sluice_force.csv,
OUT/peer_vs_sluice.txt (the tables as printed) and OUT/peer_vs_sluice.png (P1 panel, P1
point probe and whole-wall force against t*, every run and the experiment; left the record,
right the first impact). OUT defaults to perf/impact/results.
"""
from __future__ import annotations

import argparse
import dataclasses
import io
import math
import sys
from contextlib import redirect_stdout
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))
import analyse  # noqa: E402  (perf/impact/analyse.py)
import experiment  # noqa: E402
import metrics  # noqa: E402
import run_folders  # noqa: E402
from sluice_loads import impact, signals, tables  # noqa: E402  (on the path through analyse)
from sluice_loads.tables import format_cell as fmt  # noqa: E402
import panels  # noqa: E402  (perf/impact/panels.py)

SIGNALS = [("P1 panel 150-170 mm", "P1_panel", 0.16), ("P1 point 160 mm", "P1", 0.16),
           ("120 mm point", "P1_y120mm", 0.12), ("70-90 mm panel", "y080mm_panel", 0.08),
           ("80 mm point", "y080mm", 0.08), ("20-40 mm panel", "y030mm_panel", 0.03),
           ("30 mm point", "y030mm", 0.03), ("15 mm point", "y015mm", 0.015),
           ("0-20 mm panel", "y010mm_panel", 0.01), ("3 mm point", "y003mm", 0.003)]
LATER = [(3.2, 5.0), (5.0, 6.5), (6.5, 8.0)]   # t* ranges of the record after the first impact
SECOND = (5.0, 8.0)                             # where the second peak is searched


def signal(run: Path, probe: str) -> tuple[np.ndarray, np.ndarray] | None:
    f = run / "probes" / f"{probe}.csv"
    if not f.exists():
        return None
    d = np.genfromtxt(f, delimiter=",", names=True)
    p = d["Fx_N"] / panels.PANEL_HEIGHT if probe.endswith("_panel") else d["pressure_Pa"]
    return d["time_s"], p


def mean_over(t_star: np.ndarray, pf: np.ndarray, lo: float, hi: float) -> float:
    m = (t_star >= lo) & (t_star <= hi)
    if not m.any() or t_star[-1] < hi:
        return math.nan
    return float(np.mean(pf[m]))


def figures(label: str, run: Path, sc: impact.Scales, exp: dict) -> list[dict]:
    rows = []
    for name, probe, y in SIGNALS:
        s = signal(run, probe)
        if s is None:
            continue
        t, p = s
        m = panels.figures(run, probe, sc)
        row = {"run": label, "signal": name, "probe": probe, "y": y, **{
            k: m[k] for k in ("t_contact_star", "peak_raw_star", "peak_filt_star",
                              "t_peak_filt_star", "impulse_star", "min_raw_star",
                              "neg_longest_ms", "window_complete")}}
        if probe in ("P1", "P1_panel"):
            ts = t / sc.t
            pf = signals.moving_average(t, p, impact.DEFAULT_FILTER_S) / sc.p
            lo, hi = experiment.RMS_RANGE_STAR
            row.update({
                "ratio_peak_filt": m["peak_filt_star"] / exp["peak_filt_star"],
                "ratio_impulse": m["impulse_star"] / exp["impulse_star"],
                "dt_contact_star": m["t_contact_star"] - exp["t_contact_star"],
                "rms_2_7": (metrics.rms_against(ts, pf, exp["t_star"], exp["p_star"], lo, hi)
                            if ts[-1] >= hi else math.nan)})
            for a, b in LATER:
                row[f"mean_{a:g}_{b:g}"] = mean_over(ts, pf, a, b)
            m2 = (ts >= SECOND[0]) & (ts <= SECOND[1])
            ok = m2.any() and ts[-1] >= SECOND[1]
            row["second_peak_filt_star"] = float(pf[m2].max()) if ok else math.nan
            row["t_second_peak_star"] = float(ts[m2][np.argmax(pf[m2])]) if ok else math.nan
        rows.append(row)
    return rows


def run_info(label: str, run: Path, sc: impact.Scales) -> run_folders.RunInfo:
    """What wall_force_table needs: a peer run's study_run.json (peer_metrics.py) gives its c0;
    a sluice run of zhou_2d.toml has dx = 0.01 m and c0 = 48.52 m/s unless --set changed them."""
    if (run / "study_run.json").exists():
        info = run_folders.run_from_study(run)
        return dataclasses.replace(info, variant=label)
    return run_folders.RunInfo(folder=run, variant=label, label=run.name, dx=0.01, c0=48.52,
                               c0_factor=20.0, end_time=math.nan, scales=sc, probes={})


def print_tables(rows: list[dict], exp: dict, exp_b: dict) -> None:
    print("== first impact: per signal (p* = p / rho g H, t* = t sqrt(g/H); window 0.5 t* after "
          "contact; filter 1 ms)")
    print(f"{'signal':22s} {'run':18s} {'t*c':>5s} {'raw':>7s} {'filt':>6s} {'t*pk':>5s} "
          f"{'I*':>6s} {'min*':>7s} {'<-.5ms':>6s}  (cut: the run ends inside the window)")
    for name, _, _ in SIGNALS:
        for r in (x for x in rows if x["signal"] == name):
            print(f"{name:22s} {r['run']:18s} {fmt(r['t_contact_star'], '5.2f')} "
                  f"{fmt(r['peak_raw_star'], '7.2f')} {fmt(r['peak_filt_star'], '6.2f')} "
                  f"{fmt(r['t_peak_filt_star'], '5.2f')} {fmt(r['impulse_star'], '6.3f')} "
                  f"{fmt(r['min_raw_star'], '7.2f')} {fmt(r['neg_longest_ms'], '6.1f')}"
                  f"{'' if r['window_complete'] is not False else '  cut'}")
    print(f"{'experiment P1 (Trixi)':22s} {'':18s} {exp['t_contact_star']:5.2f} "
          f"{exp['peak_raw_star']:7.2f} {exp['peak_filt_star']:6.2f} "
          f"{exp['t_peak_filt_star']:5.2f} {exp['impulse_star']:6.3f}")
    print(f"{'experiment P1 (PySPH)':22s} {'':18s} {exp_b['t_contact_star']:5.2f} "
          f"{exp_b['peak_raw_star']:7.2f} {exp_b['peak_filt_star']:6.2f} "
          f"{exp_b['t_peak_filt_star']:5.2f} {exp_b['impulse_star']:6.3f}")
    p1 = [r for r in rows if r["probe"] in ("P1", "P1_panel")]
    print("\n== P1 against the experiment (Trixi digitisation): filtered peak and impulse ratios, "
          "contact offset, RMS over t* 2-7; after the first impact the 1 ms mean over t* ranges "
          "(experiment: 0.54 / 0.64 / 0.47) and the second peak (experiment 0.88 at t* 5.83)")
    print(f"{'signal':22s} {'run':18s} {'pk/exp':>6s} {'I/exp':>6s} {'dt*c':>6s} {'rms':>5s} "
          + " ".join(f"{f'{a:g}-{b:g}':>7s}" for a, b in LATER) + f" {'2nd pk':>6s} {'t*':>5s}")
    for r in p1:
        print(f"{r['signal']:22s} {r['run']:18s} {fmt(r['ratio_peak_filt'], '6.2f')} "
              f"{fmt(r['ratio_impulse'], '6.2f')} {fmt(r['dt_contact_star'], '+6.2f')} "
              f"{fmt(r['rms_2_7'], '5.2f')} "
              + " ".join(fmt(r[f"mean_{a:g}_{b:g}"], '7.2f') for a, b in LATER)
              + f" {fmt(r['second_peak_filt_star'], '6.2f')} "
                f"{fmt(r['t_second_peak_star'], '5.2f')}")


def plot(runs: list[tuple[str, Path]], sc: impact.Scales, exps: list[dict], out: Path) -> Path:
    import matplotlib  # noqa: PLC0415 (only when plotting)
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt  # noqa: PLC0415
    rows = [("P1_panel", "P1 panel (150-170 mm): Fx / 0.02 m, p / ρgH", True),
            ("P1", "P1 point probe (160 mm), p / ρgH", True),
            ("F_right_wall", "whole downstream wall: Fx / (ρgH²/2)", False)]
    fig, axes = plt.subplots(len(rows), 2, figsize=(15, 4.2 * len(rows)),
                             gridspec_kw={"width_ratios": [1.7, 1]}, squeeze=False)
    colours = plt.cm.tab10.colors
    force_scale = 0.5 * sc.rho0 * sc.g * sc.H**2
    for i, (probe, title, with_exp) in enumerate(rows):
        for ax, (lo, hi) in zip(axes[i], [(1.5, 8.3), (2.3, 3.4)]):
            for j, (label, run) in enumerate(runs):
                f = run / "probes" / f"{probe}.csv"
                if not f.exists():
                    continue
                if probe == "F_right_wall":
                    d = np.genfromtxt(f, delimiter=",", names=True)
                    t, v = d["time_s"], d["Fx_N"] / force_scale
                else:
                    t, p = signal(run, probe)
                    v = p / sc.p
                vf = signals.moving_average(t, v, impact.DEFAULT_FILTER_S)
                ts = t / sc.t
                m = (ts >= lo) & (ts <= hi)
                ax.plot(ts[m], signals.dry_as_zero(v[m]), color=colours[j], lw=0.4, alpha=0.35)
                ax.plot(ts[m], vf[m], color=colours[j], lw=1.4, label=f"{label} (1 ms mean)")
            if with_exp:
                for e, style in zip(exps, ["k-", "k--"]):
                    m = (e["t_star"] >= lo) & (e["t_star"] <= hi)
                    ax.plot(e["t_star"][m], e["p_star"][m], style, lw=1.6, label=e["label"])
            ax.set_xlim(lo, hi)
            ax.axhline(0.0, color="grey", lw=0.5)
            ax.set_title(title + ("" if lo < 2 else ", first impact"), fontsize=10)
            ax.set_xlabel("t* = t √(g/H)")
            ax.grid(alpha=0.3)
        axes[i][0].legend(fontsize=7, loc="upper right")
        # the first-impact column shows the peaks in full; the record column is clipped so the
        # record after the impact is readable
        axes[i][0].set_ylim(-1.0, 3.0)
    fig.suptitle("Zhou / Buchner dam break, dx = H/60, c0 = 20 √(gH): sluice and DualSPHysics "
                 "(raw thin, 1 ms mean thick; left axis clipped to [-1, 3])", fontsize=11)
    fig.tight_layout()
    path = out / "peer_vs_sluice.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def write_csv(path: Path, rows: list[dict]) -> None:
    cols = []
    for r in rows:
        cols.extend(k for k in r if k not in cols)
    tables.write_csv(path, rows, cols)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--run", action="append", required=True, metavar="LABEL=DIR",
                    help="a run folder with probes/ (sluice's, or a peer run after peer_metrics.py)")
    ap.add_argument("--out", type=Path, default=HERE.parent / "results")
    ap.add_argument("--no-plot", action="store_true")
    a = ap.parse_args(argv)
    runs = []
    for s in a.run:
        label, _, d = s.partition("=")
        if not d or not (Path(d) / "probes").is_dir():
            ap.error(f"--run {s}: expected LABEL=DIR with DIR/probes/")
        runs.append((label, Path(d)))
    sc = metrics.zhou_scales()
    exps = experiment.experiment_metrics(0.16, sc)
    exp, exp_b = exps[0], exps[1]
    rows = [r for label, run in runs for r in figures(label, run, sc, exp)]
    buf = io.StringIO()
    with redirect_stdout(buf):
        print_tables(rows, exp, exp_b)
        force = analyse.wall_force_table([run_info(label, run, sc) for label, run in runs],
                                         impact.DEFAULT_WINDOW_STAR, impact.DEFAULT_FILTER_S)
        print("   (variant = run label; whole wall = the x+ face and the corner it shares; "
              "peak over rho g H^2/2 = 1766 N/m, impulse over that times sqrt(H/g))")
    text = buf.getvalue()
    print(text, end="")
    a.out.mkdir(parents=True, exist_ok=True)
    (a.out / "peer_vs_sluice.txt").write_text(
        "# perf/impact/peer/compare.py " + " ".join(f"--run {s}" for s in a.run) + "\n" + text)
    write_csv(a.out / "peer_vs_sluice.csv", rows)
    if force:
        write_csv(a.out / "peer_vs_sluice_force.csv", force)
    if not a.no_plot:
        print(f"wrote {plot(runs, sc, exps, a.out)}")
    print(f"wrote {a.out / 'peer_vs_sluice.txt'}, peer_vs_sluice.csv, peer_vs_sluice_force.csv")
    return 0


if __name__ == "__main__":
    sys.exit(main())
