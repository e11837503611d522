#!/usr/bin/env bash
# Wall-impact pressure convergence study (perf/impact/README.md): Zhou/Buchner dam break over resolutions
# x sound speeds x variants, then the analysis. Options go to perf/impact/study.py (--help):
#   perf/impact/run.sh --quick                                  # H/30, H/60 x c0 20, 40
#   perf/impact/run.sh --jobs 2 --variant riemann:numerics.x=y  # full matrix, two variants
#   perf/impact/analyse.py perf/impact/results                  # re-analyse existing runs
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exec /usr/bin/python3 "$here/study.py" "$@"
