#!/usr/bin/python3
"""Speed against error: sweep resolution and scheme options on four validation cases.

    perf/speed_vs_error/run.sh [--quick] [--cases dam_break,hydrostatic,taylor_green,poiseuille]
                               [--variants baseline,projection]
                               [--threads 1] [--out DIR] [--nice N] [--label TEXT]
                               [--sluice-float build/release-float/sluice]

Every run is a real `sluice run` of the case file under cases/ with --set overrides; its
error comes from its own output files (evaluate.py, same definitions as tests/validation/),
its cost is core-seconds = threads x wall time of the time loop (summary.json), with the
process's measured CPU seconds beside it. Writes OUT/speed_vs_error[_quick].csv (one row per
run) and OUT/<case>[_quick].png: error against core-seconds, log-log, the Pareto front (runs no
other run beats on both) drawn and circled. --quick is a coarse sweep (two resolutions, four
variants per case; minutes); the default sweep has more resolutions and every variant.
"""
from __future__ import annotations

import argparse
import csv
import math
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "lib"))
sys.path.insert(0, str(HERE))
import evaluate  # noqa: E402
import sluice_run as sr  # noqa: E402

# case -> file, fixed overrides (output needed by the evaluator, no needless output),
# resolutions (dx) for quick / full, end time for quick / full (None: the file's).
CASES = {
    "dam_break": {
        "file": "cases/dam_break_2d.toml",
        "fixed": {"output.snapshots": False, "probes.1.interval": 0.005},
        "dx": {"quick": [0.04, 0.02], "full": [0.02, 0.01, 0.005]},
        "end": {"quick": 0.45, "full": 0.45},  # T = 3 at t = 0.43 s (a = 0.4 m)
    },
    "hydrostatic": {
        "file": "cases/hydrostatic_2d.toml",
        "fixed": {"output.snapshots": False},
        "dx": {"quick": [0.04, 0.02], "full": [0.02, 0.01, 0.005]},
        "end": {"quick": 2.0, "full": 5.0},
    },
    "taylor_green": {
        "file": "cases/taylor_green_2d.toml",
        # snapshots every 0.05 s: the error is a fit of the decay over all of them
        "fixed": {"time.output_interval": 0.05, "output.fields": ["velocity", "mass"]},
        "dx": {"quick": [0.05, 0.025], "full": [0.05, 0.025, 0.0125, 0.00625]},
        "end": {"quick": 1.0, "full": 1.0},
    },
    "impact": {
        "file": "perf/impact/zhou_2d.toml",
        "fixed": {"output.snapshots": False},
        # The evaluator reads the 2 cm wall panel at P1, whose edges fall between wall rows
        # only for dx = 0.01 m / k (at 0.02 m they fall on rows): no coarser resolution.
        "dx": {"quick": [0.01], "full": [0.01, 0.005]},
        "end": {"quick": 0.85, "full": 0.85},  # first impact at P1: t* 2.5-3.0, t = 0.62-0.74 s
    },
    "poiseuille": {
        "file": "cases/poiseuille_2d.toml",
        "fixed": {"time.output_interval": 0.0, "output.fields": ["position", "velocity", "kind"]},
        "dx": {"quick": [1e-4, 5e-5], "full": [1e-4, 5e-5, 2.5e-5, 1.25e-5]},
        "end": {"quick": 1.0, "full": 1.0},
    },
}


def resolution_overrides(name: str, case: dict, dx: float) -> dict:
    o = {"particles.dx": dx}
    if name == "poiseuille":
        # The periodic axis needs 3 cells of one support (3 dx): keep 16 particles along x,
        # as the file has at dx = 2.5e-5 m.
        lx = 16 * dx
        h = case["domain"]["hi"][1]
        o.update({"domain.hi": [lx, h], "blocks.0.hi": [lx, case["blocks"][0]["hi"][1]],
                  "walls.tank_hi": [lx, case["walls"]["tank_hi"][1]]})
    if name == "impact":
        # Sensor P1 half a dx inside the fluid at every resolution.
        x_wall = case["walls"]["tank_hi"][0]
        o["probes.0.position"] = [x_wall - dx / 2, case["probes"][0]["position"][1]]
    return o


def projection_available(sluice: Path, case_file: Path) -> bool:
    """True once the solver accepts numerics.scheme = "projection" (the WCSPH-vs-projection
    comparison of perf/README.md, "Speed against error"): asked of `sluice info`, which
    validates without running."""
    r = subprocess.run([str(sluice), "info", str(case_file), "--set",
                        "numerics.scheme=projection"], capture_output=True, text=True)
    return r.returncode == 0


def variants(case: dict, quick: bool, projection: bool) -> list[tuple[str, dict]]:
    """(label, overrides) for the baseline and its scheme options; kernels keep the support
    at 3 dx (quintic h = dx; Wendland C2 and cubic spline h = 1.5 dx)."""
    num = case.get("numerics", {})
    kernel = num.get("kernel", "quintic")
    density = num.get("density", "continuity")
    out = [("baseline", {})]
    others = [k for k in ("wendland_c2", "quintic", "cubic_spline") if k != kernel]
    for k in others[:1] if quick else others:
        out.append((f"kernel {k}", {"numerics.kernel": k,
                                    "numerics.h_over_dx": 1.0 if k == "quintic" else 1.5}))
    if density == "continuity":
        out.append(("summation density", {"numerics.density": "summation"}))
        if num.get("delta_sph", 0.1) > 0:
            out.append(("no delta-SPH", {"numerics.delta_sph": 0.0}))
    else:
        out.append(("continuity + delta-SPH", {"numerics.density": "continuity",
                                               "numerics.delta_sph": 0.1}))
        out.append(("continuity, no delta-SPH", {"numerics.density": "continuity",
                                                 "numerics.delta_sph": 0.0}))
    # The baseline from a lattice displaced by 1e-3 dx (particles.jitter): how much of the
    # error comes from the exact symmetry of the starting lattice.
    out.append(("jitter 1e-3", {"particles.jitter": 1e-3}))
    if case.get("walls", {}).get("model") == "dummy":
        # The impact study's two wall options (perf/impact/STUDY.md): artificial viscosity on
        # wall pairs (the default before 5b5d1ac) and the Riemann solver.
        out.append(("wall artificial viscosity", {"numerics.wall_artificial_viscosity": True}))
        out.append(("riemann", {"numerics.dissipation": "riemann", "numerics.delta_sph": 0.0,
                                "numerics.artificial_viscosity": 0.0}))
    if projection:
        out.append(("projection", {"numerics.scheme": "projection"}))
    return out


def pareto(points: list[tuple[float, float]]) -> list[int]:
    """Indices of the points no other point beats on both cost and error (both minimised)."""
    front = []
    for i, (c, e) in enumerate(points):
        dominated = any((c2 <= c and e2 <= e) and (c2 < c or e2 < e)
                        for j, (c2, e2) in enumerate(points) if j != i)
        if not dominated:
            front.append(i)
    return sorted(front, key=lambda i: points[i][0])


COLUMNS = ["case", "variant", "dx", "particles", "fluid_particles", "steps", "simulated_s",
           "threads", "wall_s", "core_s", "cpu_s", "peak_rss_bytes", "error", "error_measure",
           "pareto", "status", "overrides", "precision", "git", "mode"]

# The variant run with --sluice-float's binary (the baseline's settings in single precision).
SINGLE = "single precision"


def plot(case: str, rows: list[dict], png: Path, subtitle: str) -> None:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("   (matplotlib missing: no PNG; apt-get install python3-matplotlib)")
        return
    ok = [r for r in rows if r["status"] == "ok" and r["error"] > 0 and math.isfinite(r["error"])]
    fig, ax = plt.subplots(figsize=(7.5, 5.2))
    markers = "osD^v<>pX*"
    for k, label in enumerate(dict.fromkeys(r["variant"] for r in ok)):
        pts = sorted((r for r in ok if r["variant"] == label), key=lambda r: r["core_s"])
        ax.plot([r["core_s"] for r in pts], [r["error"] for r in pts], marker=markers[k % 10],
                linestyle="-", linewidth=0.8, label=label)
        for r in pts:
            ax.annotate(f"dx={r['dx']:g}", (r["core_s"], r["error"]), fontsize=6,
                        xytext=(3, 3), textcoords="offset points")
    front = [r for r in ok if r["pareto"]]
    front.sort(key=lambda r: r["core_s"])
    if front:
        xs, ys = [front[0]["core_s"]], [front[0]["error"]]
        for r in front[1:]:
            xs += [r["core_s"], r["core_s"]]
            ys += [ys[-1], r["error"]]
        ax.plot(xs, ys, color="k", linewidth=1.2, alpha=0.6, label="Pareto front")
        ax.scatter([r["core_s"] for r in front], [r["error"] for r in front], s=160,
                   facecolors="none", edgecolors="k", linewidths=1.2)
    failed = [r for r in rows if r["status"] != "ok"]
    if failed:
        ax.text(0.01, 0.01, "failed: " + "; ".join(f"{r['variant']} dx={r['dx']:g}" for r in failed),
                transform=ax.transAxes, fontsize=6, color="crimson", va="bottom")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("core-seconds (threads x wall time of the time loop)")
    ax.set_ylabel(rows[0]["error_measure"] if rows else "error")
    ax.set_title(f"{case}: error against cost\n{subtitle}", fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="coarse sweep (minutes in total)")
    ap.add_argument("--cases", default=",".join(CASES), help="comma-separated subset")
    ap.add_argument("--threads", type=int, default=1, help="worker threads per run (default 1)")
    ap.add_argument("--out", type=Path, default=HERE / "results")
    ap.add_argument("--runs", type=Path, default=sr.ROOT / "results" / "speed_vs_error",
                    help="folder for the runs' own output (default results/speed_vs_error)")
    ap.add_argument("--sluice", type=Path, default=sr.DEFAULT_SLUICE)
    ap.add_argument("--sluice-float", type=Path, default=None,
                    help="a single-precision build (preset release-float): adds the variant "
                         "'single precision' (the baseline run with this binary)")
    ap.add_argument("--nice", type=int, default=0, help="run sluice under nice -n N")
    ap.add_argument("--variants", default="",
                    help="comma-separated subset of the variants' labels (default: all), "
                         "e.g. 'baseline,projection'")
    ap.add_argument("--label", default="",
                    help="note for the plots' subtitle, e.g. 'machine under load'")
    args = ap.parse_args()
    mode = "quick" if args.quick else "full"
    wanted = {v.strip() for v in args.variants.split(",") if v.strip()}
    chosen = [c.strip() for c in args.cases.split(",") if c.strip()]
    for c in chosen:
        if c not in CASES:
            sr.die(f"speed_vs_error: unknown case '{c}' (known: {', '.join(CASES)})")
    sluice = sr.ensure_binary(args.sluice)
    sluice_float = args.sluice_float
    if sluice_float and not sluice_float.exists():
        sr.die(f"speed_vs_error: {sluice_float} missing (cmake --preset release-float && "
               "cmake --build --preset release-float -j2)")
    args.out.mkdir(parents=True, exist_ok=True)
    suffix = "_quick" if args.quick else ""
    git = sr.git_revision()
    machine = sr.machine_description()
    print(f"== speed against error ({mode} sweep), git {git}, {args.threads} thread(s) per run")
    print(f"   machine: {machine}")

    all_rows = []
    for name in chosen:
        spec = CASES[name]
        case_file = sr.ROOT / spec["file"]
        base = sr.read_case(case_file)
        evaluator, measure = evaluate.EVALUATORS[name]
        proj_file = sr.projection_case(sluice, case_file, args.out)
        proj = projection_available(sluice, proj_file)
        print(f"\n-- {name} ({spec['file']}): {measure}"
              + ("" if proj else "; projection scheme not offered by this build, skipped"))
        rows = []
        runs = [(label, var, sluice) for label, var in variants(base, args.quick, proj)]
        if wanted:
            runs = [r for r in runs if r[0] in wanted]
        if sluice_float:
            runs.append((SINGLE, {}, sluice_float))
        for label, var, binary in runs:
            for dx in spec["dx"][mode]:
                overrides = dict(spec["fixed"])
                overrides["time.end_time"] = spec["end"][mode]
                overrides.update(resolution_overrides(name, base, dx))
                overrides.update(var)
                tag = f"{name}_{label.replace(' ', '_').replace(',', '')}_dx{dx:g}"
                run = sr.run_sluice(binary, proj_file if label == "projection" else case_file,
                                    args.runs / tag, args.threads, overrides,
                                    nice=args.nice, echo=False)
                row = {"case": name, "variant": label, "dx": dx, "threads": args.threads,
                       "error_measure": measure, "git": git, "mode": mode,
                       "overrides": " ".join(f"{k}={sr.toml_value(v)}" for k, v in var.items()),
                       "cpu_s": run.cpu_s, "peak_rss_bytes": run.peak_rss_bytes, "pareto": False}
                if run.ok:
                    s = run.summary
                    row.update(precision=s.get("precision", "double"), particles=s["particles"], fluid_particles=s["fluid_particles"],
                               steps=s["steps"], simulated_s=s["simulated_time"],
                               wall_s=s["wall_seconds"], core_s=args.threads * s["wall_seconds"])
                    try:
                        row["error"] = evaluator(run.out_dir, sr.read_case(case_file, overrides))
                        row["status"] = "ok" if math.isfinite(row["error"]) else "error not finite"
                    except (OSError, KeyError, IndexError, ValueError) as e:
                        row.update(error=float("nan"), status=f"evaluation failed: {e}")
                else:
                    row.update(error=float("nan"), wall_s=float("nan"), core_s=float("nan"),
                               status=f"run failed (exit {run.returncode})")
                rows.append(row)
                print(f"   {label:<26} dx = {dx:<8g} "
                      + (f"{row['core_s']:8.2f} core-s  error {100 * row['error']:8.3f} %"
                         if row["status"] == "ok" else row["status"]
                         + (f": {run.stderr_tail.splitlines()[-1]}" if run.stderr_tail else "")),
                      flush=True)
        ok = [r for r in rows if r["status"] == "ok"]
        for i in pareto([(r["core_s"], r["error"]) for r in ok]):
            ok[i]["pareto"] = True
        front = sorted((r for r in ok if r["pareto"]), key=lambda r: r["core_s"])
        print("   Pareto front: " + ", ".join(
            f"{r['variant']} dx={r['dx']:g} ({r['core_s']:.2f} core-s, {100 * r['error']:.2f} %)"
            for r in front))
        subtitle = (f"{mode} sweep, {args.threads} thread(s)/run, git {git}"
                    + (f"; {args.label}" if args.label else ""))
        png = args.out / f"{name}{suffix}.png"
        plot(name, rows, png, subtitle)
        print(f"   plot: {png}")
        all_rows += rows

    csv_path = args.out / f"speed_vs_error{suffix}.csv"
    with open(csv_path, "w", newline="") as f:
        f.write(f"# sluice speed against error, {mode} sweep, git {git}; machine: {machine}"
                + (f"; {args.label}" if args.label else "") + "\n")
        w = csv.DictWriter(f, fieldnames=COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in all_rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})
    print(f"\n   table: {csv_path}")
    return 0 if all(r["status"] == "ok" for r in all_rows) else 1


if __name__ == "__main__":
    sys.exit(main())
