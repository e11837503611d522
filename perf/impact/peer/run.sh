#!/usr/bin/env bash
# The peer code (DualSPHysics v5.4 CPU) on sluice's wall-impact case: generates the case from
# zhou_2d_Def.xml (GenCase), runs it, and turns its gauges into a sluice-like run folder
# (peer_metrics.py): probes/<name>.csv as sluice writes them, then the first-impact figures.
#
# Usage: perf/impact/peer/run.sh [--name NAME] [--end T] [--threads N] [--out DIR]
#            [--set KEY=VALUE ...] [--const NAME=VALUE ...] [--dry-run]
#   --name     run label (default "peer"); the run goes to OUT/NAME (default OUT=/tmp/peer_impact)
#   --end      TimeMax in s (default 0.85: the first impact and 0.5 t* after it; 2.0 = the record)
#   --set      KEY=VALUE: the value of <parameter key="KEY"> (e.g. ViscoBoundFactor=0, Visco=0.02,
#              StepAlgorithm=1, Boundary=2); the key must exist in the XML
#   --const    NAME=VALUE: the value attribute of <NAME> in <constantsdef> (e.g. speedsound=97.04,
#              cflnumber=0.2); the element must exist in the XML
#   --example  the peer's own example settings (01_DamBreak/CaseDambreakVal2D_Def.xml): Verlet,
#              Visco 0.02, h = 1.0 sqrt(2) dp (coefh 1 instead of hdp 1.5); c0 stays 48.52 m/s
# Needs the peer built (PEER_DIR, default /tmp/peer; /work/shared/peer/build.sh makes it):
# $PEER_DIR/bin/GenCase and $PEER_DIR/bin/DualSPHysics5.4CPU_linux64.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
PEER=${PEER_DIR:-/tmp/peer}
name=peer; end=0.85; threads=2; out=/tmp/peer_impact; dry=0; example=0
sets=(); consts=()
while (($#)); do
  case $1 in
    --name) name=$2; shift 2 ;;
    --end) end=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --set) sets+=("$2"); shift 2 ;;
    --const) consts+=("$2"); shift 2 ;;
    --example) example=1; shift ;;
    --dry-run) dry=1; shift ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
solver=$PEER/bin/DualSPHysics5.4CPU_linux64; gencase=$PEER/bin/GenCase
for f in "$solver" "$gencase"; do
  [ -x "$f" ] || { echo "run.sh: $f missing: build the peer first (PEER_DIR=$PEER)" >&2; exit 2; }
done
if ((example)); then
  sets=(StepAlgorithm=1 Visco=0.02 "${sets[@]}")
fi

dir=$out/$name
rm -rf "$dir"; mkdir -p "$dir"
xml=$dir/Case_Def.xml
cp "$here/zhou_2d_Def.xml" "$xml"
for kv in "TimeMax=$end" "${sets[@]}"; do
  k=${kv%%=*}; v=${kv#*=}
  grep -qE "<parameter key=\"$k\" " "$xml" || { echo "run.sh: no <parameter key=\"$k\"> in the XML" >&2; exit 2; }
  sed -i -E "s|(<parameter key=\"$k\" value=\")[^\"]*|\1$v|" "$xml"
done
for kv in "${consts[@]}"; do
  k=${kv%%=*}; v=${kv#*=}
  grep -qE "<$k value=" "$xml" || { echo "run.sh: no <$k value=...> in <constantsdef>" >&2; exit 2; }
  sed -i -E "s|(<$k value=\")[^\"]*|\1$v|" "$xml"
done
if ((example)); then  # the example's smoothing length: coefh = 1 (h = sqrt(2) dp in 2-D)
  sed -i -E 's|<_coefh value=|<coefh value=|; s|<hdp value=|<_hdp value=|' "$xml"
fi
{ echo "name=$name end=$end threads=$threads example=$example"
  echo "set: ${sets[*]:-}"; echo "const: ${consts[*]:-}"; } >"$dir/peer_run.txt"
((dry)) && { echo "dry run: $xml"; exit 0; }

cd "$dir"
"$gencase" Case_Def Case -threads:"$threads" >gencase.log 2>&1 || { tail -20 gencase.log >&2; exit 1; }
[ -s Case.bi4 ] || { echo "run.sh: GenCase wrote no Case.bi4 in $dir" >&2; exit 1; }
s=$(date +%s.%N)
"$solver" Case out -cpu -ompthreads:"$threads" >run.log 2>&1 || { tail -20 run.log >&2; exit 1; }
e=$(date +%s.%N)
echo "wall_s=$(awk -v s="$s" -v e="$e" 'BEGIN{printf "%.1f", e-s}')" >>"$dir/peer_run.txt"
/usr/bin/python3 "$here/peer_metrics.py" "$dir"
