#!/usr/bin/python3
"""`sluice info --ranks R`'s memory estimate per rank against the measured peak resident memory
of every rank of a run (perf/memory/README.md, "Memory estimate").

For each case and rank count: the estimate (its terms as `sluice info` prints them), then a run
as peak_rss.py makes it (each rank under /usr/bin/time, snapshots at the start and the end, a
checkpoint every 2 steps, 1 thread per rank) and the ratio of the estimate to the largest
rank's peak.

    perf/memory/estimate_vs_peak.py                       # the cases of the README's table
    perf/memory/estimate_vs_peak.py --case cases/dam_break_3d.toml --ranks 1 4 \\
        --set particles.dx=0.01
"""
import argparse
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import peak_rss  # noqa: E402

ROOT = peak_rss.ROOT
UNITS = {"B": 1, "KiB": 2**10, "MiB": 2**20, "GiB": 2**30, "TiB": 2**40}
# (case, --set overrides, end time): the README's table.
DEFAULT_RUNS = [
    ("cases/dam_break_2d.toml", [], "2e-3"),
    ("cases/dam_break_3d.toml", [], "2e-3"),
    ("perf/memory/sparse_domain_3d.toml", [], "2e-3"),
    ("perf/cases/dam_break_2d_peer_200k.toml", [], "1e-4"),
    ("cases/dam_break_3d.toml", ["particles.dx=0.008"], "2e-4"),
]


def mib(text):
    value, unit = text.split()
    return float(value) * UNITS[unit] / 2**20


def estimate(exe, case, ranks, sets):
    args = [exe, "info", case, "--ranks", str(ranks), "--max-memory", "1TiB"]
    for s in sets:
        args += ["--set", s]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    total = re.search(r"^memory\s+~([0-9.]+ \w+) per rank", out, re.M)
    terms = dict((k, mib(v)) for k, v in re.findall(
        r"^  (process|particles|halo|totals|grid)\s+([0-9.]+ \w+)", out, re.M))
    return mib(total.group(1)), terms


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", default=str(ROOT / "build/release/sluice"))
    ap.add_argument("--case", help="one case instead of the table's")
    ap.add_argument("--set", action="append", default=[], help="case override (with --case)")
    ap.add_argument("--end-time", default="2e-3")
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 4])
    ap.add_argument("--out", default="/tmp/sluice_estimate_vs_peak")
    a = ap.parse_args()
    runs = [(a.case, a.set, a.end_time)] if a.case else DEFAULT_RUNS
    version = subprocess.run([a.exe, "--version"], capture_output=True, text=True).stdout.strip()
    print(f"{version}; 1 thread per rank; MiB")
    print("| case | ranks | estimate (process + particles + halo + totals + grid) | "
          "measured peak, ranks 0.. | estimate / largest peak |")
    print("|---|---|---|---|---|")
    for k, (case, sets, end_time) in enumerate(runs):
        for ranks in a.ranks:
            est, terms = estimate(a.exe, str(ROOT / case), ranks, sets)
            out = pathlib.Path(a.out) / f"{k}_{ranks}"
            peaks, _ = peak_rss.run(a.exe, ROOT / case, ranks, out, end_time, 2, 1, sets)
            worst = max(peaks.values())
            parts = " + ".join(f"{terms.get(t, 0):.1f}"
                               for t in ["process", "particles", "halo", "totals", "grid"])
            shown = case + "".join(f" {s}" for s in sets)
            print(f"| {shown} | {ranks} | {est:.1f} ({parts}) | "
                  f"{', '.join(f'{peaks[r]:.1f}' for r in sorted(peaks))} | "
                  f"{est / worst:.2f} |", flush=True)


if __name__ == "__main__":
    main()
