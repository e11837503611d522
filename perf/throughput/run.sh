#!/usr/bin/env bash
# Throughput benchmark (perf/README.md): particle-steps per second (whole steps, I/O off), per core,
# per stage with achieved neighbour interactions, and memory per particle, for the fixed
# configurations in perf/cases/; --scaling adds time per step against N (10^4 ... 10^6).
# All options are passed to perf/throughput/throughput.py (run with --help for the list):
#   perf/throughput/run.sh --short                  # a few steps of each configuration
#   perf/throughput/run.sh --configs 1 --threads 2  # configuration 1 in full
#   perf/throughput/run.sh --scaling-only           # time per step against N
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exec /usr/bin/python3 "$here/throughput.py" "$@"
