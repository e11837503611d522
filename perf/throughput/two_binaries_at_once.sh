#!/usr/bin/env bash
# Two sluice binaries on configuration 1 (perf/cases/dam_break_2d_peer.toml) at the same time,
# one thread each, each pinned to its own core (taskset), so that both see the same machine: on
# a shared 2-core host whose speed drifts within minutes, runs taken one after the other differ
# more than a few-per-cent change does. The cores are not equal (on the 2-core development VM
# the run on one of them was up to 10 % faster), so rounds alternate which binary gets core 0,
# and the result is the geometric mean over an even number of rounds. Each round prints both
# runs' wall time and their stages' busy milliseconds per step. Bursts of other work on the host
# still move single rounds by 10-30 %, so it also prints each run's step time over its own
# walls stage (`step/walls`): set ONLY when the walls stage is the same code in both binaries,
# it is a clock that saw the same bursts as the rest of that run. Use peer_two_binaries.sh for
# the 2-thread figure against the peer.
# Usage: perf/throughput/two_binaries_at_once.sh OLD_BIN NEW_BIN [ROUNDS] [END_TIME]
set -euo pipefail
old=${1:?usage: two_binaries_at_once.sh OLD_BIN NEW_BIN [ROUNDS] [END_TIME]}
new=${2:?usage: two_binaries_at_once.sh OLD_BIN NEW_BIN [ROUNDS] [END_TIME]}
rounds=${3:-6}
((rounds % 2 == 0)) || { echo "two_binaries_at_once.sh: ROUNDS must be even" >&2; exit 2; }
end=${4:-0.03}
root=$(cd "$(dirname "$0")/../.." && pwd)
case_file="$root/perf/cases/dam_break_2d_peer.toml"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((r = 1; r <= rounds; r++)); do
    a=$old b=$new
    ((r % 2 == 0)) && a=$new b=$old
    rm -rf "$work/a" "$work/b"
    taskset -c 0 "$a" run "$case_file" --threads 1 -q --out "$work/a" --set time.end_time="$end" >/dev/null &
    taskset -c 1 "$b" run "$case_file" --threads 1 -q --out "$work/b" --set time.end_time="$end" >/dev/null &
    wait
    if ((r % 2 == 0)); then
        mv "$work/a" "$work/new_$r" && mv "$work/b" "$work/old_$r"
    else
        mv "$work/a" "$work/old_$r" && mv "$work/b" "$work/new_$r"
    fi
done
python3 - "$work" "$rounds" <<'PY'
import json, statistics as st, sys
work, rounds = sys.argv[1], int(sys.argv[2])
stages = ["density", "walls", "accel", "kick", "drift"]
def load(path):
    d = json.load(open(f"{path}/summary.json"))
    n = d["steps"]
    busy = d["extra"]["stage_busy_seconds"]
    return d["wall_seconds"], {k: 1e3 * busy[k] / n for k in stages if k in busy}
ratios = {k: [] for k in ["wall"] + stages + ["step/walls"]}
for r in range(1, rounds + 1):
    (wo, so), (wn, sn) = load(f"{work}/old_{r}"), load(f"{work}/new_{r}")
    first = "old" if r % 2 else "new"
    print(f"round {r} ({first} on core 0): wall old {wo:.2f} s, new {wn:.2f} s; ms/step old/new "
          + ", ".join(f"{k} {so[k]:.3f}/{sn[k]:.3f}" for k in so))
    ratios["wall"].append(wn / wo)
    for k in so:
        ratios[k].append(sn[k] / so[k])
    if "walls" in so:
        ro, rn = sum(so.values()) / so["walls"], sum(sn.values()) / sn["walls"]
        print(f"         step/walls old {ro:.2f}, new {rn:.2f}")
        ratios["step/walls"].append(rn / ro)
print("RESULT geometric mean new/old over", rounds, "rounds (half with each binary on core 0): "
      + ", ".join(f"{k} {st.geometric_mean(v):.3f}" for k, v in ratios.items() if v))
PY
