// describe_case: what `sluice info` prints, derived from the configuration alone (no particles
// are made, no step is run). Apart from the solver's run loop (run.cpp), so that the case
// checks and the case-reader fuzzer need none of the solver.
#include "sluice/solver/run.hpp"

#include "sluice/physics/kernels.hpp"
#include "sluice/physics/timestep.hpp"
#include "sluice/solver/built_geometry.hpp"
#include "sluice/solver/case_memory.hpp"
#include "sluice/solver/initial_state.hpp"
#include "sluice/solver/motion_check.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

namespace sluice {
namespace {

const char* kernel_name(KernelType k) {
    switch (k) {
    case KernelType::quintic:
        return "Morris quintic spline (support 3h)";
    case KernelType::wendland_c2:
        return "Wendland C2 (support 2h)";
    case KernelType::cubic_spline:
        return "cubic spline (support 2h)";
    }
    return "?";
}

// "[a, b]" or "[a, b, c]" with 6 significant digits.
std::string vec_str(const Triple& v, int dim) {
    std::string s = "[";
    for (int d = 0; d < dim; ++d)
        s += fmt::format("{}{:.6g}", d ? ", " : "", v[static_cast<std::size_t>(d)]);
    return s + "]";
}

// One line per walled tank face, obstacle and fluid block: where it is as built against the
// case (case_warnings warns where they differ by more than 0.1 dx).
std::vector<std::string> geometry_lines(const CaseConfig& cfg, int layers) {
    std::vector<std::string> out;
    const BuiltGeometry g = built_geometry(cfg, layers);
    const int dim = cfg.dimension;
    // Round-off (1e-18 m for a face at 0) printed as the case's value.
    const auto shown = [&](double built, double want) {
        return std::abs(built - want) < 1e-9 * cfg.dx ? want : built;
    };
    for (const BuiltFace& f : g.faces)
        out.push_back(fmt::format("tank face {}{}: surface at {:.6g} m ({:+.3f} dx from the "
                                  "case's {:.6g} m), {} layers, {} particles",
                                  "xyz"[f.axis], f.upper ? '+' : '-', shown(f.built, f.requested),
                                  (f.built - f.requested) / cfg.dx, f.requested, f.layers,
                                  f.particles));
    for (std::size_t i = 0; i < g.boxes.size(); ++i) {
        BuiltBox b = g.boxes[i];
        for (std::size_t d = 0; d < 3; ++d) {
            b.lo[d] = shown(b.lo[d], cfg.boxes[i].lo[d]);
            b.hi[d] = shown(b.hi[d], cfg.boxes[i].hi[d]);
        }
        std::string sites, thin;
        for (int d = 0; d < dim; ++d) {
            sites += fmt::format("{}{}", d ? " x " : "", b.sites[static_cast<std::size_t>(d)]);
            if (b.thin[static_cast<std::size_t>(d)])
                thin += "xyz"[d];
        }
        out.push_back(fmt::format(
            "walls.boxes[{}]: {} to {} m (case {} to {}), {} sites, {} layers{}, {} particles", i,
            vec_str(b.lo, dim), vec_str(b.hi, dim), vec_str(cfg.boxes[i].lo, dim),
            vec_str(cfg.boxes[i].hi, dim), sites, layers,
            thin.empty() ? std::string()
                         : fmt::format(" (filled solid along {}: thinner than 2 x layers)", thin),
            b.particles));
    }
    for (std::size_t i = 0; i < g.blocks.size(); ++i) {
        const BuiltBlock& b = g.blocks[i];
        std::string sites;
        for (int d = 0; d < dim; ++d)
            sites += fmt::format("{}{}", d ? " x " : "", b.sites[static_cast<std::size_t>(d)]);
        // A box or ellipse that a wall mesh cuts is compared with its uncut volume.
        const bool cut = !cfg.meshes.empty() && cfg.blocks[i].shape != BlockShape::mesh;
        out.push_back(fmt::format("blocks[{}]: {} to {} m (case to {}), {} sites, {} particles, "
                                  "volume {:.6g} m^{} (case {:.6g}{}, {:+.2f} %)",
                                  i, vec_str(cfg.blocks[i].lo, dim), vec_str(b.hi, dim),
                                  vec_str(cfg.blocks[i].hi, dim), sites, b.particles, b.volume, dim,
                                  b.requested_volume, cut ? " before the wall meshes cut it" : "",
                                  100 * (b.volume / b.requested_volume - 1)));
    }
    for (std::size_t i = 0; i < g.meshes.size(); ++i) {
        const BuiltMesh& m = g.meshes[i];
        const ShapeReport& r = m.shape;
        const bool tri = dim == 3;
        std::string line = fmt::format(
            "walls.meshes[{}] \"{}\" ({}): {} {}, {}, {} to {} m, {} {:.6g} m{}", i,
            cfg.meshes[i].file, cfg.meshes[i].role == MeshRole::solid ? "solid" : "surface",
            r.elements, tri ? "triangles" : "segments",
            r.closed ? (r.outward ? "closed, normals out" : "closed, normals in") : "open",
            vec_str(r.lo, dim), vec_str(r.hi, dim), tri ? "area" : "length", r.size,
            tri ? "^2" : "");
        if (r.closed)
            line += fmt::format(", encloses {:.6g} m^{}, thinnest {:.4g} m ({:.3g} dx)", r.volume,
                                dim, r.thinnest, r.thinnest / cfg.dx);
        if (cfg.walls == WallModel::dummy)
            line += fmt::format("; {} wall particles ({:.6g} m^{}) in {} layers, {} in the "
                                "innermost ({:.3f} per dx^{} of surface), its surface within "
                                "{:.2g} dx of the mesh",
                                m.walls.particles,
                                static_cast<double>(m.walls.particles) * std::pow(cfg.dx, dim), dim,
                                layers, m.walls.first_layer, m.coverage, dim - 1,
                                m.walls.surface_deviation / cfg.dx);
        else
            line += "; reflective faces";
        out.push_back(line);
    }
    return out;
}

} // namespace

CaseInfo describe_case(const CaseConfig& cfg, int ranks) {
    CaseInfo info;
    info.h = cfg.h_over_dx * cfg.dx;
    info.support = kernel_support_factor(cfg.kernel) * info.h;
    const int layers = wall_layers(info.support, cfg.dx);
    info.fluid_particles = count_fluid_particles(cfg);
    info.wall_particles = count_wall_particles(cfg, layers);
    info.memory = case_memory(cfg, static_cast<double>(info.fluid_particles),
                              static_cast<double>(info.wall_particles), ranks);
    double g = 0, vmax = 0;
    for (int d = 0; d < cfg.dimension; ++d)
        g += cfg.gravity[d] * cfg.gravity[d];
    for (const auto& b : cfg.blocks)
        vmax = std::max(vmax, block_max_speed(b, cfg.dimension));
    const TimeStepParams prm{info.h, cfg.viscosity / cfg.rho0, cfg.cfl, cfg.viscous_cfl,
                             cfg.force_cfl};
    const double c = cfl_sound_speed(cfg.scheme == Scheme::projection, cfg.sound_speed);
    const TimeStepLimits l = particle_time_step(prm, c, vmax, std::sqrt(g));
    info.dt_acoustic = l.acoustic;
    info.dt_viscous = l.viscous;
    info.dt_force = l.force;
    info.dt_stable = l.min();
    info.dt_estimate = cfg.fixed_dt ? *cfg.fixed_dt : l.min();
    info.cells = static_cast<std::size_t>(case_grid_cells(cfg));

    auto& ph = info.physics;
    ph.push_back(fmt::format("kernel: {}, h = {:.4g} m ({} dx)", kernel_name(cfg.kernel), info.h,
                             cfg.h_over_dx));
    if (cfg.scheme == Scheme::projection)
        ph.push_back(fmt::format(
            "scheme: incompressible projection (WMLS operators, PPE by {}, tolerance {:g}, "
            "gamma {:g})",
            cfg.projection.solver == PressureSolver::sor
                ? fmt::format("SOR, relaxation {:g}", cfg.projection.relaxation)
                : std::string("BiCGSTAB + Jacobi"),
            cfg.projection.tolerance, cfg.projection.gamma));
    else if (cfg.density == DensityScheme::summation)
        ph.push_back("density: summation");
    else if (cfg.dissipation == Dissipation::riemann)
        ph.push_back("density: continuity; dissipation: low-dissipation Riemann solver (Zhang, "
                     "Hu & Adams 2017)");
    else
        ph.push_back(cfg.delta_sph > 0 ? fmt::format("density: continuity + delta-SPH (delta = {})",
                                                     cfg.delta_sph)
                                       : std::string("density: continuity"));
    if (cfg.scheme == Scheme::wcsph)
        ph.push_back(
            cfg.eos == EosType::linear
                ? fmt::format("EOS: linear, c0 = {} m/s", cfg.sound_speed)
                : fmt::format("EOS: Tait (gamma = {}), c0 = {} m/s", cfg.gamma, cfg.sound_speed));
    if (cfg.background_pressure != 0)
        ph.push_back(fmt::format("background pressure: {} Pa", cfg.background_pressure));
    if (cfg.viscosity > 0)
        ph.push_back(fmt::format("laminar viscosity (Morris): mu = {} Pa s", cfg.viscosity));
    if (cfg.artificial_viscosity > 0)
        ph.push_back(
            fmt::format("artificial viscosity (Monaghan): alpha = {}", cfg.artificial_viscosity));
    if (g > 0)
        ph.push_back(fmt::format("body force: |g| = {:.4g} m/s^2", std::sqrt(g)));
    if (cfg.walls == WallModel::dummy)
        ph.push_back(fmt::format("walls: dummy particles (Adami 2012), {} layers, {}", layers,
                                 cfg.no_slip ? "no-slip" : "free-slip"));
    else if (cfg.walls == WallModel::reflective)
        ph.push_back(fmt::format("walls: reflective planes, restitution {}", cfg.restitution));
    std::string periodic;
    for (int d = 0; d < cfg.dimension; ++d)
        if (cfg.periodic[d])
            periodic += "xyz"[d];
    if (!periodic.empty())
        ph.push_back("periodic along: " + periodic);
    ph.push_back(fmt::format("leaving the domain: a fluid particle {}",
                             cfg.particle_exit == ParticleExit::remove ? "is removed and counted"
                                                                       : "stops the run"));
    ph.push_back(cfg.fixed_dt ? fmt::format("time step: fixed {:.4g} s", *cfg.fixed_dt)
                              : std::string("time step: adaptive (CFL, viscous, force limits)"));
    for (std::string& line : motion_summary(cfg))
        ph.push_back(std::move(line));
    info.geometry = geometry_lines(cfg, layers);
    return info;
}

} // namespace sluice
