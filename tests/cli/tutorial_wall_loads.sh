#!/usr/bin/env bash
# docs/TUTORIAL_WALL_LOADS.md does not go stale: every block of scripts/tutorial_wall_loads.sh
# between "# tutorial:NAME" and "# tutorial:end" appears in the document verbatim, and the
# script runs with --coarse (the same commands at dx = H/5 to H/20, two ensemble members;
# about 10 s on one core): every run finishes, scripts/plot writes its PNG, and scripts/loads
# writes its tables with finite numbers for every load probe of the case.
# Skipped (exit code 77) where Debian's python3 lacks numpy, matplotlib, h5py or PIL.
# Usage: tutorial_wall_loads.sh <sluice exe> <source dir>
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
py=/usr/bin/python3
if ! "$py" -c "import numpy, matplotlib, h5py, PIL" 2>/dev/null; then
    echo "SKIP: $py lacks numpy, matplotlib, h5py or PIL (python3-matplotlib, python3-h5py)"
    exit 77
fi
script="$src/scripts/tutorial_wall_loads.sh"
doc="$src/docs/TUTORIAL_WALL_LOADS.md"

"$py" - "$script" "$doc" <<'PY' || fail "the document does not quote the script's blocks"
import re, sys
script, doc = (open(p).read() for p in sys.argv[1:])
blocks = re.findall(r"^# tutorial:(\w+)\n(.*?)^# tutorial:end$", script, re.M | re.S)
if len(blocks) < 4:
    sys.exit(f"only {len(blocks)} tutorial blocks in the script")
for name, text in blocks:
    if f"```sh\n{text}```" not in doc:
        sys.exit(f"block '{name}' of the script is not a ```sh block of the document:\n{text}")
PY

out="$work/t"
bash "$script" --coarse --sluice "$exe" --out "$out" --threads 1 >"$work/log.txt" 2>&1 ||
    fail "tutorial --coarse: exit code $?: $(grep -v '^step' "$work/log.txt" | tail -20)"

for f in first/summary.json first/plots/probes.png ensemble/j0/summary.json \
    ensemble/j0.01/summary.json ladder/dx0.06/j0/summary.json ladder/dx0.015/j0.01/summary.json \
    ensemble.csv gci.csv; do
    [ -s "$out/$f" ] || fail "tutorial --coarse wrote no $f"
done
grep -q '^== first impact, SI units' "$work/log.txt" || fail "no peaks table in the output"
grep -q '^report' "$work/log.txt" || fail "no report lines from loads gci"

"$py" - "$out" <<'PY' || fail "the tables hold a number that is not finite"
import csv, math, sys
out = sys.argv[1]
probes = {"sensor_30mm", "sensor_90mm", "wall_force"}
for name, keys in (("ensemble.csv", ["median", "min", "max"]),
                   ("gci.csv", ["coarse", "medium", "fine", "fine_min", "fine_max"])):
    rows = list(csv.DictReader(open(f"{out}/{name}")))
    if {r["probe"] for r in rows} != probes:
        sys.exit(f"{name}: probes {sorted({r['probe'] for r in rows})}, not {sorted(probes)}")
    for r in rows:
        bad = [k for k in keys if not math.isfinite(float(r[k]))]
        if bad:
            sys.exit(f"{name}: {r['probe']} {r['figure']}: {bad} not finite")
    gci = [r for r in rows if name == "gci.csv"]
    if gci and any(not r["verdict"] for r in gci):
        sys.exit("gci.csv: a row without a verdict")
PY

[ $failures -eq 0 ] && echo "tutorial wall loads: all checks passed"
exit $((failures > 0))
