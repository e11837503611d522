"""Puts scripts/ on the import path, so that the study scripts use the product's load package
(scripts/sluice_loads: signals on irregular samples, the first-impact figures, tables), the
one `scripts/loads` is built on. Import this module before any `sluice_loads` import."""
import sys
from pathlib import Path

SCRIPTS = str(Path(__file__).resolve().parents[2] / "scripts")
if SCRIPTS not in sys.path:
    sys.path.insert(0, SCRIPTS)
