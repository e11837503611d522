#!/usr/bin/env python3
"""Per-particle agreement of two runs of one case on different rank counts (the projection
scheme agrees to its solver's tolerance, not bit for bit): every snapshot of ONE has its twin
in THREE with the same particle ids; pressure within 1e-6 of SCALE and positions within 1e-9 m.
SCALE is a pressure in Pa, or a case file whose rho0 |g| H (H = the domain's height) is used.
Usage: compare_layouts.py ONE THREE LABEL SCALE MIN_SNAPSHOTS"""
import glob
import os
import sys
import tomllib

import h5py
import numpy as np

one, three, label, scale_arg, min_snaps = sys.argv[1:6]
if os.path.isfile(scale_arg):
    cfg = tomllib.load(open(scale_arg, "rb"))
    g = np.linalg.norm(cfg["fluid"].get("gravity", [0, -9.81]))
    H = cfg["domain"]["hi"][-1] - cfg["domain"]["lo"][-1]
    scale = cfg["fluid"]["rho0"] * max(g, 1.0) * H
else:
    scale = float(scale_arg)
snaps = sorted(glob.glob(os.path.join(one, "snapshots", "*.h5")))
assert len(snaps) >= int(min_snaps), snaps
worst_p = worst_x = 0.0
for f in snaps:
    a = h5py.File(f, "r")
    b = h5py.File(os.path.join(three, "snapshots", os.path.basename(f)), "r")
    ia, ib = np.argsort(a["id"][:]), np.argsort(b["id"][:])
    assert np.array_equal(a["id"][:][ia], b["id"][:][ib]), "different particles"
    worst_p = max(worst_p, np.abs(a["pressure"][:][ia] - b["pressure"][:][ib]).max() / scale)
    worst_x = max(worst_x, np.abs(a["position"][:][ia] - b["position"][:][ib]).max())
print(f"{label}: 1 vs 3 ranks over {len(snaps)} snapshots: max |dp| / scale = "
      f"{worst_p:.2e}, max |dx| = {worst_x:.2e} m")
assert worst_p < 1e-6, worst_p
assert worst_x < 1e-9, worst_x
