#!/usr/bin/python3
"""Discretisation uncertainty of the wall loads from three resolutions, each an ensemble.

The study's form, on analyse.py's tables (variant, c0, H/dx columns); for runs of a case of
your own, `scripts/loads gci` does the same from the run folders (scripts/sluice_loads/gci.py
is the arithmetic of both).

    perf/impact/grid_convergence.py CSV [--wall-force CSV] [--c0 20] [--variant default]
                                    [--out PREFIX]

CSV is an analyse.py table (impact_convergence.csv: one row per run and probe) holding runs
at three resolutions H/N, H/2N, H/4N at one sound speed; --wall-force adds analyse.py's
impact_wall_force.csv (the whole downstream wall). Each resolution enters by the median of
its runs (study.py --jitters), with the range of its runs beside it.

For each sensor and each figure (the 1 ms filtered first-impact peak, the peak after the
10 ms average, the impulse over the first-impact window) it follows Celik et al. (2008), "Procedure
for estimation and reporting of uncertainty due to discretization in CFD applications",
J. Fluids Eng. 130, 078001, with the constant refinement ratio r = 2: with f1, f2, f3 the
fine, middle and coarse medians, e21 = f2 - f1 and e32 = f3 - f2,
  - the apparent order p = |ln|e32 / e21|| / ln 2 (their eq. 3 with r constant);
  - e32 / e21 < 0 is oscillatory convergence: no order, no extrapolation;
  - both |e21| and |e32| within 1 % of f1 is "flat": converged, and too little change to read
    an order from;
  - the extrapolated value f_ext = (2^p f1 - f2) / (2^p - 1) (their eq. 4);
  - the fine-grid convergence index GCI = 1.25 |e21 / f1| / (2^p - 1) (their eq. 5), with p
    taken as at most 2, the formal order of the kernel approximation, since a larger apparent
    order from three noisy medians would claim more than the scheme can give (Roache 1998,
    "Verification and validation in computational science and engineering", ch. 5).
Where the change grows with refinement ("diverging", not yet asymptotic) the order is printed
negative and nothing is extrapolated. Beside it: the change per doubling, (fine - coarse) / fine
as analyse.py gives it (perf/impact/README.md's criterion: less than 15 %), and whether the
last change is larger than the fine ensemble's
half-range, the run-to-run scatter below which a change is not resolved.
"""
from __future__ import annotations

import argparse
import csv
import math
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import loads_package  # noqa: E402, F401  (scripts/ on the path)
from convergence import CRITERION  # noqa: E402
from sluice_loads import gci  # noqa: E402
from sluice_loads.tables import format_cell as fmt, write_csv  # noqa: E402

FORMAL_ORDER = 2.0
SAFETY = 1.25  # Celik et al. (2008): the factor for three grids
FLAT = 0.01    # both changes within 1 % of the fine value: converged, no order to compute
FIGURES = [("1 ms peak", "peak_filt_star", "peak_filt"),
           ("10 ms peak", "peak_smooth_star", "peak_smooth"),
           ("impulse", "impulse_star", "impulse_star")]


def read_rows(path: Path) -> list[dict]:
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def ensembles(rows: list[dict], key: str, c0: float, variant: str,
              name_of=lambda r: r["probe"]) -> dict[str, dict[int, list[float]]]:
    """{sensor: {H/dx: [value of each run]}} at this c0 and variant. NaN values are dropped,
    and so are runs that end inside the sensor's first-impact window (analyse.py's
    window_complete False): their peak and impulse are of a cut window."""
    out: dict[str, dict[int, list[float]]] = {}
    for r in rows:
        if r["variant"] != variant or abs(float(r["c0_factor"]) - c0) > 1e-6:
            continue
        if r.get("window_complete") == "False":
            continue
        v = float(r[key])
        if not math.isfinite(v):
            continue
        out.setdefault(name_of(r), {}).setdefault(round(float(r["H_over_dx"])), []).append(v)
    return out


def celik(f1: float, f2: float, f3: float) -> dict:
    """Celik et al. (2008) for r = 2 (scripts/sluice_loads/gci.py): apparent order, extrapolated
    value and the fine-grid convergence index (order capped at FORMAL_ORDER), or the kind of
    failure."""
    res = gci.three_grid(f1, f2, f3, 2.0, 2.0, SAFETY, FORMAL_ORDER, FLAT)
    return {k: res[k] for k in ("order", "f_ext", "gci_fine", "kind")}


def table(groups: dict[str, dict[int, list[float]]], figure: str) -> list[dict]:
    rows = []
    for sensor, by_res in groups.items():
        levels = sorted(by_res)  # coarse -> fine (H/dx ascending)
        if len(levels) < 3:
            continue
        n3, n2, n1 = levels[-3:]
        if not (n2 == 2 * n3 and n1 == 2 * n2):
            continue
        f3, f2, f1 = (statistics.median(by_res[n]) for n in (n3, n2, n1))
        fine = by_res[n1]
        half_range = 0.5 * (max(fine) - min(fine))
        c = celik(f1, f2, f3)
        rows.append({"sensor": sensor, "figure": figure, "H_coarse": n3, "H_mid": n2,
                     "H_fine": n1, "runs": "/".join(str(len(by_res[n])) for n in (n3, n2, n1)),
                     "coarse": f3, "mid": f2, "fine": f1, "fine_min": min(fine),
                     "fine_max": max(fine),
                     "change_mid": (f2 - f3) / f2 if f2 else math.nan,
                     "change_fine": (f1 - f2) / f1 if f1 else math.nan,
                     "resolved": abs(f1 - f2) > half_range, **c})
    return rows


def format_table(rows: list[dict]) -> list[str]:
    lines = [f"{'sensor':16s} {'figure':10s} {'runs':>7s} {'coarse':>7s} {'mid':>7s} {'fine':>7s} "
             f"{'fine range':>15s} {'step1 %':>8s} {'step2 %':>8s} {'>noise':>6s} {'order':>6s} "
             f"{'f_ext':>7s} {'GCI %':>6s}  kind"]
    for r in rows:
        lines.append(
            f"{r['sensor'][:16]:16s} {r['figure']:10s} {r['runs']:>7s} {r['coarse']:7.3f} "
            f"{r['mid']:7.3f} {r['fine']:7.3f} {r['fine_min']:7.3f}-{r['fine_max']:<7.3f}"
            f"{fmt(100 * r['change_mid'], '+8.1f')} {fmt(100 * r['change_fine'], '+8.1f')} "
            f"{'yes' if r['resolved'] else 'no':>6s} {fmt(r['order'], '6.2f')} "
            f"{fmt(r['f_ext'], '7.3f')} {fmt(100 * r['gci_fine'], '6.1f')}  {r['kind']}")
    return lines


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", type=Path, help="analyse.py's impact_convergence.csv")
    ap.add_argument("--wall-force", type=Path, help="analyse.py's impact_wall_force.csv")
    ap.add_argument("--c0", type=float, default=20.0, help="c0 / sqrt(gH) (default 20)")
    ap.add_argument("--variant", default="default")
    ap.add_argument("--out", type=Path, help="writes PREFIX.csv and PREFIX.txt")
    a = ap.parse_args(argv)

    probe_rows = read_rows(a.csv)
    force_rows = read_rows(a.wall_force) if a.wall_force else []
    rows = []
    for figure, key, force_key in FIGURES:
        groups = ensembles(probe_rows, key, a.c0, a.variant)
        if force_rows:
            groups.update(ensembles(force_rows, force_key, a.c0, a.variant,
                                    name_of=lambda r: "whole wall"))
        rows.extend(table(groups, figure))
    if not rows:
        print("no sensor has three resolutions H/N, H/2N, H/4N at this c0 and variant",
              file=sys.stderr)
        return 1
    order = {s: i for i, s in enumerate(dict.fromkeys(r["sensor"] for r in rows))}
    rows.sort(key=lambda r: (order[r["sensor"]], [f[0] for f in FIGURES].index(r["figure"])))
    lines = [f"# perf/impact/grid_convergence.py {' '.join(argv if argv else sys.argv[1:])}",
             f"# medians of each resolution's runs, c0 = {a.c0:g} sqrt(gH), variant {a.variant};"
             " peaks in rho g H, impulse in rho g H sqrt(H/g); the whole wall in rho g H^2/2 "
             "(and that times sqrt(H/g))",
             "# step1 / step2: (fine - coarse) / fine from coarse to mid and from mid to fine "
             f"(criterion: |change| < {100 * CRITERION:g} %); >noise: |fine - mid| above half the "
             "fine runs' range; order, f_ext, GCI: Celik et al. (2008), GCI with the order "
             f"capped at {FORMAL_ORDER:g}"]
    text = "\n".join(lines + format_table(rows)) + "\n"
    print(text, end="")
    if a.out:
        a.out.parent.mkdir(parents=True, exist_ok=True)
        a.out.with_suffix(".txt").write_text(text)
        write_csv(a.out.with_suffix(".csv"), rows, list(rows[0].keys()))
        print(f"wrote {a.out.with_suffix('.txt')} and {a.out.with_suffix('.csv')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
