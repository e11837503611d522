#!/usr/bin/env bash
# What --trace costs: the same run with and without it, interleaved, ROUNDS rounds, and
# optionally a second binary without it (BASE: e.g. a build of the commit before a trace
# change, to see that the runtime's recording costs nothing when tracing is off). Prints each
# run's wall_seconds (summary.json: the time loop) and the medians.
# Usage: perf/strong_scaling/trace_overhead.sh SLUICE RANKS ROUNDS [BASE] -- CASE [sluice run args]
set -euo pipefail
exe=$(realpath "$1") ranks=$2 rounds=$3
shift 3
base=""
[[ $1 != -- ]] && { base=$(realpath "$1"); shift; }
shift # --
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=("$@")
declare -A walls
kinds=(off on)
[[ -n $base ]] && kinds=(base off on)
for ((k = 0; k < rounds; k++)); do
    for kind in "${kinds[@]}"; do
        bin=$exe extra=()
        [[ $kind == base ]] && bin=$base
        [[ $kind == on ]] && extra=(--trace "$work/t.json")
        launch=("$bin")
        ((ranks > 1)) && launch=(mpirun --oversubscribe --bind-to none -np "$ranks" "$bin")
        "${launch[@]}" run "${args[@]}" -q --out "$work/$kind" "${extra[@]}" >/dev/null
        w=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['wall_seconds'])" \
            "$work/$kind/summary.json")
        walls[$kind]+="$w "
        echo "round $k $kind: $w s"
    done
done
for kind in "${kinds[@]}"; do
    /usr/bin/python3 -c "import statistics,sys; x=[float(v) for v in sys.argv[2:]]; print(f'{sys.argv[1]:5s} median {statistics.median(x):.3f} s  ({len(x)} runs: ' + ', '.join(f'{v:.3f}' for v in x) + ')')" \
        "$kind" ${walls[$kind]}
done
[[ -f $work/t.json ]] && echo "trace: $(stat -c %s "$work/t.json") bytes"
