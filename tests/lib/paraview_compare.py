"""Compares what ParaView read from a run's snapshots.xmf (tests/lib/paraview_read.py's OUTDIR)
with the run's HDF5 snapshots as h5py reads them. Exit code 1 and a line per difference.

    /usr/bin/python3 paraview_compare.py RESULTS OUTDIR

For each reader: as many time steps as RESULTS/snapshots/snap_*.h5 files, each step's time
equal to that file's `time` attribute; each step as many points as the file has particles;
the point arrays exactly the file's datasets other than `position`, with the same number of
components; the points and every array equal to the file's values, bit for bit (NaN where the
file has NaN). XDMFReader must also make one vertex cell per particle (what ParaView draws);
Xdmf3ReaderS's cell count is printed, not checked.
"""
import glob
import json
import os
import sys

import h5py
import numpy as np

results, outdir = sys.argv[1], sys.argv[2]
files = sorted(glob.glob(os.path.join(results, "snapshots", "snap_*.h5")))
problems = []


def check(ok, what):
    if not ok:
        problems.append(what)


for reader in ("XDMFReader", "Xdmf3ReaderS"):
    with open(os.path.join(outdir, f"{reader}.json")) as f:
        seen = json.load(f)
    check(len(seen["times"]) == len(files),
          f"{reader}: {len(seen['times'])} time steps, the run wrote {len(files)} snapshots")
    cells = []
    for k, path in enumerate(files[: len(seen["times"])]):
        step = seen["steps"][k]
        where = f"{reader} step {k} ({os.path.basename(path)})"
        pv = np.load(os.path.join(outdir, f"{reader}_{k}.npz"))
        with h5py.File(path, "r") as h5:
            t = float(h5.attrs["time"])
            check(seen["times"][k] == t, f"{where}: time {seen['times'][k]!r}, the file's {t!r}")
            n = h5["position"].shape[0]
            check(step["points"] == n, f"{where}: {step['points']} points, {n} particles")
            cells.append(step["cells"])
            if reader == "XDMFReader":
                check(step["cells"] == n, f"{where}: {step['cells']} cells, {n} particles")
            fields = sorted(k2 for k2 in h5 if k2 != "position")
            names = sorted(a["name"] for a in step["arrays"])
            check(names == fields, f"{where}: point arrays {names}, datasets {fields}")
            for a in step["arrays"]:
                if a["name"] in h5:
                    want = h5[a["name"]].shape[1] if h5[a["name"]].ndim == 2 else 1
                    check(a["components"] == want, f"{where}: {a['name']} has "
                          f"{a['components']} components, the dataset {want}")
            for name in ["position"] + fields:
                key = "points" if name == "position" else name
                if key not in pv.files:
                    continue  # reported above with the array names
                got, want = pv[key], h5[name][:]
                if got.shape != want.shape:
                    problems.append(f"{where}: {name} has shape {got.shape}, the file's "
                                    f"{want.shape}")
                elif not np.array_equal(got, want,
                                        equal_nan=np.issubdtype(want.dtype, np.floating)):
                    diff = np.nanmax(np.abs(got.astype(float) - want.astype(float)))
                    problems.append(f"{where}: {name} differs from the file's by up to {diff}")
            if k == len(files) - 1 and "pressure" in pv.files and n:
                print(f"{reader}: last step's max |pressure| {np.abs(pv['pressure']).max():.17g}"
                      f" Pa, the file's {np.abs(h5['pressure'][:]).max():.17g} Pa")
    arrays = ", ".join(a["name"] for a in seen["steps"][0]["arrays"]) if seen["steps"] else "-"
    print(f"{reader}: {len(seen['times'])} steps, points {[s['points'] for s in seen['steps']]},"
          f" cells {cells}, arrays {arrays}")

for line in problems:
    print("FAIL:", line)
sys.exit(1 if problems or not files else 0)
