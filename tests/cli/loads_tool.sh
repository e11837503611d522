#!/usr/bin/env bash
# scripts/loads on results folders written here with known answers (no simulation): `peaks`
# gives a triangle pulse's contact, peaks and impulse, `ensemble` the median and spread of
# three runs, `gci` the order and the extrapolated value of a ladder f = f0 + C dx^p; missing
# folders, unknown probes and empty series exit with code 2 and name the file or probe. Runs the
# package's unit tests (scripts/sluice_loads/tests) first. Skipped (exit code 77) where
# Debian's python3 lacks numpy.
# Usage: loads_tool.sh <sluice exe> <source dir>   (the executable is not used)
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
py=/usr/bin/python3
if ! "$py" -c "import numpy" 2>/dev/null; then
    echo "SKIP: $py lacks numpy (python3-numpy)"
    exit 77
fi
loads() { "$py" "$src/scripts/loads" "$@"; }

"$py" -m unittest discover -s "$src/scripts/sluice_loads/tests" >"$work/unit.txt" 2>&1 ||
    fail "unit tests: $(tail -20 "$work/unit.txt")"

# Results folders: a case (rho g H = 1000 * 10 * 0.4 = 4000 Pa, rho g H^2/2 = 800 N/m,
# sqrt(H/g) = 0.2 s), and runs whose area sensor `sensor` reads a triangle from 0.4 to 0.5 s
# with its apex at 0.45 s, and whose force probe `wall` on face x+ reads half of it in Fx.
"$py" - "$work" <<'PY' || fail "writing the results folders"
import json, sys
from pathlib import Path
import numpy as np
work = Path(sys.argv[1])
(work / "case.toml").write_text("""[case]
name = "synthetic"
dimension = 2
[fluid]
rho0 = 1000.0
gravity = [0.0, -10.0]
[particles]
dx = 0.02
[[blocks]]
lo = [0.0, 0.0]
hi = [0.8, 0.4]
[[probes]]
name = "sensor"
type = "pressure"
position = [2.0, 0.02]
diameter = 0.01
[[probes]]
name = "wall"
type = "force"
face = "x+"
""")
t = np.linspace(0.0, 1.0, 2001)  # every 0.5 ms
tri = np.interp(t, [0.0, 0.4, 0.45, 0.5, 1.0], [0.0, 0.0, 1.0, 0.0, 0.0])
def run(name, dx, peak):
    d = work / name
    (d / "probes").mkdir(parents=True)
    (d / "summary.json").write_text(json.dumps({
        "case": "synthetic", "dimension": 2, "source_file": str(work / "case.toml"),
        "extra": {"neighbours": {"crowded_below": dx / 2}}}))
    np.savetxt(d / "probes" / "sensor.csv", np.c_[t, peak * tri], delimiter=",",
               header="time_s,pressure_Pa", comments="")
    np.savetxt(d / "probes" / "wall.csv", np.c_[t, 0.5 * peak * tri, 0 * t], delimiter=",",
               header="time_s,Fx_N,Fy_N", comments="")
    np.savetxt(d / "probes" / "front.csv", np.c_[t, t], delimiter=",", header="time_s,front_x_m",
               comments="")
run("one", 0.02, 9000.0)
for j, peak in enumerate([4000.0, 8000.0, 16000.0]):
    run(f"ens/j{j}", 0.02, peak)
for dx in (0.04, 0.02, 0.01):  # peak = 4000 (1 + 25 dx^1.5) Pa: order 1.5, limit 1 rho g H
    for j in range(2):
        run(f"ladder/dx{dx}/j{j}", dx, 4000.0 * (1 + 25 * dx**1.5) * (1 + 0.001 * j))
(work / "ens_empty").mkdir()
run("empty", 0.02, 1.0)
(work / "empty" / "probes" / "sensor.csv").write_text("time_s,pressure_Pa\n")
PY

# check NAME CSV PYTHON-EXPRESSION: the expression, over `rows` (the CSV's rows as dicts with
# numbers as floats), must hold
check() {
    "$py" - "$2" "$3" <<'PY' || fail "$1: $3 does not hold for $2"
import csv, math, sys
def num(v):
    try:
        return float(v)
    except ValueError:
        return v
rows = [{k: num(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
close = lambda a, b, tol=1e-9: abs(a - b) <= tol * max(1.0, abs(b))
by = {(r.get("probe"), r.get("figure"), r.get("units")): r for r in rows}
sys.exit(0 if eval(sys.argv[2]) else 1)
PY
}

# peaks: contact at the first sample above 200 Pa (0.4015 s, 270 Pa), raw peak 9000 Pa =
# 2.25 rho g H at 0.45 s, the 10 ms average's peak 9000 (1 - 0.01 / (4 * 0.05)) = 8550 Pa, the
# impulse over the window (0.5 sqrt(H/g) = 0.1 s from contact) 450 - 0.5 * 0.0015 * 270 Pa s.
loads peaks "$work/one" --csv "$work/peaks.csv" >"$work/peaks.txt" 2>&1 ||
    fail "peaks: exit code $?: $(tail -5 "$work/peaks.txt")"
check peaks "$work/peaks.csv" 'len(rows) == 2 and {r["probe"] for r in rows} == {"sensor", "wall"}'
check peaks "$work/peaks.csv" 'close(rows[0]["t_contact"], 0.4015) and close(rows[0]["peak_raw"], 9000) and close(rows[0]["peak_raw_scaled"], 2.25) and close(rows[0]["t_peak_raw"], 0.45)'
check peaks "$work/peaks.csv" 'close(rows[0]["peak_smooth"], 8550, 1e-5) and close(rows[0]["impulse"], 449.7975, 1e-5) and close(rows[0]["impulse_scaled"], 449.7975 / 800, 1e-5) and rows[0]["window_complete"] == "True"'
check peaks "$work/peaks.csv" 'rows[1]["signal"] == "Fx" and close(rows[1]["peak_raw_scaled"], 4500 / 800) and rows[1]["unit"] == "N/m"'
grep -q 'rho g H^2/2' "$work/peaks.txt" || fail "peaks: no scaled table: $(cat "$work/peaks.txt")"
# the search from 0.45 to 0.47 s, the window to its end: contact at 0.45 s, impulse 7200 * 0.02
loads peaks "$work/one" --probe sensor --from 0.45 --to 0.47 --window 0 --csv "$work/cut.csv" \
    >/dev/null 2>&1 || fail "peaks --from --to: exit code $?"
check peaks_range "$work/cut.csv" 'close(rows[0]["t_contact"], 0.45) and close(rows[0]["t_window_end"], 0.47) and close(rows[0]["peak_raw"], 9000) and close(rows[0]["impulse"], 144, 1e-6)'

# ensemble of three runs whose peaks are 1, 2 and 4 rho g H: median 2, spread 150 %
loads ensemble "$work/ens" --probe sensor --csv "$work/ens.csv" >"$work/ens.txt" 2>&1 ||
    fail "ensemble: exit code $?: $(tail -5 "$work/ens.txt")"
check ensemble "$work/ens.csv" 'by[("sensor", "raw", "scaled")]["median"] == 2 and close(by[("sensor", "raw", "scaled")]["spread_pct"], 150) and by[("sensor", "raw", "si")]["max"] == 16000'

# gci on the ladder (no short average: --filter-ms 0): order 1.5 and the limit 1 rho g H (times
# the common factor 1.0005 of each level's median)
loads gci "$work/ladder/dx0.04" "$work/ladder/dx0.02" "$work/ladder/dx0.01" --probe sensor \
    --filter-ms 0 --csv "$work/gci.csv" >"$work/gci.txt" 2>&1 ||
    fail "gci: exit code $?: $(tail -5 "$work/gci.txt")"
check gci "$work/gci.csv" 'close(by[("sensor", "0 ms", "scaled")]["order"], 1.5, 2e-3) and close(by[("sensor", "0 ms", "scaled")]["f_ext"], 1.0, 1e-3) and by[("sensor", "0 ms", "scaled")]["kind"] == "monotone"'
grep -q 'report' "$work/gci.txt" || fail "gci: no report lines: $(cat "$work/gci.txt")"
loads gci "$work/ladder/dx0.04" "$work/ladder/dx0.02" >"$work/gci2.txt" 2>&1
[ $? -eq 2 ] && grep -q 'three resolutions' "$work/gci2.txt" ||
    fail "gci on two resolutions: not refused with code 2: $(cat "$work/gci2.txt")"

# bad input: exit code 2, the file or probe named
refused() { # what pattern args...
    local what=$1 pattern=$2
    shift 2
    loads "$@" >"$work/bad.txt" 2>&1
    local rc=$?
    [ $rc -eq 2 ] || fail "$what: exit code $rc, not 2: $(cat "$work/bad.txt")"
    grep -q -- "$pattern" "$work/bad.txt" || fail "$what: message does not name $pattern: $(cat "$work/bad.txt")"
}
refused "missing folder" "$work/nowhere" peaks "$work/nowhere"
refused "unknown probe" "'nope'" peaks "$work/one" --probe nope
refused "not a load probe" "front.csv" peaks "$work/one" --probe front
refused "empty series" "sensor.csv" peaks "$work/empty" --probe sensor
refused "folder of no runs" "ens_empty" ensemble "$work/ens_empty"
refused "unknown component" "Mz" peaks "$work/one" --probe wall --component Mz
refused "runs at two dx" "differ in dx" ensemble "$work/ladder/dx0.04" "$work/ladder/dx0.02"

[ $failures -eq 0 ] && echo "loads tool: all checks passed"
exit $((failures > 0))
