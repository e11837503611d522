#!/usr/bin/env bash
# What a moving tank costs: perf/cases/sloshing_3d.toml (a closed 3-D tank rolling 3 degrees,
# every wall particle moving) beside the same tank held fixed, interleaved round by round
# (fixed, moving) on the same binary and threads, so both see the same machine. Prints each
# run's particle-steps per second and steps, the medians and the ratio of the time per
# particle-step, moving / fixed.
# Usage: perf/moving_walls/run.sh [ROUNDS] [THREADS] [END_TIME]
set -euo pipefail
rounds=${1:-3}
threads=${2:-2}
end=${3:-0.1}
root=$(cd "$(dirname "$0")/../.." && pwd)
exe="$root/build/release/sluice"
[[ -x $exe ]] || { echo "run.sh: $exe missing (cmake --preset release && cmake --build --preset release)" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
moving="$root/perf/cases/sloshing_3d.toml"
fixed="$work/sloshing_3d_fixed.toml"
# The fixed tank: the same file without its motion.
/usr/bin/python3 - "$moving" "$fixed" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
text = re.sub(r'\ntank_motion = "roll"\n', "\n", text)
text = re.sub(r"\[\[motions\]\]\n(?:[^\[\n].*\n|\n)*", "", text)
open(sys.argv[2], "w").write(text)
PY
"$exe" check "$fixed" >/dev/null
for ((r = 1; r <= rounds; r++)); do
    for kind in fixed moving; do
        case_file=$fixed
        [[ $kind == moving ]] && case_file=$moving
        "$exe" run "$case_file" --threads "$threads" -q --out "$work/$kind$r" --set time.end_time="$end"
    done
done
/usr/bin/python3 - "$work" "$rounds" "$threads" <<'PY'
import json, statistics as st, sys
work, rounds, threads = sys.argv[1], int(sys.argv[2]), sys.argv[3]
rate = {"fixed": [], "moving": []}
for r in range(1, rounds + 1):
    for kind in rate:
        s = json.load(open(f"{work}/{kind}{r}/summary.json"))
        rate[kind].append(s["particle_steps_per_second"])
        print(f"round {r} {kind:6s}: {s['particles']} particles, {s['steps']} steps, "
              f"{s['wall_seconds']:.2f} s, {s['particle_steps_per_second'] / 1e6:.3f} M particle-steps/s")
f, m = st.median(rate["fixed"]), st.median(rate["moving"])
print(f"median ({threads} threads): fixed {f / 1e6:.3f}, moving {m / 1e6:.3f} M particle-steps/s; "
      f"time per particle-step moving / fixed = {f / m:.3f}")
PY
