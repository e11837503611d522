"""PNGs of the impact study (called by analyse.py; needs matplotlib).

* impact_P1.png: p*(t*) at the P1 probe (y = 0.16 m) against Buchner's record, one line per
  run (raw thin, 1 ms moving average thick), one row per variant; left the whole record,
  right the first impact.
* impact_peaks.png: filtered first-impact peak against c0 (one line per dx) and against dx
  (one line per c0), log axes, one row per probe; the experimental peak dashed at P1/P2.
* impact_lowest.png: the lowest probe's signals, as impact_P1.png.
"""
from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter, NullLocator  # noqa: E402

LINESTYLES = ["-", "--", ":", "-."]
MARKERS = ["o", "s", "^", "D", "v", "P"]


def _run_colours(results) -> dict:
    """One colour per (dx, c0): hue by dx, shade by c0."""
    dxs = sorted({r.run.dx for r in results}, reverse=True)
    cs = sorted({r.run.c0_factor for r in results})
    maps = [plt.cm.Blues, plt.cm.Oranges, plt.cm.Greens, plt.cm.Purples, plt.cm.Reds, plt.cm.Greys]
    out = {}
    for i, dx in enumerate(dxs):
        cmap = maps[i % len(maps)]
        for j, c in enumerate(cs):
            shade = 0.4 + 0.6 * (j / max(1, len(cs) - 1)) if len(cs) > 1 else 0.8
            out[(dx, c)] = cmap(shade)
    return out


def _label(r) -> str:
    return f"H/{r.run.scales.H / r.run.dx:.0f}, c0={r.run.c0_factor:g}√gH"


def _signals(results, pick, out: Path, title: str, fname: str) -> Path | None:
    variants = sorted({r.run.variant for r in results})
    chosen = {v: [r for r in results if r.run.variant == v and pick(r)] for v in variants}
    chosen = {v: rs for v, rs in chosen.items() if rs}
    if not chosen:
        return None
    colours = _run_colours(results)
    fig, axes = plt.subplots(len(chosen), 2, figsize=(14, 5.2 * len(chosen)), squeeze=False,
                             gridspec_kw={"width_ratios": [1.6, 1]})
    for row, (v, rs) in enumerate(chosen.items()):
        sc = rs[0].run.scales
        t_end = max(float(r.t[-1]) / sc.t for r in rs)
        contacts = [r.metrics["t_contact_star"] for r in rs
                    if math.isfinite(r.metrics["t_contact_star"])]
        exp = rs[0].exp
        if exp:
            contacts.append(exp[0]["t_contact_star"])
        tc = min(contacts) if contacts else 0.0
        ymin, ymax = 0.0, 0.0
        for col, ax in enumerate(axes[row]):
            if col == 0:
                lo, hi = max(0.0, tc - 0.5), max(t_end, tc + 0.2)
            else:
                lo, hi = tc - 0.1, min(tc + 0.8, max(t_end, tc + 0.2))
            for r in rs:
                c = colours[(r.run.dx, r.run.c0_factor)]
                ts, p = r.t / sc.t, np.where(np.isfinite(r.p), r.p, 0.0) / sc.p
                m = (ts >= lo) & (ts <= hi)
                ax.plot(ts[m], p[m], color=c, lw=0.4, alpha=0.45)
                ax.plot(ts[m], r.pf[m] / sc.p, color=c, lw=1.8, label=_label(r) + " (1 ms avg)")
                if col == 1 and m.any():
                    ymin = min(ymin, float(np.min(r.pf[m] / sc.p)))
                    ymax = max(ymax, float(np.max(r.pf[m] / sc.p)))
            for k, e in enumerate(exp):
                me = (e["t_star"] >= lo) & (e["t_star"] <= hi)
                ax.plot(e["t_star"][me], e["p_star"][me], color="k",
                        ls="-" if k == 0 else "none", marker="o" if k == 0 else "x", ms=3.5,
                        lw=1.0, label=e["label"])
                if col == 1 and me.any():
                    ymax = max(ymax, float(np.max(e["p_star"][me])))
            ax.axhline(0, color="0.6", lw=0.5)
            ax.set_xlim(lo, hi)
            ax.set_xlabel("t* = t √(g/H)")
            ax.set_ylabel("p* = p / (ρ g H)")
            ax.grid(alpha=0.3)
            if col == 0:
                ax.set_title(f"{title} — variant {v}")
                # the raw signal's spikes would hide everything: clip to the filtered range
                fmax = max(float(np.max(r.pf / sc.p)) for r in rs)
                fmin = min(float(np.min(r.pf / sc.p)) for r in rs)
                if exp:
                    fmax = max(fmax, float(np.max(exp[0]["p_star"])))
                ax.set_ylim(min(-0.3, 1.3 * fmin), 1.4 * fmax + 0.1)
            else:
                ax.set_title("first impact (thin: raw, thick: 1 ms average)")
                ax.set_ylim(min(-0.2, 1.3 * ymin), 1.35 * ymax + 0.1)
        axes[row][0].legend(fontsize=7, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.16),
                            frameon=False)
    fig.tight_layout()
    path = out / fname
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def plot_p1(results, out: Path) -> Path | None:
    return _signals(results, lambda r: abs(r.y - 0.16) < 1e-3, out,
                    "P1 (y = 0.16 m) against Buchner (2002)", "impact_P1.png")


def plot_lowest(results, out: Path) -> Path | None:
    if not results:
        return None
    ylow = min(r.y for r in results)
    return _signals(results, lambda r: abs(r.y - ylow) < 1e-9, out,
                    f"lowest probe (y = {ylow:g} m)", "impact_lowest.png")


def plot_peaks(results, out: Path) -> Path | None:
    probes = sorted({(r.y, r.probe) for r in results})
    if not probes:
        return None
    variants = sorted({r.run.variant for r in results})
    fig, axes = plt.subplots(len(probes), 2, figsize=(11, 3.0 * len(probes)), squeeze=False)
    for row, (y, name) in enumerate(probes):
        rs = [r for r in results if r.probe == name and abs(r.y - y) < 1e-12]
        for col, (xkey, lkey) in enumerate((("c0_factor", "dx"), ("dx", "c0_factor"))):
            ax = axes[row][col]
            for iv, v in enumerate(variants):
                rv = [r for r in rs if r.run.variant == v]
                for il, lval in enumerate(sorted({getattr(r.run, lkey) for r in rv})):
                    pts = sorted((getattr(r.run, xkey), r.metrics["peak_filt_star"])
                                 for r in rv if getattr(r.run, lkey) == lval)
                    pts = [(x, p) for x, p in pts if math.isfinite(p) and p > 0]
                    if not pts:
                        continue
                    lab = (f"H/{rv[0].run.scales.H / lval:.0f}" if lkey == "dx" else f"c0={lval:g}√gH")
                    if len(variants) > 1:
                        lab = f"{v}: {lab}"
                    ax.plot([x for x, _ in pts], [p for _, p in pts],
                            ls=LINESTYLES[iv % len(LINESTYLES)], marker=MARKERS[il % len(MARKERS)],
                            color=f"C{il}", label=lab)
            if rs and rs[0].exp:
                pe = rs[0].exp[0]["peak_filt_star"]
                ax.axhline(pe, color="k", ls="--", lw=1,
                           label=f"experiment {pe:.2f} (Trixi digitisation)")
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.yaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0)))
            ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
            ax.yaxis.set_minor_locator(LogLocator(base=10, subs=np.arange(1, 10)))
            ax.yaxis.set_minor_formatter(NullFormatter())
            ax.grid(alpha=0.3, which="both")
            ax.set_ylabel("filtered peak p*")
            if xkey == "c0_factor":
                ax.set_xlabel("c0 / √(gH)")
                ax.set_title(f"{name} (y = {y:g} m): peak vs c0")
            else:
                ax.set_xlabel("dx [m]")
                ax.set_title(f"{name} (y = {y:g} m): peak vs dx")
            xs = sorted({getattr(r.run, xkey) for r in rs})
            if xs:
                ax.set_xticks(xs)
                ax.set_xticklabels([f"{x:g}" for x in xs])
                ax.xaxis.set_minor_locator(NullLocator())
                ax.set_xlim(xs[0] / 1.3, xs[-1] * 1.3)
            if ax.get_legend_handles_labels()[0]:
                ax.legend(fontsize=7)
    fig.tight_layout()
    path = out / "impact_peaks.png"
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def all_plots(results, out: Path, window_star: float = 0.5) -> list[Path]:
    out.mkdir(parents=True, exist_ok=True)
    paths = [plot_p1(results, out), plot_peaks(results, out), plot_lowest(results, out)]
    return [p for p in paths if p is not None]
