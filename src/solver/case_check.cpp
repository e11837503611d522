// Checks and advice on a validated case, derived from the configuration alone (no particles).
#include "sluice/solver/case_check.hpp"
#include "sluice/solver/motion_check.hpp"
#include "sluice/solver/numerics_advice.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/physics/initial_profiles.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/physics/timestep.hpp"
#include "sluice/solver/built_geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace sluice {
namespace {

// A box moved by a wave-maker: a paddle, whatever its thickness.
bool is_paddle(const CaseConfig& cfg, int motion) {
    if (motion < 0)
        return false;
    const MotionKind k = cfg.motions[static_cast<std::size_t>(motion)].kind;
    return k == MotionKind::piston || k == MotionKind::flap || k == MotionKind::piston_irregular;
}

constexpr const char* kAxis = "xyz";

// Lowest and highest value of up . x over the corners of the box [lo, hi].
std::pair<double, double> height_range(const Triple& lo, const Triple& hi, const Triple& up,
                                       int dim) {
    double low = 0, high = 0;
    for (std::size_t a = 0; a < static_cast<std::size_t>(dim); ++a) {
        low += std::min(up[a] * lo[a], up[a] * hi[a]);
        high += std::max(up[a] * lo[a], up[a] * hi[a]);
    }
    return {low, high};
}

// The key whose value sets the time step a run starts with.
const char* time_step_key(const CaseConfig& cfg, const CaseInfo& info) {
    if (cfg.fixed_dt)
        return "numerics.dt";
    if (info.dt_estimate == info.dt_acoustic)
        return "numerics.cfl";
    if (info.dt_estimate == info.dt_viscous)
        return "numerics.viscous_cfl";
    return "numerics.force_cfl";
}

// Every step must move the clock towards time.end_time. A limit can underflow to zero (a CFL
// factor of 1e-320), be infinite (the projection scheme, whose CFL limit has no sound speed,
// with the fluid at rest and neither gravity nor viscosity: nothing limits the step), or be
// below end_time's resolution (t + dt == t): each would make the run spin or jump past the end.
void check_clock_advances(const CaseConfig& cfg, const CaseInfo& info) {
    const double dt = info.dt_estimate;
    if (!std::isfinite(dt))
        throw CaseError(cfg.source_file, "numerics.dt",
                        "nothing limits the time step (no sound speed in the projection "
                        "scheme's CFL limit, the fluid at rest, no gravity, no viscosity): give "
                        "a fixed numerics.dt");
    if (step_advances_clock(cfg.end_time, dt))
        return;
    const bool end_too_far = dt >= min_useful_dt;
    throw CaseError(cfg.source_file, end_too_far ? "time.end_time" : time_step_key(cfg, info),
                    fmt::format("a time step of {:.4g} s (acoustic {:.4g} s, viscous {:.4g} s, "
                                "force {:.4g} s) cannot advance the clock to time.end_time = "
                                "{:.6g} s",
                                dt, info.dt_acoustic, info.dt_viscous, info.dt_force,
                                cfg.end_time));
}

} // namespace

void check_runnable(const CaseConfig& cfg, const CaseInfo& info) {
    // The projection scheme's geometry (convex hulls, WMLS rank tests, the BiCGSTAB solve to
    // 1e-8) works with tolerances below single precision's resolution; it is validated in
    // double only (docs/ARCHITECTURE.md, "Dimension and precision").
    if (single_precision && cfg.scheme == Scheme::projection)
        throw CaseError(cfg.source_file, "numerics.scheme",
                        "the projection scheme needs a double-precision build of sluice (this "
                        "one was built with SLUICE_PRECISION=float)");
    for (std::size_t a = 0; a < static_cast<std::size_t>(cfg.dimension); ++a)
        if (cfg.periodic[a] && (cfg.domain_hi[a] - cfg.domain_lo[a]) < 3 * info.support)
            throw CaseError(cfg.source_file, "domain.periodic",
                            fmt::format("the periodic {} axis is {:.4g} m long, shorter than "
                                        "three kernel supports (3 x {:.4g} m)",
                                        kAxis[a], cfg.domain_hi[a] - cfg.domain_lo[a],
                                        info.support));
    // Same test as the solver's (Simulation), with the fastest initial speed of the blocks.
    if (cfg.fixed_dt && *cfg.fixed_dt > info.dt_stable)
        throw CaseError(cfg.source_file, "numerics.dt",
                        fmt::format("fixed time step {:.4g} s exceeds the stability limit {:.4g} s "
                                    "(acoustic {:.4g} s, viscous {:.4g} s, force {:.4g} s); "
                                    "remove numerics.dt to let the solver choose",
                                    *cfg.fixed_dt, info.dt_stable, info.dt_acoustic,
                                    info.dt_viscous, info.dt_force));
    check_clock_advances(cfg, info);
    if (!cfg.motions.empty())
        check_motion_paths(cfg, wall_layers(info.support, cfg.dx));
}

std::vector<CaseWarning> case_warnings(const CaseConfig& cfg, const CaseInfo& info) {
    std::vector<CaseWarning> out = motion_warnings(cfg);
    for (CaseWarning& w : numerics_warnings(cfg))
        out.push_back(std::move(w));
    const auto dim = static_cast<std::size_t>(cfg.dimension);

    const BuiltGeometry built = built_geometry(cfg, wall_layers(info.support, cfg.dx));

    // Resolution: the smallest fluid block extent (as built), tank dimension or obstacle extent
    // over dx. Periodic axes have no feature to resolve.
    double smallest = std::numeric_limits<double>::infinity();
    std::string what;
    auto consider = [&](double extent, const std::string& name) {
        if (extent < smallest) {
            smallest = extent;
            what = name;
        }
    };
    for (std::size_t a = 0; a < dim; ++a) {
        if (cfg.periodic[a])
            continue;
        for (std::size_t i = 0; i < cfg.blocks.size(); ++i)
            consider(std::min(cfg.blocks[i].hi[a], built.blocks[i].hi[a]) - cfg.blocks[i].lo[a],
                     fmt::format("blocks[{}] along {}", i, kAxis[a]));
        if (cfg.walls != WallModel::none)
            consider(cfg.tank_hi[a] - cfg.tank_lo[a], fmt::format("the tank along {}", kAxis[a]));
        // An obstacle's size sets the flow features around it (its wake, the run-up on its
        // face), so the same 20 particles apply; a wave-maker's paddle is a wall, not one.
        for (std::size_t i = 0; i < cfg.boxes.size(); ++i)
            if (!is_paddle(cfg, cfg.boxes[i].motion))
                consider(cfg.boxes[i].hi[a] - cfg.boxes[i].lo[a],
                         fmt::format("walls.boxes[{}] along {}", i, kAxis[a]));
    }
    if (std::isfinite(smallest) && smallest / cfg.dx < min_particles_across)
        out.push_back({"particles.dx",
                       fmt::format("only {:.3g} particles across {} ({:.4g} m / dx = {:.4g} m); "
                                   "fewer than ~{:.0f} resolve it poorly (inaccurate): dx <= "
                                   "{:.3g} m gives {:.0f}",
                                   smallest / cfg.dx, what, smallest, cfg.dx, min_particles_across,
                                   smallest / min_particles_across, min_particles_across)});

    // Geometry: a surface or a block edge as built more than 0.1 dx from where the case puts
    // it (tank faces never are: their layers are laid from the face).
    const double tol = 0.1 * cfg.dx;
    for (const BuiltFace& f : built.faces)
        if (std::abs(f.built - f.requested) > tol)
            out.push_back({f.upper ? "walls.tank_hi" : "walls.tank_lo",
                           fmt::format("the {}{} wall surface is built at {:.6g} m, {:.2g} dx "
                                       "from {:.6g} m",
                                       kAxis[f.axis], f.upper ? '+' : '-', f.built,
                                       (f.built - f.requested) / cfg.dx, f.requested)});
    for (std::size_t i = 0; i < built.boxes.size(); ++i)
        for (std::size_t a = 0; a < dim; ++a) {
            const BuiltBox& b = built.boxes[i];
            const WallBox& c = cfg.boxes[i];
            if (std::abs(b.lo[a] - c.lo[a]) <= tol && std::abs(b.hi[a] - c.hi[a]) <= tol)
                continue;
            out.push_back({fmt::format("walls.boxes[{}].hi", i),
                           fmt::format("the obstacle is built {:.4g} m thick along {} instead of "
                                       "{:.4g} m ({} to {} m): it is thinner than 2 x {} wall "
                                       "layers and is filled with whole particles, centred; a "
                                       "thickness of a whole number of dx = {:g} m avoids this",
                                       b.hi[a] - b.lo[a], kAxis[a], c.hi[a] - c.lo[a], b.lo[a],
                                       b.hi[a], wall_layers(info.support, cfg.dx), cfg.dx)});
            break;
        }
    // Meshes: a solid thinner than the kernel's reach lets a fluid particle at one face see
    // the fluid at the other through it; a built surface off the mesh, or with too few sites
    // in its innermost layer (curvature on the scale of dx, left-out sites), is a wall other
    // than the one drawn.
    const int layers = wall_layers(info.support, cfg.dx);
    for (std::size_t i = 0; i < built.meshes.size(); ++i) {
        const BuiltMesh& m = built.meshes[i];
        const std::string key = fmt::format("walls.meshes[{}].file", i);
        const std::string& file = cfg.meshes[i].file;
        if (cfg.meshes[i].role == MeshRole::solid && m.shape.thinnest < layers * cfg.dx)
            out.push_back(
                {key, fmt::format("\"{}\" is {:.3g} m ({:.2g} dx) thick at its thinnest, less "
                                  "than its {} wall layers ({:.3g} m, the kernel's reach): fluid "
                                  "on one side sees the fluid on the other through it; "
                                  "dx <= {:.3g} m gives the layers room",
                                  file, m.shape.thinnest, m.shape.thinnest / cfg.dx, layers,
                                  layers * cfg.dx, m.shape.thinnest / layers)});
        if (cfg.walls != WallModel::dummy)
            continue;
        if (m.walls.surface_deviation > tol)
            out.push_back(
                {key, fmt::format("the wall surface of \"{}\" as built lies up to {:.2g} dx "
                                  "from the mesh (more than 0.1 dx)",
                                  file, m.walls.surface_deviation / cfg.dx)});
        if (m.coverage < min_mesh_coverage)
            out.push_back(
                {key, fmt::format("the innermost wall layer of \"{}\" holds {:.2f} sites per "
                                  "dx^{} of its surface (a flat face: 1): its surface curves "
                                  "on the scale of dx or has features below it, so the wall "
                                  "the fluid sees has gaps; a smaller dx follows it",
                                  file, m.coverage, dim - 1)});
    }
    for (std::size_t i = 0; i < built.blocks.size(); ++i)
        for (std::size_t a = 0; a < dim && cfg.blocks[i].shape != BlockShape::mesh; ++a) {
            // (A mesh block's edge is its mesh, not the lattice's end.)
            const BuiltBlock& b = built.blocks[i];
            const double want = cfg.blocks[i].hi[a];
            if (std::abs(b.hi[a] - want) <= tol)
                continue;
            out.push_back(
                {fmt::format("blocks[{}].hi", i),
                 fmt::format(
                     "the block's lattice ends at {} = {:.6g} m, {:+.2g} dx from hi = {:.6g} "
                     "m ({} particles along {}{}; volume {:+.2f} %): a block extent of a "
                     "whole number of dx = {:g} m avoids this",
                     kAxis[a], b.hi[a], (b.hi[a] - want) / cfg.dx, want, b.sites[a], kAxis[a],
                     b.capped[a] ? ", one fewer than round(extent/dx): the next would "
                                   "sit within dx/4 of the walled tank face or beyond it"
                                 : "",
                     100 * (b.volume / b.requested_volume - 1), cfg.dx)});
            break;
        }

    // Cost: a tiny time step.
    if (info.dt_estimate < min_useful_dt) {
        const char* key = cfg.fixed_dt                           ? "numerics.dt"
                          : info.dt_estimate == info.dt_acoustic ? "fluid.sound_speed"
                          : info.dt_estimate == info.dt_viscous  ? "fluid.viscosity"
                                                                 : "fluid.gravity";
        out.push_back({key, fmt::format("time step {:.3g} s is below {:.0e} s: about {:.3g} "
                                        "steps to t = {:.4g} s (slow)",
                                        info.dt_estimate, min_useful_dt,
                                        cfg.end_time / info.dt_estimate, cfg.end_time)});
    }

    // Compressibility: c0 >= 10 sqrt(g H) keeps density variations near 1 % (Monaghan 1994).
    // Gravity along a periodic axis builds no column, so only the other components count.
    Triple g{};
    double g_norm = 0;
    for (std::size_t a = 0; a < dim; ++a) {
        g[a] = cfg.periodic[a] ? 0.0 : cfg.gravity[a];
        g_norm += g[a] * g[a];
    }
    g_norm = std::sqrt(g_norm);
    // (The projection scheme is incompressible: c0 only bounds the speed there.)
    if (g_norm > 0 && !cfg.blocks.empty() && cfg.scheme == Scheme::wcsph) {
        Triple up{};
        for (std::size_t a = 0; a < dim; ++a)
            up[a] = -g[a] / g_norm;
        double top = -std::numeric_limits<double>::infinity();
        double floor = std::numeric_limits<double>::infinity();
        for (const auto& b : cfg.blocks) {
            const auto [low, high] = height_range(b.lo, b.hi, up, cfg.dimension);
            top = std::max(top, high);
            floor = std::min(floor, low);
        }
        if (cfg.walls != WallModel::none) // the fluid may fall to the tank's lowest corner
            floor =
                std::min(floor, height_range(cfg.tank_lo, cfg.tank_hi, up, cfg.dimension).first);
        const double H = top - floor;
        const double c_min = min_mach_ratio * std::sqrt(g_norm * H);
        // 0.5 % slack: the shipped cases round 10 sqrt(g H) to the digits a user types.
        if (cfg.sound_speed < 0.995 * c_min)
            out.push_back({"fluid.sound_speed",
                           fmt::format("c0 = {:.4g} m/s is below 10 sqrt(g H) = {:.4g} m/s "
                                       "(|g| = {:.4g} m/s^2, fluid column H = {:.4g} m): density "
                                       "will vary by more than ~1 % (inaccurate)",
                                       cfg.sound_speed, c_min, g_norm, H)});
        const bool measures_loads =
            std::any_of(cfg.probes.begin(), cfg.probes.end(), [](const ProbeConfig& p) {
                return p.type == ProbeType::pressure || p.type == ProbeType::force;
            });
        // Water can only surge into a wall if some block leaves part of the tank's floor dry
        // (a layer over the whole floor, as in a still tank, cannot collapse).
        const Triple& box_lo = cfg.walls != WallModel::none ? cfg.tank_lo : cfg.domain_lo;
        const Triple& box_hi = cfg.walls != WallModel::none ? cfg.tank_hi : cfg.domain_hi;
        bool can_surge = false;
        for (const auto& b : cfg.blocks)
            for (std::size_t a = 0; a < dim; ++a)
                if (std::abs(up[a]) < 1e-12 && !cfg.periodic[a] &&
                    (b.lo[a] > box_lo[a] + 1e-9 || b.hi[a] < box_hi[a] - 1e-9))
                    can_surge = true;
        const double c_loads = min_mach_ratio_loads * std::sqrt(g_norm * H);
        if (measures_loads && can_surge && cfg.sound_speed >= 0.995 * c_min &&
            cfg.sound_speed < 0.995 * c_loads)
            out.push_back({"fluid.sound_speed",
                           fmt::format("c0 = {:.4g} m/s is below 20 sqrt(g H) = {:.4g} m/s and "
                                       "the case measures pressure or force: impact loads are "
                                       "not converged in c0 there (inaccurate; "
                                       "docs/RECOMMENDED_PRACTICE.md)",
                                       cfg.sound_speed, c_loads)});
    }
    return out;
}

} // namespace sluice
