"""Statistics of one figure over the runs of an ensemble: runs of one case that differ only by
`particles.jitter`, whose first-impact peaks scatter by up to 2x (docs/IMPACT_LOADS.md,
"Running an impact study"). Median, not mean: four runs, one of which may catch a spike."""
from __future__ import annotations

import math
import statistics


def summary(values: list[float]) -> dict:
    """n, median, min, max and the spread (max - min) in % of |median| of the finite values
    (NaN figures, e.g. a probe that never reached contact, are left out and not counted)."""
    v = [x for x in values if isinstance(x, (int, float)) and math.isfinite(x)]
    if not v:
        return {"n": 0, "median": math.nan, "min": math.nan, "max": math.nan,
                "spread_pct": math.nan}
    med = statistics.median(v)
    spread = 100.0 * (max(v) - min(v)) / abs(med) if med else math.nan
    return {"n": len(v), "median": med, "min": min(v), "max": max(v), "spread_pct": spread}


def half_range(values: list[float]) -> float:
    """Half the range of the finite values: the run-to-run scatter a change must exceed to be
    resolved; NaN with fewer than two."""
    v = [x for x in values if math.isfinite(x)]
    return 0.5 * (max(v) - min(v)) if len(v) >= 2 else math.nan
