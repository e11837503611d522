#!/usr/bin/env bash
# Refusals from the memory estimate per rank (CASE_REFERENCE.md, [particles], "Size limits"): a
# 3-D dam break of 2e8 fluid particles fits 64 ranks of 24 GiB and is refused on one rank,
# naming the file and particles.dx; the estimate per rank falls with the rank count; --max-memory
# is read (a limit below the process itself refuses the default case) and checked; a hostile
# size (1e15 particles) is still refused at once by the reader.
# Usage: memory_limits.sh SLUICE_EXE SOURCE_DIR
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../lib/script_args.sh"
cd "$work"
# 10 m x 4 m x 5 m of water at dx = 0.01 m: 1000 x 400 x 500 = 2e8 particles, in a 20 x 4 x 6 m
# tank with dummy walls.
cat >big.toml <<'TOML'
[case]
dimension = 3
[domain]
lo = [0.0, 0.0, 0.0]
hi = [20.0, 4.0, 6.0]
[fluid]
rho0 = 1000.0
viscosity = 1.0e-3
sound_speed = 100.0
gravity = [0.0, 0.0, -9.81]
[particles]
dx = 0.01
[[blocks]]
lo = [0.0, 0.0, 0.0]
hi = [10.0, 4.0, 5.0]
[numerics]
kernel = "wendland_c2"
h_over_dx = 1.5
[walls]
model = "dummy"
tank_lo = [0.0, 0.0, 0.0]
tank_hi = [20.0, 4.0, 6.0]
tank_faces = ["x-", "x+", "y-", "y+", "z-"]
[time]
end_time = 1.0
TOML

# expect RC NAME COMMAND...: the exit code, and for 2 big.toml and its key in the message.
expect() {
    local want=$1 name=$2
    shift 2
    local rc=0
    timeout 20 "$@" >"$name.out" 2>"$name.err" || rc=$?
    [ "$rc" -eq "$want" ] || fail "$name: exit code $rc, expected $want: $(cat "$name.err")"
    if [ "$want" -eq 2 ]; then
        grep -q "big.toml: key 'particles.dx'" "$name.err" ||
            fail "$name: no file and key in: $(cat "$name.err")"
    fi
}

expect 0 fits_64 "$exe" check big.toml --ranks 64 --max-memory 24GiB
grep -q "big.toml: ok (2" fits_64.out || fail "fits_64: $(cat fits_64.out)"
expect 2 one_rank "$exe" check big.toml --max-memory 24GiB
grep -q "on 1 rank the busiest rank would need about" one_rank.err ||
    fail "one_rank: no estimate in: $(cat one_rank.err)"
# Without --max-memory: this machine's memory, which no machine has for one rank of 2e8.
expect 2 one_rank_machine "$exe" check big.toml
grep -q "MemTotal" one_rank_machine.err || fail "one_rank_machine: $(cat one_rank_machine.err)"
expect 2 info_one_rank "$exe" info big.toml --max-memory 24GiB

# The estimate per rank, in MiB, from `sluice info --ranks R`.
per_rank() {
    "$exe" info big.toml --ranks "$1" --max-memory 1TiB |
        awk '/^memory/ { v = substr($2, 2); u = $3;
             print (u == "GiB" ? v * 1024 : u == "TiB" ? v * 1048576 : v) }'
}
m16=$(per_rank 16)
m64=$(per_rank 64)
awk -v a="$m16" -v b="$m64" 'BEGIN { exit !(b < a && a > 0) }' ||
    fail "estimate per rank does not fall from 16 to 64 ranks: $m16 MiB, $m64 MiB"
"$exe" info big.toml --ranks 64 --max-memory 1TiB >terms.out
for term in process particles halo totals grid; do
    grep -q "^  $term " terms.out || fail "info --ranks 64 lacks the $term term: $(cat terms.out)"
done

# --max-memory is used: the default case fits 1 GiB and not 1 MiB; a bad size is a bad
# command line.
default="$src/cases/dam_break_2d.toml"
"$exe" check "$default" --max-memory 1GiB >/dev/null || fail "the default case does not fit 1 GiB"
rc=0
"$exe" check "$default" --max-memory 1MiB 2>tiny.err || rc=$?
[ "$rc" -eq 2 ] && grep -q "dam_break_2d.toml: key 'particles.dx'" tiny.err &&
    grep -q -- "--max-memory 1.0 MiB" tiny.err || fail "1 MiB limit: rc $rc, $(cat tiny.err)"
rc=0
"$exe" check "$default" --max-memory 4GB/s 2>bad.err || rc=$?
[ "$rc" -eq 2 ] && grep -q "max-memory" bad.err || fail "bad size: rc $rc, $(cat bad.err)"

# Hostile input: 1e15 particles refused by the reader, quickly, naming the key.
sed 's/^dx = 0.01$/dx = 0.00002/' big.toml >hostile.toml
start=$(date +%s%N)
rc=0
"$exe" check hostile.toml --ranks 16777216 --max-memory 1000TiB 2>hostile.err || rc=$?
ms=$((($(date +%s%N) - start) / 1000000))
[ "$rc" -eq 2 ] && grep -q "hostile.toml: key 'particles.dx'" hostile.err &&
    grep -q "beyond any machine" hostile.err || fail "hostile: rc $rc, $(cat hostile.err)"
[ "$ms" -lt 5000 ] || fail "hostile: refused after $ms ms"
exit $failures
