#!/usr/bin/env bash
# Speed against error (perf/README.md): error of four validation cases against core-seconds, over
# resolutions and scheme options. Options go to perf/speed_vs_error/sweep.py (--help):
#   perf/speed_vs_error/run.sh --quick --label "machine under load"   # coarse, minutes
#   perf/speed_vs_error/run.sh --cases dam_break --threads 2           # full sweep of one case
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
exec /usr/bin/python3 "$here/sweep.py" "$@"
