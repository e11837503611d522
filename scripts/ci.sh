#!/usr/bin/env bash
# Everything CI runs (.ci/run), stage by stage, with the wall time of each:
#   release    scripts/check_product_text.sh (a second: the documentation and comments speak of
#              the software, not of how it was developed), then the README's test command
#              (scripts/test.sh): every test, Release build, with ParaView installed
#              (SLUICE_WITH_PARAVIEW=1, scripts/setup.sh) so that cli_paraview_snapshots runs
#              instead of skipping (SLUICE_WITH_PARAVIEW=0 leaves it out);
#   asan       AddressSanitizer + UndefinedBehaviorSanitizer: the unit tests listed in
#              asan_unit_tests (reading, output, checkpoints, the task runtime), the MPI unit
#              tests (halo exchange, migration on 3 ranks) and sluice's bad-input cli test;
#   asan-full  (not by default) asan plus every cli and mpi test, i.e. whole runs of sluice
#              under ASan: checkpoint/restart, SIGKILL, progress, plots, rank invariance, ...;
#   tsan       ThreadSanitizer: the runtime's unit tests (decomposition, graph sums) and the
#              proof that TSan sees a missing edge (below); no simulation code is built;
#   tsan-full  (not by default) tsan plus the solver's thread invariance and the MPI halo and
#              migration tests (label `runtime`);
#   fuzz       the case-reader fuzzer for 30 s and the shape-reader fuzzer for a third of that
#              (scripts/fuzz.sh; seconds: SLUICE_FUZZ_SECONDS),
#              built from the case reader's and the case checks' sources only.
# The *-full stages did not fit CI's 30 minutes (the numbers and the reason: perf/README.md,
# "CI stage times"); run them with `bash scripts/ci.sh asan-full tsan-full`.
#
# ThreadSanitizer: Debian's oneTBB is not built with -fsanitize=thread, so the step graph tells
# TSan its declared dependency edges itself (tasks/src/tsan_sync.hpp); TSan then checks that
# those edges order every conflicting access of the node bodies. That it does is a test:
# tsan_missing_edge_is_reported runs a graph with a neighbourhood edge left out and passes only
# if TSan reports the race (tests/tsan/missing_edge.cpp). Suppressions, each explained:
# tests/tsan.supp. The sanitizer presets build with line tables only, as unity builds, tsan at
# -O1 and asan at -O0 (its build took most of the stage; test_graph_neighbour_sums keeps -O1),
# and each stage builds only the targets it runs (CMakePresets.json).
# Usage: scripts/ci.sh [stage...]   (default: release asan tsan fuzz). Stops at the first stage
# that fails; prints the timings either way.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
stages=("$@")
((${#stages[@]})) || stages=(release asan tsan fuzz)

# Unit tests of the code that owns memory, files, threads and messages (case reading, output,
# checkpoints, the task runtime); the numerical kernels' unit tests run in the Release stage.
asan_unit_tests=(test_case_reader test_case_check test_checkpoint test_snapshot_writer
                 test_probes test_progress test_state_check test_decomposition test_rank_layout
                 test_graph_neighbour_sums test_convex_hull_3d test_wmls test_halo_wiring
                 test_migration test_step_agreement test_contact_world)
asan_tests="^(cli_bad_input|$(IFS='|'; echo "${asan_unit_tests[*]}"))\$"
asan_full_tests="^(cli_.*|mpi_.*|$(IFS='|'; echo "${asan_unit_tests[*]}"))\$"
tsan_targets=(test_decomposition test_rank_layout test_graph_neighbour_sums test_balance_policy
              tsan_missing_edge)
tsan_tests="^(test_decomposition|test_rank_layout|test_graph_neighbour_sums|test_balance_policy|tsan_.*)\$"
tsan_full_targets=("${tsan_targets[@]}" test_thread_invariance test_halo_wiring test_migration
                   test_step_agreement)

run_stage() {
    case "$1" in
    release)
        bash scripts/check_product_text.sh &&
            SLUICE_WITH_PARAVIEW="${SLUICE_WITH_PARAVIEW:-1}" bash scripts/test.sh
        ;;
    asan)
        bash scripts/setup.sh asan sluice "${asan_unit_tests[@]}" &&
            ctest --preset asan -R "$asan_tests"
        ;;
    asan-full)
        bash scripts/setup.sh asan sluice "${asan_unit_tests[@]}" &&
            ctest --preset asan -R "$asan_full_tests"
        ;;
    tsan) bash scripts/setup.sh tsan "${tsan_targets[@]}" && ctest --preset tsan -R "$tsan_tests" ;;
    tsan-full)
        bash scripts/setup.sh tsan "${tsan_full_targets[@]}" && ctest --preset tsan -L runtime
        ;;
    fuzz) bash scripts/fuzz.sh "${SLUICE_FUZZ_SECONDS:-30}" ;;
    *)
        echo "ci: unknown stage '$1' (release, asan, asan-full, tsan, tsan-full, fuzz)"
        return 2
        ;;
    esac
}

report=()
status=0
total_start=$(date +%s)
for s in "${stages[@]}"; do
    echo "=== ci: stage $s"
    start=$(date +%s)
    run_stage "$s"
    rc=$?
    report+=("$(printf '%-8s %5d s  %s' "$s" $(($(date +%s) - start)) "$([ $rc -eq 0 ] && echo ok || echo "FAILED ($rc)")")")
    if [ $rc -ne 0 ]; then
        status=$rc
        break
    fi
done
echo "=== ci: stage timings ($(nproc) cores)"
printf '%s\n' "${report[@]}"
echo "total    $(($(date +%s) - total_start)) s"
exit $status
