#!/usr/bin/env bash
# Runs tests/tsan/missing_edge.cpp's executable with a missing graph edge and passes only if
# ThreadSanitizer's first report is the data race in missing_edge.cpp itself.
# Usage: expect_race.sh EXECUTABLE
set -uo pipefail
out="$(TSAN_OPTIONS="${TSAN_OPTIONS:-} halt_on_error=1 exitcode=66" "$1" missing 2>&1)"
rc=$?
if [ $rc -eq 66 ] && grep -q "SUMMARY: ThreadSanitizer: data race .*missing_edge.cpp" <<<"$out"; then
    echo "expect_race: ThreadSanitizer reported the missing edge, as it must"
    exit 0
fi
echo "$out"
echo "expect_race: no ThreadSanitizer report of the missing edge (exit code $rc)"
exit 1
