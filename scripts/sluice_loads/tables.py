"""Tables as text (aligned columns, "-" for a figure that could not be computed) and as CSV."""
from __future__ import annotations

import csv
import math
import re
from pathlib import Path


def write_csv(path: Path, rows: list[dict], columns: list[str]) -> None:
    """Rows as CSV with these columns (others left out); floats with 6 significant digits."""
    path = Path(path)
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


def text_table(rows: list[dict], columns: list[tuple[str, str, str]]) -> list[str]:
    """Lines of an aligned table: columns are (title, key, format spec without width, e.g.
    ".4g", "s"); each column is as wide as its widest cell; numbers right-aligned."""
    cells = []
    for r in rows:
        line = []
        for _, key, spec in columns:
            v = r.get(key, "")
            if isinstance(v, bool):
                v = "yes" if v else "no"
            line.append(format_cell(v, spec) if isinstance(v, (int, float)) and
                        not isinstance(v, bool) else str(v))
        cells.append(line)
    widths = [max([len(c[0])] + [len(line[i]) for line in cells]) for i, c in enumerate(columns)]
    left = [spec == "s" for _, _, spec in columns]

    def join(parts):
        return "  ".join(p.ljust(w) if lf else p.rjust(w)
                         for p, w, lf in zip(parts, widths, left)).rstrip()

    return [join([c[0] for c in columns]), join(["-" * w for w in widths])] + \
        [join(line) for line in cells]
