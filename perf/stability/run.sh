#!/usr/bin/env bash
# Stability suite on hard cases (perf/stability/README.md): runs cases/hard/* (and Tak's (2024)
# debris box) and prints a PASS/FAIL line per rule; exit status 0 only if every rule passes.
# Usage: perf/stability/run.sh [--coarse] [--threads N] [--sluice EXE] [--out DIR]
#                              [--set KEY=VALUE ...] [CASE ...]
# CASE: rotating, mach, still_water, elliptical_drop, impact, debris_box (default: all).
# --coarse: the short versions the ctest entries run. --set applies to every run (to try an
# option, e.g. --set numerics.shifting=0). Rules and figures: perf/stability/README.md.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exec /usr/bin/python3 "$here/stability.py" "$@"
