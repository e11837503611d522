"""A results folder of `sluice run` (docs/CASE_REFERENCE.md, "Results folder"): its probe
files, summary.json and the case file it was made from, and what the load figures need from
them: dx, the dimension, the scales rho g H and sqrt(H/g), and which probes carry loads.

`--set` overrides are not recorded in a results folder. dx is read from summary.json (its
`extra.neighbours.crowded_below` is dx/2, so a `--set particles.dx` shows); rho0, gravity and
the fluid blocks come from the case file, so a run made with those overridden needs the
scales given (`--scale`) or an edited copy of the case (`--case`)."""
from __future__ import annotations

import csv
import json
import math
import tomllib
import warnings
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from .impact import Scales

REPO = Path(__file__).resolve().parents[2]
FORCE_COMPONENTS = ("Fx", "Fy", "Fz")


class BadInput(Exception):
    """Input the tools cannot use (a missing folder or file, an unknown probe, an empty
    series); its message names the file or probe."""


def load_probe(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """time_s and the first value column of a probe CSV; NaN (dry) kept as NaN."""
    d = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return d[:, 0], d[:, 1]


def read_probe(path: Path) -> tuple[list[str], np.ndarray]:
    """(column names, rows) of a probe CSV; BadInput when it is unreadable or has fewer than
    two samples."""
    try:
        with open(path, newline="") as f:
            header = next(csv.reader(f), [])
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # numpy warns on a file without rows
                data = np.loadtxt(f, delimiter=",", ndmin=2)
    except (OSError, ValueError) as e:
        raise BadInput(f"{path}: cannot read it as a probe file ({e})") from e
    if not header or header[0] != "time_s":
        raise BadInput(f"{path}: not a probe file (no time_s column)")
    if data.shape[0] < 2:
        raise BadInput(f"{path}: empty series ({data.shape[0]} samples; at least 2 needed)")
    if data.shape[1] != len(header):
        raise BadInput(f"{path}: {data.shape[1]} values per row under {len(header)} columns")
    return header, data


def case_scales(case: dict) -> Scales:
    """rho0, |g| and H from a case: H is the height of the fluid blocks from the lowest block
    bottom to the highest top along gravity (the last axis without gravity)."""
    fluid = case.get("fluid", {})
    dim = int(case["case"]["dimension"])
    gvec = np.array(fluid.get("gravity", [0.0] * dim), dtype=float)
    up = int(np.argmax(np.abs(gvec))) if np.any(gvec) else dim - 1
    blocks = case.get("blocks", [])
    if not blocks:
        raise BadInput("the case has no [[blocks]]: give --scale rho,g,H")
    H = max(float(b["hi"][up]) for b in blocks) - min(float(b["lo"][up]) for b in blocks)
    nonzero = gvec[gvec != 0]  # one component: its magnitude exactly, as the case writes it
    g = abs(float(nonzero[0])) if len(nonzero) == 1 else float(np.linalg.norm(gvec))
    return Scales(H=H, g=g, rho0=float(fluid.get("rho0", 1000.0)))


def parse_scale(text: str) -> Scales:
    """--scale rho,g,H."""
    try:
        rho, g, H = (float(x) for x in text.split(","))
    except ValueError as e:
        raise BadInput(f"--scale {text}: expected rho,g,H (three numbers)") from e
    if min(rho, g, H) <= 0:
        raise BadInput(f"--scale {text}: rho, g and H must be positive")
    return Scales(H=H, g=g, rho0=rho)


@dataclass
class Probe:
    name: str
    path: Path
    kind: str            # "pressure" (point probe), "area" (area sensor) or "force"
    columns: list[str]
    spec: dict = field(default_factory=dict)   # the case's [[probes]] entry, if found

    def default_component(self) -> str:
        """A force probe on a tank face: the force into that face (x+: Fx, x-: -Fx, ...);
        otherwise Fx."""
        face = self.spec.get("face", "")
        if len(face) == 2 and face[0] in "xyz":
            return ("-" if face[1] == "-" else "") + "F" + face[0]
        return "Fx"


@dataclass
class Run:
    folder: Path
    summary: dict
    case: dict | None
    case_path: Path | None
    scales: Scales | None
    probes: dict[str, Probe]

    @property
    def label(self) -> str:
        return str(self.folder)

    @property
    def dimension(self) -> int:
        if "dimension" in self.summary:
            return int(self.summary["dimension"])
        if self.case:
            return int(self.case["case"]["dimension"])
        return 2

    @property
    def dx(self) -> float:
        """The run's dx: summary.json's crowded_below is dx/2; without summary.json (a run that
        did not reach its end time) the case file's particles.dx; NaN when neither."""
        below = self.summary.get("extra", {}).get("neighbours", {}).get("crowded_below")
        if below:
            return 2.0 * float(below)
        if self.case and "dx" in self.case.get("particles", {}):
            return float(self.case["particles"]["dx"])
        return math.nan

    def probe(self, name: str) -> Probe:
        if name not in self.probes:
            path = self.folder / "probes" / f"{name}.csv"
            if path.is_file():
                with open(path, newline="") as f:
                    cols = ",".join(next(csv.reader(f), [])) or "no header"
                raise BadInput(f"{path}: probe '{name}' is not a load probe (columns {cols}); "
                               "loads are pressure probes, area sensors and force probes")
            known = ", ".join(sorted(self.probes)) or "none"
            raise BadInput(f"{self.folder}: no probe '{name}' (load probes: {known})")
        return self.probes[name]


def _find_case(folder: Path, summary: dict, case_path: Path | None) -> tuple[dict | None,
                                                                               Path | None]:
    if case_path is not None:
        candidates = [case_path]
    else:
        src = summary.get("source_file")
        candidates = [Path(src), REPO / src] if src else []
    for c in candidates:
        if c.is_file():
            try:
                with open(c, "rb") as f:
                    return tomllib.load(f), c
            except (OSError, tomllib.TOMLDecodeError) as e:
                raise BadInput(f"{c}: cannot read the case file ({e})") from e
    if case_path is not None:
        raise BadInput(f"{case_path}: no such case file")
    return None, None


def _probe_kind(header: list[str], spec: dict) -> str | None:
    if len(header) > 1 and header[1] == "pressure_Pa":
        return "area" if "diameter" in spec else "pressure"
    if len(header) > 1 and header[1] == "Fx_N":
        return "force"
    return None  # water level, surge front, motion: not a load


def open_run(folder: Path, case_path: Path | None = None,
             scales: Scales | None = None) -> Run:
    """The run in `folder`, with the scales from `scales`, else from its case file (None when
    neither is found). BadInput when the folder or its probes/ is missing."""
    folder = Path(folder)
    if not folder.is_dir():
        raise BadInput(f"{folder}: no such results folder")
    if not (folder / "probes").is_dir():
        raise BadInput(f"{folder}: no probes/ folder (not a results folder of sluice run)")
    summary = {}
    if (folder / "summary.json").is_file():
        try:
            summary = json.loads((folder / "summary.json").read_text())
        except (OSError, json.JSONDecodeError) as e:
            raise BadInput(f"{folder / 'summary.json'}: cannot read it ({e})") from e
    case, found = _find_case(folder, summary, case_path)
    if scales is None and case is not None:
        scales = case_scales(case)
    specs = {p.get("name"): p for p in (case or {}).get("probes", [])}
    probes = {}
    for path in sorted((folder / "probes").glob("*.csv")):
        with open(path, newline="") as f:
            header = next(csv.reader(f), [])
        spec = specs.get(path.stem, {})
        kind = _probe_kind(header, spec)
        if kind:
            probes[path.stem] = Probe(path.stem, path, kind, header, spec)
    return Run(folder, summary, case, found, scales, probes)
