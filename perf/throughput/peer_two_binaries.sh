#!/usr/bin/env bash
# Configuration 1 (perf/cases/dam_break_2d_peer.toml) side by side in one window: the peer
# (DualSPHysics CPU, ../shared/peer/run.sh) and two sluice binaries, interleaved round by round
# (peer, OLD, NEW), 2 threads each, whole-process wall time; then the medians and the ratios
# peer/OLD, peer/NEW and OLD/NEW. ../shared/peer/versus.sh does the same for one binary; a
# speed claim is a ratio measured beside the previous binary and the peer (perf/README.md).
# Usage: perf/throughput/peer_two_binaries.sh OLD_BIN NEW_BIN [ROUNDS] [THREADS]
# Run from the project checkout; needs the peer built (../shared/peer/README).
set -euo pipefail
old=${1:?usage: peer_two_binaries.sh OLD_BIN NEW_BIN [ROUNDS] [THREADS]}
new=${2:?usage: peer_two_binaries.sh OLD_BIN NEW_BIN [ROUNDS] [THREADS]}
rounds=${3:-3}
threads=${4:-2}
root=$(cd "$(dirname "$0")/../.." && pwd)
peer_run="$root/../shared/peer/run.sh"
[[ -f $peer_run ]] || { echo "peer_two_binaries.sh: $peer_run not found" >&2; exit 2; }
case_file="$root/perf/cases/dam_break_2d_peer.toml"
wall() { # binary -> whole-process wall seconds
    local o s e
    o=$(mktemp -d)
    s=$(date +%s.%N)
    "$1" run "$case_file" --threads "$threads" -q --out "$o" >/dev/null
    e=$(date +%s.%N)
    rm -rf "$o"
    python3 -c "print(f'{$e - $s:.3f}')"
}
peer=() olds=() news=()
for ((r = 1; r <= rounds; r++)); do
    p=$(bash "$peer_run" case2d "$threads" | sed -nE 's/.* wall_s=([0-9.]+).*/\1/p')
    a=$(wall "$old")
    b=$(wall "$new")
    echo "round $r: peer $p s, old $a s, new $b s"
    peer+=("$p") olds+=("$a") news+=("$b")
done
python3 - "${peer[*]}" "${olds[*]}" "${news[*]}" <<'PY'
import statistics as st, sys
p, a, b = ([float(x) for x in s.split()] for s in sys.argv[1:4])
mp, ma, mb = st.median(p), st.median(a), st.median(b)
print(f"RESULT configuration 1: peer median {mp:.1f} s, old {ma:.1f} s, new {mb:.1f} s; "
      f"peer/old {mp / ma:.2f}x, peer/new {mp / mb:.2f}x, old/new {ma / mb:.3f} "
      f"(per round peer/new: {', '.join(f'{x / y:.2f}' for x, y in zip(p, b))})")
PY
