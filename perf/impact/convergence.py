"""Convergence of the first-impact figures between sound speeds and between resolutions:
the relative change of the filtered peak (perf/impact/README.md's criterion: less than 15 % from c0 = 20
to 40 sqrt(gH) and from H/60 to H/120), of the longer average's peak and of the impulse; an
ensemble of runs (study.py --jitters) enters by its medians."""
from __future__ import annotations

import dataclasses
import math
import statistics
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from analyse import ProbeResult

CRITERION = 0.15  # perf/impact/README.md: the filtered peak changes by less than 15 %


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
