#!/usr/bin/env bash
# Remakes the pictures of docs/GALLERY.md: a coarse run of each shipped case (particle spacing
# doubled, some end times shortened), then scripts/plot. Each command is printed before it runs
# and is the one quoted in docs/GALLERY.md.
# Usage (from the repository root, after building sluice):
#   docs/gallery/make.sh [CASE ...]      CASE: the case's file stem, e.g. dam_break_2d
#   PLOTS_ONLY=1 docs/gallery/make.sh    reuse finished runs, remake only the PNGs
# Runs go to results/gallery/<case>/; the PNGs to docs/gallery/.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
SLUICE=${SLUICE:-./build/release/sluice}
OUT=results/gallery
PNG=docs/gallery

run() { # run CASE_FILE STEM --set ... : a quiet single-thread run, CPU seconds printed
    local file=$1 stem=$2
    shift 2
    echo "+ sluice run $file --out $OUT/$stem --threads 1 $*"
    if [ -n "${PLOTS_ONLY:-}" ] && [ -f "$OUT/$stem/summary.json" ]; then
        return # PLOTS_ONLY=1: keep a finished run, only remake its pictures
    fi
    rm -rf "${OUT:?}/$stem"
    /usr/bin/time -f "  $stem: %U s user + %S s system CPU, %e s wall" \
        nice -n 19 "$SLUICE" run "$file" --out "$OUT/$stem" --threads 1 --quiet "$@"
}
plot() { # plot SUBCOMMAND STEM PNG_NAME [options]: scripts/plot into a scratch folder, then rename
    local sub=$1 stem=$2 name=$3
    shift 3
    echo "+ scripts/plot $sub $OUT/$stem $*"
    rm -rf "$OUT/$stem/plots"
    scripts/plot "$sub" "$OUT/$stem" --out "$OUT/$stem/plots" "$@" >/dev/null
    local made
    made=$(ls "$OUT/$stem/plots"/*.png | grep -v front_reference | head -1)
    cp "$made" "$PNG/${stem}_$name.png"
    if [ -f "$OUT/$stem/plots/probes_front_reference.png" ]; then
        cp "$OUT/$stem/plots/probes_front_reference.png" "$PNG/${stem}_front_reference.png"
    fi
}

case_dam_break_2d() {
    run cases/dam_break_2d.toml dam_break_2d --set particles.dx=0.02
    plot snapshot dam_break_2d snapshot --time 0.6
    plot probes dam_break_2d probes
}
case_hydrostatic_2d() {
    run cases/hydrostatic_2d.toml hydrostatic_2d --set particles.dx=0.02
    plot snapshot hydrostatic_2d snapshot
    plot probes hydrostatic_2d probes --hydrostatic
}
case_poiseuille_2d() {
    run cases/poiseuille_2d.toml poiseuille_2d # case resolution: 40 particles across, 16 along
    plot snapshot poiseuille_2d snapshot --field velocity
}
case_taylor_green_2d() {
    run cases/taylor_green_2d.toml taylor_green_2d --set particles.dx=0.02
    plot snapshot taylor_green_2d snapshot --field velocity --time 0.5 --dpi 64
    plot history taylor_green_2d history
}
case_dam_break_3d() {
    run cases/dam_break_3d.toml dam_break_3d # case resolution dx = 0.02 m
    plot snapshot dam_break_3d snapshot --field velocity --time 0.3
    plot probes dam_break_3d probes
}
case_debris_box_3d() {
    run cases/debris_box_3d.toml debris_box_3d --set particles.dx=0.0263157894736842 \
        --set time.end_time=0.3 --set time.output_interval=0.02
    plot snapshot debris_box_3d snapshot --field velocity
}
case_dam_break_ramp_2d() {
    run cases/dam_break_ramp_2d.toml dam_break_ramp_2d # case resolution dx = 0.01 m
    plot snapshot dam_break_ramp_2d snapshot --time 0.6
    plot probes dam_break_ramp_2d probes
}
case_dam_break_mach() {
    run cases/hard/dam_break_mach.toml dam_break_mach --set particles.dx=0.02 --set time.end_time=0.3
    plot snapshot dam_break_mach snapshot
    plot probes dam_break_mach probes --reference tests/data/martin_moyce_1952_n2_2.csv
}
case_elliptical_drop() {
    run cases/hard/elliptical_drop.toml elliptical_drop --set particles.dx=0.05
    plot snapshot elliptical_drop snapshot
}
case_high_speed_impact() {
    run cases/hard/high_speed_impact.toml high_speed_impact --set particles.dx=0.01
    plot snapshot high_speed_impact snapshot --time 0.0055
    plot probes high_speed_impact probes
}
case_rotating_square_patch() {
    run cases/hard/rotating_square_patch.toml rotating_square_patch --set particles.dx=0.04
    plot snapshot rotating_square_patch snapshot
}
case_still_water_long() {
    run cases/hard/still_water_long.toml still_water_long --set particles.dx=0.02 --set time.end_time=5.0
    plot probes still_water_long probes --hydrostatic
    plot history still_water_long history
}

case_timeline() { # not a case: the task timeline of a 2-rank run of dam_break_2d
    echo "+ mpirun --oversubscribe -np 2 sluice run cases/dam_break_2d.toml --out $OUT/trace --threads 2 --set particles.dx=0.02 --set time.end_time=0.05 --trace $OUT/trace.json"
    if [ -z "${PLOTS_ONLY:-}" ] || [ ! -f "$OUT/trace.json" ]; then
        rm -rf "${OUT:?}/trace"
        nice -n 19 mpirun --oversubscribe -np 2 "$SLUICE" run cases/dam_break_2d.toml --out "$OUT/trace" \
            --threads 2 --quiet --set particles.dx=0.02 --set time.end_time=0.05 --trace "$OUT/trace.json"
    fi
    echo "+ scripts/plot timeline $OUT/trace.json --first-step 100"
    scripts/plot timeline "$OUT/trace.json" --first-step 100 --out "$OUT/trace_plots"
    cp "$OUT/trace_plots/trace_timeline.png" "$PNG/timeline_dam_break_2d_2_ranks.png"
    cp "$OUT/trace_plots/trace_busy.png" "$PNG/timeline_dam_break_2d_2_ranks_busy.png"
}

all=(dam_break_2d hydrostatic_2d poiseuille_2d taylor_green_2d dam_break_3d debris_box_3d
    dam_break_ramp_2d dam_break_mach elliptical_drop high_speed_impact rotating_square_patch still_water_long timeline)
mkdir -p "$OUT" "$PNG"
for c in "${@:-${all[@]}}"; do
    "case_$c"
done
