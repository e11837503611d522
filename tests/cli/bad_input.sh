#!/usr/bin/env bash
# Broken case files are refused with exit code 2, a message naming the file and the key, and no
# results folder. Usage: bad_input.sh <sluice executable> <source dir>
set -u

exe=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0

fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

cat >valid.toml <<'EOF'
[case]
name = "valid"
dimension = 2

[domain]
lo = [0, 0]
hi = [2, 1]

[fluid]
rho0 = 1000
viscosity = 0
sound_speed = 20

[particles]
dx = 0.02

[[blocks]]
lo = [0, 0]
hi = [0.5, 0.5]

[numerics]
h_over_dx = 1.3

[time]
end_time = 0.4
EOF

# make_case NAME SED-EXPRESSION: a copy of valid.toml with one edit.
make_case() {
    sed "$2" valid.toml >"$1.toml"
}

# expect_refused NAME EXPECTED-KEY-TEXT [sluice args...]
expect_refused() {
    local name=$1 key=$2
    shift 2
    "$exe" run "$name.toml" "$@" >out.txt 2>err.txt
    local rc=$?
    [ "$rc" -eq 2 ] || fail "$name: exit code $rc, expected 2 ($(cat err.txt))"
    grep -q "$name.toml" err.txt || fail "$name: stderr does not name the file: $(cat err.txt)"
    grep -q -- "$key" err.txt || fail "$name: stderr does not name '$key': $(cat err.txt)"
    grep -q "^sluice: error: " err.txt || fail "$name: no 'sluice: error:' prefix: $(cat err.txt)"
    [ ! -e results ] || fail "$name: a results folder was created"
    rm -rf results
}

make_case syntax 's/^rho0 = 1000$/rho0 = = 1000/'
expect_refused syntax "line 10"

make_case unknown_key 's/^h_over_dx = 1.3$/h_over_dxx = 1.3/'
expect_refused unknown_key "numerics.h_over_dxx"

make_case wrong_type 's/^rho0 = 1000$/rho0 = "heavy"/'
expect_refused wrong_type "fluid.rho0"

make_case missing_key '/^sound_speed = 20$/d'
expect_refused missing_key "fluid.sound_speed"

make_case bad_h 's/^h_over_dx = 1.3$/h_over_dx = 0/'
expect_refused bad_h "numerics.h_over_dx"

make_case negative_rho 's/^rho0 = 1000$/rho0 = -1000/'
expect_refused negative_rho "fluid.rho0"

make_case block_outside 's/^hi = \[0.5, 0.5\]$/hi = [0.5, 1.5]/'
expect_refused block_outside "blocks\[0\].hi"

make_case end_time 's/^end_time = 0.4$/end_time = 0/'
expect_refused end_time "time.end_time"

# The scheme and the projection settings (docs/CASE_REFERENCE.md, [projection]).
cp valid.toml scheme.toml
expect_refused scheme "numerics.scheme" --set 'numerics.scheme="incompressible"'
cp valid.toml projection_key.toml
expect_refused projection_key "projection.gamma" --set projection.gamma=0.5
cp valid.toml projection_gamma.toml
expect_refused projection_gamma "projection.gamma" --set 'numerics.scheme="projection"' \
    --set projection.gamma=2
cp valid.toml projection_solver.toml
expect_refused projection_solver "projection.solver" --set 'numerics.scheme="projection"' \
    --set 'projection.solver="cg"'
cp valid.toml projection_relaxation.toml
expect_refused projection_relaxation "projection.relaxation" \
    --set 'numerics.scheme="projection"' --set projection.relaxation=1.2
cp valid.toml projection_beta.toml
expect_refused projection_beta "projection.surface_density_ratio" \
    --set 'numerics.scheme="projection"' --set projection.surface_density_ratio=1.5
cp valid.toml projection_gradient.toml
expect_refused projection_gradient "projection.correction_gradient" \
    --set 'numerics.scheme="projection"' --set 'projection.correction_gradient="third"'
cp valid.toml projection_collision.toml
expect_refused projection_collision "projection.fluid_collision" \
    --set 'numerics.scheme="projection"' --set projection.fluid_collision=1

# Keys of the WCSPH equation of state, density and wall velocity, which the projection scheme
# ignores, are refused under it, naming the key.
for kv in 'fluid.eos="tait"' fluid.gamma=7 'numerics.density="summation"' walls.no_slip=false \
    limits.min_density=10 limits.max_density=2000; do
    key=${kv%%=*}
    name=projection_${key//./_}
    cp valid.toml "$name.toml"
    expect_refused "$name" "$key" --set 'numerics.scheme="projection"' --set "$kv"
done

# A bad override is refused the same way.
cp valid.toml override.toml
expect_refused override "numerics.kernal" --set numerics.kernal=quintic

# The wall-load instruments (force probes, area sensors, every_step, directed fronts): `sluice run` refuses them before writing anything.
walls='[walls]\nmodel = "dummy"\ntank_lo = [0, 0]\ntank_hi = [1.5, 1]\ntank_faces = ["x-", "x+", "y-"]\n'
probe() { printf "$walls\n[[probes]]\nname = \"p\"\n%b\n" "$1" | cat valid.toml - >"$2.toml"; }
probe 'type = "force"\nface = "x+"\nhi = [1.0, 1.0]' force_off_wall
expect_refused force_off_wall "probes\[0\].hi"
probe 'type = "pressure"\nposition = [0.7, 0.3]\ndiameter = 0.02' sensor_off_wall
expect_refused sensor_off_wall "probes\[0\].position"
probe 'type = "pressure"\nposition = [1.5, 0.3]\ndiameter = -0.02' sensor_negative
expect_refused sensor_negative "probes\[0\].diameter"
probe 'type = "water_level"\nx = 1.8' gauge_outside_tank
expect_refused gauge_outside_tank "probes\[0\].x"
# The projection scheme has no pair forces: a force probe integrates the interpolated pressure
# there, and asking it for the pair-force reading is refused.
probe 'type = "force"\nface = "x+"\nreading = "force"' force_reading_projection
expect_refused force_reading_projection "probes\[0\].reading" --set 'numerics.scheme="projection"'
probe 'type = "force"\nface = "x+"\nreading = "pressure"' force_reading_unknown
expect_refused force_reading_unknown "probes\[0\].reading"

# Outputs the run could not write are refused before it starts: exit code 2, a message naming
# the option and the path, and nothing written (the working folder as it was).
# expect_unwritable NAME OPTION-AND-PATH [sluice args...]
touch plain_file
expect_unwritable() {
    local name=$1 option=$2
    shift 2
    local before
    before=$(ls -A)
    "$exe" run valid.toml "$@" >"$work.out" 2>"$work.err"
    local rc=$?
    [ "$rc" -eq 2 ] || fail "$name: exit code $rc, expected 2 ($(cat "$work.err"))"
    grep -q "^sluice: error: option $option: cannot be written: " "$work.err" ||
        fail "$name: stderr does not name $option: $(cat "$work.err")"
    [ "$(ls -A)" = "$before" ] || fail "$name: something was written: $(ls -A)"
    [ ! -s plain_file ] || fail "$name: plain_file was written to"
    rm -f "$work.out" "$work.err"
}
expect_unwritable out_proc "--out '/proc/sluice_out'" --out /proc/sluice_out
expect_unwritable out_under_file "--out 'plain_file/out'" --out plain_file/out
expect_unwritable trace_proc "--trace '/proc/x.json'" --out ok --trace /proc/x.json
expect_unwritable trace_no_folder "--trace 'no_folder/x.json'" --trace no_folder/x.json

# A missing file is a case error too.
"$exe" run missing.toml >/dev/null 2>err.txt
rc=$?
[ "$rc" -eq 2 ] || fail "missing file: exit code $rc, expected 2"
grep -q "missing.toml" err.txt || fail "missing file: stderr does not name it: $(cat err.txt)"
[ ! -e results ] || fail "missing file: a results folder was created"

# Command-line usage.
"$exe" --version >out.txt 2>&1
rc=$?
[ "$rc" -eq 0 ] || fail "--version: exit code $rc"
grep -q "^sluice " out.txt || fail "--version prints: $(cat out.txt)"

"$exe" run >/dev/null 2>&1
rc=$?
[ "$rc" -eq 2 ] || fail "run without a case file: exit code $rc, expected 2"

"$exe" >/dev/null 2>&1
rc=$?
[ "$rc" -eq 2 ] || fail "no subcommand: exit code $rc, expected 2"

"$exe" run valid.toml --no-such-option >/dev/null 2>&1
rc=$?
[ "$rc" -eq 2 ] || fail "unknown option: exit code $rc, expected 2"
[ ! -e results ] || fail "unknown option: a results folder was created"

"$exe" --help >/dev/null 2>&1
rc=$?
[ "$rc" -eq 0 ] || fail "--help: exit code $rc"

if [ "$failures" -ne 0 ]; then
    echo "$failures check(s) failed"
    exit 1
fi
echo "all CLI bad-input checks passed"
