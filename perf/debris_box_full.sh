#!/usr/bin/env bash
# Tak's (2024) 3-D case at its own settings for the full 2 s (cases/debris_box_3d.toml): the
# solver's own time step (about 7 us with c = 350 m/s, h = 0.01 m), not the paper's 1 ms.
# Prints the run summary (steps, wall time, particle-steps/s) and the surge-front history.
# Usage: perf/debris_box_full.sh [THREADS] [END_TIME]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
threads="${1:-$(nproc)}"
end="${2:-2.0}"
out="$here/results/debris_box_full"
"$here/build/release/sluice" run "$here/cases/debris_box_3d.toml" --out "$out" \
    --threads "$threads" --set time.end_time="$end"
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
s = json.load(open(f"{out}/summary.json"))
print(f"machine threads {s['threads']}: {s['steps']} steps to t = {s['simulated_time']:.4f} s, "
      f"wall {s['wall_seconds']:.1f} s, {s['particle_steps_per_second']:.3g} particle-steps/s, "
      f"mass change {s['mass_relative_change']}")
print("stage busy seconds:", {k: round(v, 2) for k, v in s['extra']['stage_busy_seconds'].items()})
rows = [l.strip().split(',') for l in open(f"{out}/probes/front.csv")][1:]
print("surge front x [m] at t [s]:", ", ".join(f"{float(t):.2f}: {float(x):.3f}" for t, x in rows[::4]))
PY
