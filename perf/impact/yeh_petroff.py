#!/usr/bin/env python3
"""Yeh & Petroff bore impact on a square column: the streamwise force on the column of a sluice
run (perf/impact/yeh_petroff_3d.toml, probe F_column) against the experiment
(perf/impact/data/yeh_petroff_column_force.csv).

The experiment's time origin is that of the published figure, not the gate opening, so both
records are aligned on the start of the impact: the first time the force exceeds
`--rise` N (default 8 N, twice the experiment's pre-impact noise of about 4 N). Reported:
the first-impact peak of the force (raw, and after a centred moving average of `--filter-ms`,
default 10 ms: the digitised record has a few points per 10 ms), the mean force over the
plateau 0.15-0.5 s after the rise, the impulse (the integral of the force, trapezoidal over the
raw samples) over the first 0.15 s after the rise (the window of the first-impact peak), and the
RMS difference of the filtered force over 0-0.5 s after the rise. Usage: yeh_petroff.py
RUN_DIR[:PROBE] [RUN_DIR[:PROBE]...] [--png FILE]; PROBE (default F_column) names another force
probe of the run, e.g. one with reading = "interpolated".
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import loads_package  # noqa: E402, F401  (scripts/ on the path)
from sluice_loads import signals  # noqa: E402  (moving_average, integral on irregular samples)

EXP = HERE / "data" / "yeh_petroff_column_force.csv"


def load_exp() -> tuple[np.ndarray, np.ndarray]:
    d = np.loadtxt(EXP, delimiter=",", comments="#", skiprows=0, dtype=str)
    rows = [r for r in d if r[0][0] in "-0123456789."]
    a = np.array([[float(x) for x in r] for r in rows])
    o = np.argsort(a[:, 0], kind="stable")
    return a[o, 0], a[o, 1]


def split_run(arg: str) -> tuple[Path, str]:
    """RUN_DIR[:PROBE] -> (run folder, probe name); the probe defaults to F_column."""
    run, _, probe = arg.partition(":")
    return Path(run), probe or "F_column"


def load_run(run: Path, probe: str = "F_column") -> tuple[np.ndarray, np.ndarray]:
    d = np.genfromtxt(run / "probes" / f"{probe}.csv", delimiter=",", names=True)
    return d["time_s"], d["Fx_N"]


def metrics(t: np.ndarray, f: np.ndarray, rise: float, filter_s: float) -> dict:
    ff = signals.moving_average(t, f, filter_s)
    hit = np.nonzero(ff > rise)[0]
    if len(hit) == 0:
        return {"t_rise": math.nan}
    t0 = t[hit[0]]
    w = (t >= t0) & (t <= t0 + 0.15)
    plateau = (t >= t0 + 0.15) & (t <= t0 + 0.5)
    return {"t_rise": float(t0), "peak_raw": float(f[w].max()), "peak_filt": float(ff[w].max()),
            "impulse": signals.integral(t, f, t0, t0 + 0.15),
            "plateau": float(ff[plateau].mean()) if plateau.any() else math.nan,
            "t_end_after_rise": float(t[-1] - t0), "tf": t - t0, "ff": ff}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("runs", nargs="+", help="RUN_DIR[:PROBE]")
    ap.add_argument("--rise", type=float, default=8.0)
    ap.add_argument("--filter-ms", type=float, default=10.0)
    ap.add_argument("--png", type=Path)
    a = ap.parse_args()
    fs = a.filter_ms * 1e-3
    te, fe = load_exp()
    e = metrics(te, fe, a.rise, fs)
    print(f"experiment   rise at t = {e['t_rise']:.3f} s (figure time)  peak {e['peak_raw']:.1f} N "
          f"(filtered {e['peak_filt']:.1f} N)  impulse {e['impulse']:.2f} N s  plateau {e['plateau']:.1f} N")
    curves = [("experiment", e)]
    for arg in a.runs:
        run, probe = split_run(arg)
        t, f = load_run(run, probe)
        m = metrics(t, f, a.rise, fs)
        if math.isnan(m["t_rise"]):
            print(f"{run}: the force never exceeds {a.rise} N")
            continue
        s = e["tf"] >= 0
        lo, hi = 0.0, min(0.5, m["t_end_after_rise"])
        sel = s & (e["tf"] <= hi) & (e["tf"] >= lo)
        rms = float(np.sqrt(np.mean((np.interp(e["tf"][sel], m["tf"], m["ff"]) - e["ff"][sel]) ** 2)))
        name = run.name if probe == "F_column" else f"{run.name}:{probe}"
        print(f"{name:40s} rise at t = {m['t_rise']:.3f} s  peak {m['peak_raw']:.1f} N "
              f"(filtered {m['peak_filt']:.1f} N, {m['peak_filt'] / e['peak_filt']:.2f} x exp)  "
              f"impulse {m['impulse']:.2f} N s ({m['impulse'] / e['impulse']:.2f} x exp)  "
              f"plateau {m['plateau']:.1f} N ({m['plateau'] / e['plateau']:.2f} x exp)  "
              f"RMS vs exp over {lo:.1f}-{hi:.2f} s after the rise {rms:.1f} N")
        curves.append((name, m))
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(9, 4.5))
        ax.plot(te - e["t_rise"], fe, ".", color="0.6", ms=3, label="experiment (digitised)")
        for name, m in curves:
            ax.plot(m["tf"], m["ff"], lw=1.5, label=f"{name} ({a.filter_ms:g} ms average)")
        ax.set_xlim(-0.1, 0.6)
        ax.set_xlabel("time after the impact starts [s]")
        ax.set_ylabel("streamwise force on the column [N]")
        ax.set_title("Yeh & Petroff bore on a square column")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"wrote {a.png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
