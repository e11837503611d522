#!/usr/bin/env python3
"""Wall panels of the Zhou/Buchner case (perf/impact/zhou_2d.toml: force probes on 2 cm high
strips of the downstream wall, N per metre of width): the mean pressure each strip carries,
Fx / 0.02 m, with the first-impact figures of analyse.py (contact, raw and 1 ms filtered peak,
time below -0.5 rho g H), beside the point probe at the same height. A panel reads the
momentum equation's fluid-wall pair forces, so a spray particle adds only its own small force
and a wall that may push but never pull reads no suction; a point probe reads the Shepard
average of the fluid pressure around it. Usage: panels.py RUN_DIR [RUN_DIR ...] [--median]
(--median: the median and range over the runs, for an ensemble)."""
from __future__ import annotations

import statistics
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import experiment  # noqa: E402
import metrics  # noqa: E402
from sluice_loads import impact  # noqa: E402  (metrics puts scripts/ on the path)

# m: each panel holds two rows of wall particles at dx = 0.01 m (four at 0.005 m). Valid for
# dx = 0.01 m / k only: at dx = 0.02 m the strips' edges fall on wall rows.
PANEL_HEIGHT = 0.02
PROBES = [("P1 (0.15-0.17 m) panel", "P1_panel"), ("P1 9 mm sensor (force)", "P1_area"),
          ("P1 9 mm sensor (interp.)", "P1_area_interp"), ("P1 point", "P1"),
          ("80 mm panel", "y080mm_panel"), ("80 mm sensor (force)", "y080mm_area"),
          ("80 mm point", "y080mm"),
          ("30 mm panel", "y030mm_panel"), ("30 mm sensor (force)", "y030mm_area"),
          ("30 mm point", "y030mm"),
          ("0-20 mm panel", "y010mm_panel"), ("4.5 mm sensor (force)", "y003mm_area"),
          ("3 mm point", "y003mm")]


def figures(run: Path, probe: str, sc: impact.Scales) -> dict | None:
    path = run / "probes" / f"{probe}.csv"
    if not path.exists():  # a run from before the probe was added to the case
        return None
    d = np.genfromtxt(path, delimiter=",", names=True)
    p = d["Fx_N"] / PANEL_HEIGHT if probe.endswith("_panel") else d["pressure_Pa"]
    return impact.impact_metrics(d["time_s"], p, sc)


def main() -> int:
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    median = "--median" in sys.argv
    sc = metrics.zhou_scales()
    rows = {name: [figures(Path(r), probe, sc) for r in args] for name, probe in PROBES}
    for exp in experiment.experiment_metrics(0.16, sc):
        print(f"{exp['label']:40s} filtered peak {exp['peak_filt_star']:.2f} rho g H, "
              f"impulse {exp['impulse_star']:.3f} rho g H sqrt(H/g)")
    for name, ms in rows.items():
        if any(m is None for m in ms):
            print(f"{name:24s} (not in every run)")
            continue
        if median:
            pk = [m["peak_filt_star"] for m in ms]
            neg = [m["neg_longest_ms"] for m in ms]
            print(f"{name:24s} filtered peak median {statistics.median(pk):6.2f} "
                  f"({min(pk):.2f}-{max(pk):.2f}) rho g H; longest below -0.5 rho g H median "
                  f"{statistics.median(neg):4.1f} ms (max {max(neg):.1f}); n = {len(ms)}")
        else:
            for r, m in zip(args, ms):
                print(f"{r:30s} {name:26s} contact t* {m['t_contact_star']:.2f}  peak raw "
                      f"{m['peak_raw_star']:6.2f}  filtered {m['peak_filt_star']:6.2f}  impulse "
                      f"{m['impulse_star']:6.3f}  longest below -0.5: "
                      f"{m['neg_longest_ms']:4.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
