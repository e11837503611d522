"""The impact study's CSV files: sluice's probe records, the reference data in data/ (a header
of '#' lines saying where the data come from, then a row of column names) and the tables the
scripts write (CSVs, and the cells of their text tables)."""
from __future__ import annotations

import csv
import math
import re
from pathlib import Path

import numpy as np

DATA = Path(__file__).resolve().parent / "data"


def load_probe(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """time_s, pressure_Pa of a probe CSV; NaN (dry) kept as NaN."""
    d = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return d[:, 0], d[:, 1]


def read_data_columns(name: str) -> dict[str, np.ndarray]:
    """The columns of a CSV in data/ ('#' header lines, then a row of column names), keyed by
    name, rows sorted by the first column (stable: digitisations such as the PySPH copy have
    a few rows out of time order, as in their sources)."""
    with open(DATA / name) as f:
        rows = list(csv.reader(ln for ln in f if not ln.startswith("#")))
    body = np.array([[float(x) for x in r] for r in rows[1:] if r])
    body = body[np.argsort(body[:, 0], kind="stable")]
    return {h: body[:, i] for i, h in enumerate(rows[0])}


def load_experiment(name: str) -> tuple[np.ndarray, np.ndarray]:
    """(t*, p*) of a digitised record in data/ (its first two columns), sorted by time."""
    cols = list(read_data_columns(name).values())
    return cols[0], cols[1]


def write_csv(path: Path, rows: list[dict], columns: list[str]) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in r.items()})


def format_cell(v, spec: str) -> str:
    """v formatted with spec for a text table, or "-" right-aligned in spec's width when v is a
    float that is not finite (a figure a run could not give)."""
    if isinstance(v, float) and not math.isfinite(v):
        width = re.match(r"[<>^]?(\d*)", spec.lstrip("+")).group(1)
        return "-".rjust(int(width) if width else 1)
    return format(v, spec)
