#!/usr/bin/python3
"""Peak resident memory of every rank of a run, at several rank counts
(perf/memory/README.md).

Runs `sluice run CASE` once per rank count, each rank under `/usr/bin/time -f %M` (its peak
resident set, KiB, written to a file per rank), with snapshots and checkpoints, and prints per
rank the peak and its ratio to the first rank count's peak. Where the binary writes them (from
the parallel-HDF5 branch on), it also prints the rank log's `memory:` lines, VmHWM (peak) and
VmRSS (now) after the initial state (from the distributed start on, each rank builds only its
own particles), after start-up (before the time loop), after the time loop (snapshots and
checkpoints included) and at the end (the run's totals), so the share of the peak that each
part sets is read off directly.

    perf/memory/peak_rss.py                                   # 1 and 4 ranks, defaults below
    perf/memory/peak_rss.py --exe /tmp/sluice_main --ranks 1 4 --out /tmp/mem_main

Defaults: perf/cases/dam_break_2d_peer_1m.toml (999,698 fluid particles), end time 2e-5 s
(5 steps), snapshots of the initial and the final state (output_interval = 0, snapshots on)
and a checkpoint every 2 steps, 1 worker thread per rank. The target: every rank's peak at 4
ranks <= 0.40 x the 1-rank peak.
"""
import argparse
import os
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def run(exe, case, ranks, out, end_time, every_steps, threads, extra):
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    rss_dir = out / "rss"
    rss_dir.mkdir()
    args = [str(exe), "run", str(case), "--out", str(out / "run"), "--threads", str(threads),
            "--quiet", "--set", f"time.end_time={end_time}", "--set", "time.output_interval=0",
            "--set", "output.snapshots=true", "--set", f"checkpoint.every_steps={every_steps}"]
    for s in extra:
        args += ["--set", s]
    # Each rank runs under its own /usr/bin/time, which writes its peak (KiB) to rss/<rank>.
    rank_var = "${OMPI_COMM_WORLD_RANK:-0}"
    wrapped = ["bash", "-c",
               f'exec /usr/bin/time -f %M -o "{rss_dir}/{rank_var}" "$@"', "peak_rss"] + args
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    cmd = wrapped if ranks == 1 else ["mpirun", "--oversubscribe", "-np", str(ranks)] + wrapped
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.exit(f"run on {ranks} rank(s) failed ({proc.returncode}):\n{proc.stderr[-3000:]}")
    peaks = {}
    for f in rss_dir.iterdir():
        peaks[int(f.name)] = int(f.read_text().split()[-1]) / 1024.0  # MiB
    logs = {}
    for r in peaks:
        log = out / "run" / "logs" / f"rank_{r}.log"
        lines = log.read_text().splitlines() if log.exists() else []
        marks = {}
        for line in lines:
            m = re.search(r"memory: peak resident ([0-9.]+) MiB (.*) "
                          r"\(resident now ([0-9.]+) MiB\)$", line)
            if m:
                marks[m.group(2)] = (float(m.group(1)), float(m.group(3)))
        logs[r] = marks
    return peaks, logs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--exe", default=str(ROOT / "build/release/sluice"))
    ap.add_argument("--case", default=str(ROOT / "perf/cases/dam_break_2d_peer_1m.toml"))
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 4])
    ap.add_argument("--end-time", default="2e-5")
    ap.add_argument("--checkpoint-every-steps", type=int, default=2)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--set", action="append", default=[], help="extra case override")
    ap.add_argument("--out", default="/tmp/sluice_peak_rss")
    a = ap.parse_args()

    version = subprocess.run([a.exe, "--version"], capture_output=True, text=True).stdout.strip()
    print(f"{version}; case {a.case}; end time {a.end_time} s; snapshots at the start and "
          f"the end; checkpoint every {a.checkpoint_every_steps} steps; {a.threads} thread(s) "
          "per rank")
    base = None
    for ranks in a.ranks:
        peaks, logs = run(a.exe, a.case, ranks, pathlib.Path(a.out) / f"{ranks}ranks", a.end_time,
                          a.checkpoint_every_steps, a.threads, a.set)
        if base is None:
            base = max(peaks.values())
        for r in sorted(peaks):
            marks = logs[r]
            extra = ""
            if marks:
                init = marks["after the initial state"]
                start = marks["after start-up"]
                loop = marks["after the time loop"]
                end = marks["at the end"]
                extra = (f"\n    VmHWM (VmRSS) in MiB: after the initial state {init[0]:.0f} "
                         f"({init[1]:.0f}), after start-up {start[0]:.0f} ({start[1]:.0f}), "
                         f"after the time loop {loop[0]:.0f} ({loop[1]:.0f}), at the end "
                         f"{end[0]:.0f} ({end[1]:.0f}); the peak after start-up is "
                         f"{100 * start[0] / end[0]:.0f} % of the run's")
            print(f"{ranks} rank(s), rank {r}: peak {peaks[r]:.0f} MiB = "
                  f"{peaks[r] / base:.3f} x the {a.ranks[0]}-rank peak{extra}")


if __name__ == "__main__":
    main()
