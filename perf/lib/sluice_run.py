"""Running `sluice` from the benchmark scripts: every perf/ Python script that starts a run
(perf/throughput, perf/speed_vs_error, perf/impact, perf/stability, perf/projection) starts
it through run_sluice().

One run = one `sluice run` process. Its peak resident memory comes from the kernel's
accounting of that very child (os.wait4 -> ru_maxrss), so no external `time` tool is needed
and runs do not contaminate each other's figures. Needs only the Python standard library.
"""
from __future__ import annotations

import json
import math
import os
import re
import shutil
import subprocess
import sys
import time
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_SLUICE = ROOT / "build" / "release" / "sluice"


@dataclass
class Run:
    """What one finished `sluice run` gives back."""

    case: str
    out_dir: Path
    returncode: int
    process_wall_s: float  # whole process: start-up, particle generation, time loop, output
    cpu_s: float  # user + system time of the process (all its threads)
    peak_rss_bytes: int
    summary: dict = field(default_factory=dict)  # summary.json ({} if the run failed)
    stderr_tail: str = ""

    @property
    def ok(self) -> bool:
        return self.returncode == 0 and bool(self.summary)


def ensure_binary(sluice: Path) -> Path:
    """Builds the Release binary if it is missing (as perf/strong_scaling/run.sh does)."""
    if not sluice.exists():
        print(f"== {sluice} missing: building it (cmake --preset release)", flush=True)
        subprocess.run(["cmake", "--preset", "release"], cwd=ROOT, check=True)
        subprocess.run(["cmake", "--build", "--preset", "release", "-j2", "--target", "sluice"],
                       cwd=ROOT, check=True)
    return sluice


def read_case(path: Path, overrides: dict[str, object] | None = None) -> dict:
    """The case file as a dict, with dotted-key overrides applied (only plain table keys)."""
    with open(path, "rb") as f:
        case = tomllib.load(f)
    for key, value in (overrides or {}).items():
        node = case
        parts = key.split(".")
        for p in parts[:-1]:
            node = node[int(p)] if isinstance(node, list) else node.setdefault(p, {})
        node[parts[-1]] = value
    return case


def acoustic_dt(case: dict) -> float:
    """The solver's time step at rest: cfl * h / c0 (or the case's fixed dt)."""
    num = case.get("numerics", {})
    if "dt" in num:
        return float(num["dt"])
    h = float(num.get("h_over_dx", 1.0)) * float(case["particles"]["dx"])
    return float(num.get("cfl", 0.25)) * h / float(case["fluid"]["sound_speed"])


def toml_value(v: object) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, str):
        return f'"{v}"'
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return str(v)


def run_sluice(sluice: Path, case: Path, out_dir: Path, threads: int,
               overrides: dict[str, object] | None = None, nice: int = 0,
               echo: bool = True, sets: list[str] | None = None) -> Run:
    """Runs `sluice run CASE --threads T --out DIR -q --set k=v ...` and waits for it.

    `overrides` are Python values (written as TOML); `sets` are "key=value" strings already in
    TOML (as a user types them after --set), passed on verbatim after the overrides."""
    if out_dir.exists():
        shutil.rmtree(out_dir)
    cmd = [str(sluice), "run", str(case), "--threads", str(threads), "--out", str(out_dir), "-q"]
    for k, v in (overrides or {}).items():
        cmd += ["--set", f"{k}={toml_value(v)}"]
    for kv in sets or []:
        cmd += ["--set", kv]
    if echo:
        print("   $ " + " ".join(cmd), flush=True)
    preexec = (lambda: os.nice(nice)) if nice else None
    t0 = time.perf_counter()
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            preexec_fn=preexec)
    # Read stderr fully before reaping, so the pipe never blocks the child.
    err = proc.stderr.read() if proc.stderr else ""
    _, status, ru = os.wait4(proc.pid, 0)
    wall = time.perf_counter() - t0
    proc.returncode = os.waitstatus_to_exitcode(status)
    summary = {}
    sfile = out_dir / "summary.json"
    if proc.returncode == 0 and sfile.exists():
        with open(sfile) as f:
            summary = json.load(f)
    return Run(case=str(case), out_dir=out_dir, returncode=proc.returncode, process_wall_s=wall,
               cpu_s=ru.ru_utime + ru.ru_stime, peak_rss_bytes=ru.ru_maxrss * 1024,  # Linux: KiB
               summary=summary, stderr_tail="\n".join(err.strip().splitlines()[-5:]))


def projection_case(sluice: Path, case_file: Path, out_dir: Path) -> Path:
    """The case without what the projection scheme refuses, for a projection variant: the keys
    `sluice schema` marks as WCSPH's (e.g. numerics.delta_sph), a force probe's explicit
    `reading = "force"` (that scheme integrates the interpolated pressure instead), and, with a
    binary older than force probes under the projection scheme, the force probes themselves
    (`is_force_probe`, `force_probes_under_projection`). The case itself when the binary has no
    `schema` command. Probe indices of the other probes are kept only if dropped force probes
    come last."""
    schema = sluice_schema(sluice)
    if schema is None:
        return case_file
    drop = {(k["table"], k["key"]) for k in schema if k["applies"] == "wcsph"}
    keep_force = force_probes_under_projection(schema)
    table, kept, probe = "", [], None
    for line in case_file.read_text().splitlines(keepends=True) + ["[end]\n"]:
        s = line.strip()
        if s.startswith("["):
            if probe is not None and (keep_force or not any(
                    re.match(r'type\s*=\s*"force"', x.strip()) for x in probe)):
                kept += probe
            probe = [] if s.startswith("[[probes]]") else None
            table = s.split("#")[0].strip().strip("[]").strip()
            if s == "[end]":
                break
        elif "=" in s and not s.startswith("#") and (table, s.split("=")[0].strip()) in drop:
            continue
        elif probe is not None and re.match(r'reading\s*=\s*"force"', s):
            continue  # the scheme's default reading ("interpolated") instead
        (kept if probe is None else probe).append(line)
    out = out_dir / f"{case_file.stem}_projection.toml"
    out.write_text("".join(kept))
    return out


def force_probes_under_projection(schema: list[dict]) -> bool:
    """Whether the binary whose `sluice schema` this is reads force probes under the projection
    scheme (the interpolated pressure integrated over the wall, since d930776)."""
    return any(k["table"] == "probes" and k["key"] == "reading"
               and 'type = "force"' in k.get("when", "") for k in schema)


def sluice_schema(sluice: Path) -> list[dict] | None:
    """The binary's `sluice schema` (its case keys); None when it has no such command or is not
    built yet."""
    try:
        r = subprocess.run([str(sluice), "schema"], capture_output=True, text=True)
    except OSError:
        return None
    return json.loads(r.stdout) if r.returncode == 0 else None


def projection_keeps_force_probes(sluice: Path) -> bool:
    """force_probes_under_projection for a binary (False without its schema)."""
    schema = sluice_schema(sluice)
    return schema is not None and force_probes_under_projection(schema)


def is_force_probe(probe: dict) -> bool:
    """A probe that binaries older than force_probes_under_projection refuse under the
    projection scheme (see projection_case)."""
    return probe.get("type") == "force"


def machine_description() -> str:
    """CPU model, core count and load at the time of the call (for the record)."""
    model = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    load = os.getloadavg()
    return (f"{model}, {os.cpu_count()} logical cores, load average "
            f"{load[0]:.2f} / {load[1]:.2f} / {load[2]:.2f} (1/5/15 min)")


def git_revision() -> str:
    try:
        return subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def fit_line(xs: list[float], ys: list[float]) -> tuple[float, float]:
    """Least-squares y = a + b x; returns (a, b)."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else 0.0
    return my - b * mx, b


def power_law_exponent(xs: list[float], ys: list[float]) -> float:
    """Slope of log y against log x (1 = linear in N)."""
    return fit_line([math.log(x) for x in xs], [math.log(y) for y in ys])[1]


def die(msg: str, code: int = 2) -> None:
    print(msg, file=sys.stderr)
    sys.exit(code)


