#!/usr/bin/env bash
# The layer check itself (cmake/CheckLayers.cmake), so that it cannot rot silently: on
# tests/data/layers/good (only allowed includes) it passes; on tests/data/layers/bad it fails
# and names every offending file with its include (one per layer rule) and the one file that
# declares a namespace outside the convention.
# Usage: check_layers.sh <cmake> <source dir>
set -u
cmake=$1
src=$2
script=$src/cmake/CheckLayers.cmake
fixtures=$src/tests/data/layers
fail=0

if ! out=$("$cmake" -DSLUICE_LAYERS_ROOT="$fixtures/good" -P "$script" 2>&1); then
    echo "FAIL: the check refused the good fixture:"
    echo "$out"
    fail=1
fi

if out=$("$cmake" -DSLUICE_LAYERS_ROOT="$fixtures/bad" -P "$script" 2>&1); then
    echo "FAIL: the check passed the bad fixture"
    fail=1
fi
# cmake wraps long messages at spaces only; join the lines before matching.
joined=$(echo "$out" | tr -s ' \n' ' ')
for expected in \
    "include/sluice/core/grid.hpp includes sluice/physics/kernels.hpp" \
    "src/physics/eos.cpp includes sluice/io/case_config.hpp" \
    "include/sluice/io/summary.hpp includes sluice/solver/run.hpp" \
    "tasks/src/comm.cpp includes sluice/physics/eos.hpp" \
    "4 include(s) against the layers" \
    "include/sluice/physics/wmls.hpp declares namespace sluice::physics: the physics layer" \
    "and 1 namespace(s) against the convention"; do
    if [[ $joined != *"$expected"* ]]; then
        echo "FAIL: the refusal does not say: $expected"
        fail=1
    fi
done
# The allowed includes of the bad fixture are not reported.
for allowed in "includes sluice/core/types.hpp" "includes sluice/tasks/comm.hpp" \
    "includes sluice/io/case_config.hpp: the io" "declares namespace sluice::tasks" \
    "declares namespace fs"; do
    if [[ $joined == *"$allowed"* ]]; then
        echo "FAIL: an allowed include was reported: $allowed"
        fail=1
    fi
done
if ((fail)); then
    echo "--- output on the bad fixture:"
    echo "$out"
fi
exit $fail
