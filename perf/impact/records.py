"""The impact study's reference data in data/: a header of '#' lines saying where the data come
from, then a row of column names. Probe files and the tables the scripts write are read and
written with the product's package (scripts/sluice_loads: runs.load_probe, tables.write_csv,
tables.format_cell)."""
from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

DATA = Path(__file__).resolve().parent / "data"


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
