#!/usr/bin/env bash
# The commands of docs/TUTORIAL_WALL_LOADS.md, "Your first wall-load study", in its order: one
# run of cases/wall_impact_2d.toml with its plots and first-impact peaks, a jitter ensemble, a
# resolution ladder, and the grid convergence index. The document quotes each block between a
# "# tutorial:NAME" line and "# tutorial:end" verbatim; tests/cli/tutorial_wall_loads.sh checks
# that it does and runs this script with --coarse, so the two cannot drift apart.
#
# Usage (from anywhere; paths are taken from the repository root, and must hold no spaces):
#   scripts/tutorial_wall_loads.sh [--coarse] [--sluice EXE] [--out DIR] [--threads N]
#   --coarse   the test's settings, seconds on one core: dx = H/10 (the case, copied into DIR
#              with that dx), a ladder of H/5 and H/20, two ensemble members (jitter 0, 0.01)
# Without --coarse: about 7 minutes on one core of the 2-core development machine.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

# tutorial:settings
sluice=./build/release/sluice
case=cases/wall_impact_2d.toml         # dx = H/40 (H = 0.3 m)
out=results/wall_impact
threads=1                              # per run
jitters="0 0.002 0.005 0.01"           # particles.jitter of the ensemble's four runs
ladder="0.015 0.00375"                 # dx of the other two resolutions: H/20 and H/80
# tutorial:end

coarse=0
while (($#)); do
    case $1 in
    --coarse) coarse=1 ;;
    --sluice) sluice=$2 && shift ;;
    --out) out=$2 && shift ;;
    --threads) threads=$2 && shift ;;
    *) echo "usage: $0 [--coarse] [--sluice EXE] [--out DIR] [--threads N]" >&2 && exit 2 ;;
    esac
    shift
done
if ((coarse)); then
    mkdir -p "$out"
    sed 's/^dx = 0\.0075 .*/dx = 0.03/' "$case" >"$out/wall_impact_2d_coarse.toml"
    grep -q '^dx = 0.03$' "$out/wall_impact_2d_coarse.toml" ||
        { echo "$0: no 'dx = 0.0075' line in $case to coarsen" >&2 && exit 1; }
    case=$out/wall_impact_2d_coarse.toml
    jitters="0 0.01"
    ladder="0.06 0.015"
fi

# tutorial:run
$sluice run $case --threads $threads --out $out/first
scripts/plot probes $out/first
scripts/loads peaks $out/first
# tutorial:end

# tutorial:ensemble
for j in $jitters; do
    $sluice run $case --threads $threads --set particles.jitter=$j \
        --set output.snapshots=false --out $out/ensemble/j$j
done
scripts/loads ensemble $out/ensemble --csv $out/ensemble.csv
# tutorial:end

# tutorial:ladder
for dx in $ladder; do
    for j in $jitters; do
        $sluice run $case --threads $threads --set particles.dx=$dx --set particles.jitter=$j \
            --set output.snapshots=false --out $out/ladder/dx$dx/j$j
    done
done
scripts/loads gci $out/ensemble $out/ladder/* --csv $out/gci.csv
# tutorial:end
