#!/usr/bin/env bash
# Runs one case on several R x T layouts with --trace and prints critical_path.py's summary of
# each (and its median step's chain). Usage:
#   perf/strong_scaling/critical_path_runs.sh OUT_DIR "1x2 2x1 4x1" CASE [sluice run args...]
# SLUICE (default build/release/sluice) is the binary; ranks run oversubscribed, unbound.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out=$1 layouts=$2
shift 2
exe=${SLUICE:-$here/../../build/release/sluice}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
for layout in $layouts; do
    r=${layout%x*} t=${layout#*x}
    launch=("$exe")
    ((r > 1)) && launch=(mpirun --oversubscribe --bind-to none -np "$r" "$exe")
    start=$(date +%s.%N)
    "${launch[@]}" run "$@" --threads "$t" -q --out "$out/$layout" --trace "$out/$layout.json"
    end=$(date +%s.%N)
    echo "== $layout ($(/usr/bin/python3 -c "print(f'{$end - $start:.1f}')") s to run)"
    /usr/bin/python3 "$here/critical_path.py" "$out/$layout.json" --latency 2e-6 --bandwidth 10e9 \
        --latency 20e-6 --bandwidth 1e9 | tee "$out/$layout.txt"
done
