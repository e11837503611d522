"""The runs an analysis reads: the run folders study.py writes (study_run.json says what each
run is) and run folders made by hand, whose dx, c0 and probe heights are inferred from the
case they were made from."""
from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

import loads_package  # noqa: F401  (scripts/ on the path)
from sluice_loads.impact import Scales
from sluice_loads.runs import load_probe

DEFAULT_CASE = Path(__file__).resolve().parent / "zhou_2d.toml"


@dataclass
class RunInfo:
    folder: Path
    variant: str
    label: str
    dx: float
    c0: float
    c0_factor: float
    end_time: float
    scales: Scales
    probes: dict[str, float]                 # pressure probe name -> height y [m]
    probe_x: dict[str, float] = field(default_factory=dict)
    wall_s: float = float("nan")
    steps: int = 0
    inferred: str = ""                       # what was guessed (old runs)


def _legacy_height(name: str) -> float | None:
    m = re.fullmatch(r"y(\d+)mm", name)
    if m:
        return int(m.group(1)) / 1000.0
    m = re.fullmatch(r"p(\d{3})", name)
    if m:
        return int(m.group(1)) / 100.0
    return {"P1": 0.16, "P2": 0.584}.get(name)


def case_scales(case: dict) -> Scales:
    b = case["blocks"][0]
    H = float(b["hi"][1] - b["lo"][1])
    g = abs(float(case["fluid"].get("gravity", [0.0, -9.81])[-1]))
    return Scales(H=H, g=g, rho0=float(case["fluid"].get("rho0", 1000.0)))


def run_from_study(folder: Path) -> RunInfo:
    with open(folder / "study_run.json") as f:
        j = json.load(f)
    sc = Scales(**j["scales"])
    summ = {}
    if (folder / "summary.json").exists():
        with open(folder / "summary.json") as f:
            summ = json.load(f)
    probes = {n: float(v["position"][1]) for n, v in j["probes"].items()}
    px = {n: float(v["position"][0]) for n, v in j["probes"].items()}
    note = "" if j.get("returncode", 0) == 0 else \
        f"run FAILED (exit {j.get('returncode')}): its probe files stop where it stopped"
    return RunInfo(folder=folder, variant=j["variant"], label=j["label"], dx=j["dx"], c0=j["c0"],
                   c0_factor=j["c0_factor"], end_time=summ.get("simulated_time", j["end_time"]),
                   scales=sc, probes=probes, probe_x=px, wall_s=summ.get("wall_seconds", math.nan),
                   steps=summ.get("steps", 0), inferred=note)


def run_from_folder(folder: Path, case: dict, heights: dict[str, float],
                    variant: str) -> RunInfo:
    """A run folder without study_run.json (made by hand): guess what is not written."""
    sc = case_scales(case)
    with open(folder / "summary.json") as f:
        summ = json.load(f)
    notes = []
    # dx from the fluid particle count and the case's block area (lattice fill)
    b = case["blocks"][0]
    area = float(np.prod(np.subtract(b["hi"], b["lo"])))
    dim = int(case["case"]["dimension"])
    dx = (area / summ["fluid_particles"]) ** (1.0 / dim)
    dx = float(f"{dx:.4g}")
    notes.append(f"dx={dx:g} from particle count")
    probe_case = {p["name"]: p for p in case.get("probes", [])}
    probes, px = {}, {}
    for f in sorted((folder / "probes").glob("*.csv")):
        with open(f) as fh:
            head = fh.readline().strip()
        if not head.startswith("time_s,pressure_Pa"):
            continue
        n = f.stem
        if n in heights:
            y = heights[n]
        elif n in probe_case and "position" in probe_case[n]:
            y = float(probe_case[n]["position"][1])
            px[n] = float(probe_case[n]["position"][0])
        else:
            y = _legacy_height(n)
            if y is None:
                print(f"   {folder}: no height for probe {n} (use --probe {n}=Y); skipped")
                continue
            notes.append(f"{n}: y={y:g} from its name")
        probes[n] = y
    # c0 from the first step: at rest dt = cfl * h / c0 (the acoustic limit governs)
    num = case.get("numerics", {})
    c0 = float(case["fluid"]["sound_speed"])
    first = next(iter(probes), None)
    if first is not None:
        t, _ = load_probe(folder / "probes" / f"{first}.csv")
        if len(t) > 1 and t[1] > 0:
            h = float(num.get("h_over_dx", 1.0)) * dx
            c0 = float(num.get("cfl", 0.25)) * h / float(t[1])
            notes.append(f"c0={c0:.4g} from first dt")
    factor = c0 / math.sqrt(sc.g * sc.H)
    return RunInfo(folder=folder, variant=variant, label=folder.name, dx=dx, c0=c0,
                   c0_factor=round(factor, 2), end_time=summ.get("simulated_time", math.nan),
                   scales=sc, probes=probes, probe_x=px, wall_s=summ.get("wall_seconds", math.nan),
                   steps=summ.get("steps", 0), inferred="; ".join(notes))


def discover(dirs: list[Path], case: dict, heights: dict[str, float],
             variant: str) -> list[RunInfo]:
    runs = []
    for d in dirs:
        if (d / "study_run.json").exists():
            runs.append(run_from_study(d))
        elif (d / "probes").is_dir():
            runs.append(run_from_folder(d, case, heights, variant))
        else:
            found = sorted(p.parent for p in d.rglob("study_run.json"))
            if not found:
                print(f"   {d}: no run folder (probes/) or study_run.json below it")
            runs.extend(run_from_study(p) for p in found)
    return [r for r in runs if (r.folder / "probes").is_dir()]
