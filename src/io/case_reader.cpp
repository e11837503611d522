// TOML case file -> validated CaseConfig: each section of the case read and checked, in file
// order. The TOML machinery (typed look-ups, the schema, --set) is in toml_section.hpp,
// case_schema.hpp and case_toml.hpp.
#include "sluice/io/case_reader.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/physics/kernels.hpp"

#include "case_fingerprint.hpp"
#include "case_limits.hpp"
#include "case_probes.hpp"
#include "case_schema.hpp"
#include "case_toml.hpp"
#include "case_walls.hpp"
#include "toml_section.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sluice {
namespace {

using case_file::Applies;
using case_file::check_blocks_in_tank;
using case_file::join_list;
using case_file::kAxis;
using case_file::kMaxNameLength;
using case_file::kMaxOutputs;
using case_file::read_probes;
using case_file::read_walls;
using case_file::Reader;
using case_file::Section;
using case_file::slack;
using case_file::type_name;

// Bounds of the case's size (the bounds of single keys are the schema's ranges): far beyond
// any real case; past them a case is a typo or hostile input. Micro-cells of the grid: 32-bit
// cell indices, and 21 bits per axis of a 3-D Morton key.
constexpr double kMaxCells = 2e8;
constexpr double kMaxCellsPerAxis3d = 2097151;

// ---------------------------------------------------------------------------------------------
// Sections of the case, in file order

const std::vector<std::pair<std::string, KernelType>> kKernels = {
    {"quintic", KernelType::quintic},
    {"wendland_c2", KernelType::wendland_c2},
    {"cubic_spline", KernelType::cubic_spline}};
const std::vector<std::pair<std::string, Scheme>> kSchemes = {{"wcsph", Scheme::wcsph},
                                                              {"projection", Scheme::projection}};
const std::vector<std::pair<std::string, PressureSolver>> kPressureSolvers = {
    {"bicgstab", PressureSolver::bicgstab}, {"sor", PressureSolver::sor}};
const std::vector<std::pair<std::string, PressurePreconditioner>> kPreconditioners = {
    {"jacobi", PressurePreconditioner::jacobi},
    {"block_lu", PressurePreconditioner::block_lu},
    {"block_ilu0", PressurePreconditioner::block_ilu0}};
const std::vector<std::pair<std::string, CorrectionGradient>> kCorrectionGradients = {
    {"second_order", CorrectionGradient::second_order},
    {"first_order", CorrectionGradient::first_order}};
const std::vector<std::pair<std::string, DensityScheme>> kDensity = {
    {"summation", DensityScheme::summation}, {"continuity", DensityScheme::continuity}};
const std::vector<std::pair<std::string, Dissipation>> kDissipation = {
    {"artificial", Dissipation::artificial}, {"riemann", Dissipation::riemann}};
const std::vector<std::pair<std::string, DensityDiffusion>> kDiffusion = {
    {"antuono", DensityDiffusion::antuono}, {"fourtakas", DensityDiffusion::fourtakas}};
const std::vector<std::pair<std::string, BalanceCost>> kBalanceCost = {
    {"time", BalanceCost::time}, {"particles", BalanceCost::particles}};
const std::vector<std::pair<std::string, InitialDecomposition>> kInitialDecomposition = {
    {"balanced", InitialDecomposition::balanced}, {"key-range", InitialDecomposition::key_range}};
const std::vector<std::pair<std::string, NeighbourPolicy>> kNeighbourPolicies = {
    {"radius", NeighbourPolicy::radius}, {"convex-hull", NeighbourPolicy::convex_hull}};
const std::vector<std::pair<std::string, bool>> kHullPoints = {{"vertices", false},
                                                               {"boundary", true}};
const std::vector<std::pair<std::string, EosType>> kEos = {{"linear", EosType::linear},
                                                           {"tait", EosType::tait}};
const std::vector<std::pair<std::string, VelocityProfile>> kProfiles = {
    {"uniform", VelocityProfile::uniform},
    {"taylor_green", VelocityProfile::taylor_green},
    {"rotating", VelocityProfile::rotating},
    {"strain", VelocityProfile::strain}};
const std::vector<std::pair<std::string, BlockShape>> kShapes = {{"box", BlockShape::box},
                                                                 {"ellipse", BlockShape::ellipse}};

void read_case_table(const Section& s, CaseConfig& c, Reader& r, const std::string& path) {
    const auto d = s.integer("dimension");
    if (!d)
        s.reader().fail(s.key("dimension"), "missing required key (2 or 3)");
    c.dimension = static_cast<int>(*d);
    r.dim = c.dimension;

    c.name = s.string("name").value_or(std::filesystem::path(path).stem().string());
    // The name becomes the default results folder results/<name>.
    const bool bad_name =
        c.name.empty() || c.name == "." || c.name == ".." ||
        std::any_of(c.name.begin(), c.name.end(), [](char ch) {
            return ch == '/' || ch == '\\' || std::iscntrl(static_cast<unsigned char>(ch)) != 0;
        });
    s.require(!bad_name, "name",
              fmt::format("\"{}\" cannot be used as a folder name (no '/', '\\', control "
                          "characters, '.' or '..')",
                          c.name));
    s.require(c.name.size() <= kMaxNameLength, "name",
              fmt::format("is {} bytes long; at most {} (it becomes a folder name)", c.name.size(),
                          kMaxNameLength));
    c.description = s.string("description").value_or("");
}

void read_domain(const Section& s, CaseConfig& c) {
    c.domain_lo = s.required_triple("lo", "lower corner of the domain [m]");
    c.domain_hi = s.required_triple("hi", "upper corner of the domain [m]");
    for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a)
        s.require(c.domain_lo[a] < c.domain_hi[a], "hi",
                  fmt::format("must be above domain.lo on every axis; on {}: lo = {}, hi = {}",
                              kAxis[a], c.domain_lo[a], c.domain_hi[a]));
    if (const auto* n = s.node("periodic")) {
        const auto* arr = n->as_array();
        s.require(
            arr != nullptr && arr->size() == static_cast<std::size_t>(c.dimension), "periodic",
            fmt::format("expected an array of exactly {} booleans (one per axis)", c.dimension));
        for (std::size_t a = 0; a < arr->size(); ++a) {
            const auto* b = (*arr)[a].as_boolean();
            if (b == nullptr)
                s.reader().fail(fmt::format("{}[{}]", s.key("periodic"), a),
                                "expected true or false, got " + type_name((*arr)[a]), n);
            c.periodic[a] = b->get();
        }
    }
}

void read_fluid(const Section& s, CaseConfig& c) {
    c.rho0 = s.required_number("rho0", "reference density [kg/m^3]");
    c.viscosity = s.required_number("viscosity", "dynamic viscosity [Pa s], 0 for inviscid");
    c.sound_speed = s.required_number("sound_speed", "artificial speed of sound [m/s]");
    // Gravity points down the last axis: -y in 2-D, -z in 3-D.
    c.gravity = c.dimension == 2 ? Triple{0, -9.81, 0} : Triple{0, 0, -9.81};
    if (auto g = s.triple("gravity"))
        c.gravity = *g;
    c.eos = s.choice("eos", c.eos, kEos);
    c.gamma = s.number("gamma", c.gamma);
    c.background_pressure = s.number("background_pressure", c.background_pressure);
}

// Keys of the rotating and strain profiles: each needs its rate, only in 2-D, and the strain
// profile's pressure is known for an ellipse only. An ellipse has no flat top, so the
// hydrostatic start (depth below the box top) is refused under gravity.
void read_block_profile(const Section& s, const CaseConfig& c, FluidBlock& b) {
    const auto rate = [&](std::string_view key, VelocityProfile owner, const char* owner_name,
                          const char* what) {
        const auto v = s.number(key);
        if (b.profile != owner) {
            s.require(!v, key, fmt::format("applies only to profile = \"{}\"", owner_name));
            return 0.0;
        }
        if (!v)
            s.reader().fail(s.key(key), fmt::format("missing required key ({}; needed with "
                                                    "profile = \"{}\")",
                                                    what, owner_name));
        s.require(c.dimension == 2, "profile",
                  fmt::format("\"{}\" is a 2-D profile; this case is 3-D", owner_name));
        return *v;
    };
    b.angular_velocity = rate("angular_velocity", VelocityProfile::rotating, "rotating",
                              "angular velocity [rad/s], counter-clockwise positive");
    b.strain_rate = rate("strain_rate", VelocityProfile::strain, "strain", "strain rate A0 [1/s]");
    if (b.profile == VelocityProfile::strain)
        s.require(b.shape == BlockShape::ellipse, "shape",
                  "profile = \"strain\" needs shape = \"ellipse\" (its initial pressure is "
                  "known for an elliptical drop only)");
    const auto up = static_cast<std::size_t>(c.dimension - 1);
    if (b.shape == BlockShape::ellipse && b.hydrostatic && c.gravity[up] != 0)
        s.require(false, "hydrostatic",
                  "an ellipse-shaped block has no flat top for the hydrostatic start; set "
                  "hydrostatic = false (or switch gravity off)");
}

void read_blocks(const Section& root, CaseConfig& c) {
    const auto blocks = root.entries("blocks");
    if (blocks.empty())
        root.reader().fail("blocks", "missing required key: at least one [[blocks]] fluid block "
                                     "is needed");
    const double eps = slack(c);
    for (const auto& s : blocks) {
        FluidBlock b;
        b.lo = s.required_triple("lo", "lower corner of the block [m]");
        b.hi = s.required_triple("hi", "upper corner of the block [m]");
        for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a) {
            s.require(b.lo[a] < b.hi[a], "hi",
                      fmt::format("must be above lo on every axis; on {}: lo = {}, hi = {}",
                                  kAxis[a], b.lo[a], b.hi[a]));
            s.require(b.lo[a] >= c.domain_lo[a] - eps, "lo",
                      fmt::format("the block lies outside the domain: {} = {} is below "
                                  "domain.lo = {}",
                                  kAxis[a], b.lo[a], c.domain_lo[a]));
            s.require(b.hi[a] <= c.domain_hi[a] + eps, "hi",
                      fmt::format("the block lies outside the domain: {} = {} is above "
                                  "domain.hi = {}",
                                  kAxis[a], b.hi[a], c.domain_hi[a]));
        }
        if (auto v = s.triple("velocity"))
            b.velocity = *v;
        b.shape = s.choice("shape", b.shape, kShapes);
        b.profile = s.choice("profile", b.profile, kProfiles);
        b.amplitude = s.number("amplitude", b.amplitude);
        b.hydrostatic = s.boolean("hydrostatic").value_or(b.hydrostatic);
        read_block_profile(s, c, b);

        // Two blocks sharing volume would put two particles on one lattice site.
        for (std::size_t j = 0; j < c.blocks.size(); ++j) {
            bool overlap = true;
            for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a)
                overlap = overlap && std::min(b.hi[a], c.blocks[j].hi[a]) -
                                             std::max(b.lo[a], c.blocks[j].lo[a]) >
                                         eps;
            s.require(!overlap, "lo", fmt::format("the block overlaps blocks[{}]", j));
        }
        c.blocks.push_back(b);
    }
}

// The lattice puts round(extent / dx) particles along each axis: a block thinner than dx/2
// would silently hold none.
void check_block_thickness(const Section& root, const CaseConfig& c) {
    for (std::size_t i = 0; i < c.blocks.size(); ++i)
        for (std::size_t a = 0; a < static_cast<std::size_t>(c.dimension); ++a) {
            const double extent = c.blocks[i].hi[a] - c.blocks[i].lo[a];
            if (std::round(extent / c.dx) < 1)
                root.reader().fail(fmt::format("blocks[{}].hi", i),
                                   fmt::format("the block is {} m thick along {}, less than "
                                               "half of dx = {} m: it would hold no particle",
                                               extent, kAxis[a], c.dx));
        }
}

// Every key the schema marks as read by one scheme only is refused under the other, where it
// would silently do nothing (numerics.delta_sph under "projection", [projection] under
// "wcsph"). Keys first, then tables, so that a key in [projection] is named rather than the
// table; tables in reverse schema order, so that a sub-table ([neighbours.laplacian]) is named
// rather than its parent (the schema lists a parent first). Only plain tables hold such keys
// (the schema's arrays of tables have none).
void check_scheme_keys(const Section& top, Scheme scheme) {
    const Applies own = scheme == Scheme::projection ? Applies::projection : Applies::wcsph;
    const auto& keys = case_file::case_keys();
    for (const bool tables : {false, true})
        for (std::size_t i = 0; i < keys.size(); ++i) {
            const auto& k = keys[tables ? keys.size() - 1 - i : i];
            const bool is_table = k.type == "table" || k.type == "array of tables";
            if (k.applies == Applies::any || k.applies == own || is_table != tables)
                continue;
            const toml::table* t = &top.table();
            std::string_view rest = k.table;
            while (t != nullptr && !rest.empty()) {
                const auto dot = rest.find('.');
                const auto* n = t->get(rest.substr(0, dot));
                t = n != nullptr ? n->as_table() : nullptr;
                rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot + 1);
            }
            const toml::node* n = t != nullptr ? t->get(k.key) : nullptr;
            if (n == nullptr)
                continue;
            top.reader().fail(
                case_file::join_key(k.table, k.key),
                fmt::format("applies only to numerics.scheme = \"{}\" (the scheme is \"{}\")",
                            case_file::applies_name(k.applies), case_file::scheme_name(scheme)),
                n);
        }
}

void read_numerics(const Section& s, CaseConfig& c) {
    c.kernel = s.choice("kernel", c.kernel, kKernels);
    c.h_over_dx = s.number("h_over_dx", c.h_over_dx);
    c.density = s.choice("density", c.density, kDensity);
    c.delta_sph = s.number("delta_sph", c.delta_sph);
    c.density_diffusion = s.choice("density_diffusion", c.density_diffusion, kDiffusion);
    c.artificial_viscosity = s.number("artificial_viscosity", c.artificial_viscosity);
    c.wall_artificial_viscosity =
        s.boolean("wall_artificial_viscosity").value_or(c.wall_artificial_viscosity);
    c.dissipation = s.choice("dissipation", c.dissipation, kDissipation);
    if (c.dissipation == Dissipation::riemann) {
        // The Riemann solver is the scheme's dissipation in both equations: refuse the keys it
        // replaces instead of ignoring them.
        s.require(c.scheme == Scheme::wcsph, "dissipation",
                  "\"riemann\" applies only to numerics.scheme = \"wcsph\"");
        s.require(c.density == DensityScheme::continuity, "dissipation",
                  "\"riemann\" needs numerics.density = \"continuity\"");
        s.require(s.node("delta_sph") == nullptr || c.delta_sph == 0, "delta_sph",
                  "must be 0 with numerics.dissipation = \"riemann\" (the Riemann solver "
                  "diffuses density itself)");
        s.require(s.node("density_diffusion") == nullptr, "density_diffusion",
                  "does not apply with numerics.dissipation = \"riemann\"");
        s.require(s.node("wall_artificial_viscosity") == nullptr, "wall_artificial_viscosity",
                  "does not apply with numerics.dissipation = \"riemann\"");
        s.require(c.artificial_viscosity == 0, "artificial_viscosity",
                  "must be 0 with numerics.dissipation = \"riemann\" (the Riemann solver is "
                  "the scheme's viscosity)");
        c.delta_sph = 0;
    }
    c.shifting = s.number("shifting", c.shifting);
    c.cfl = s.number("cfl", c.cfl);
    c.viscous_cfl = s.number("viscous_cfl", c.viscous_cfl);
    c.force_cfl = s.number("force_cfl", c.force_cfl);
    if (auto dt = s.number("dt"))
        c.fixed_dt = *dt;
    c.neighbour_skin = s.number("neighbour_skin", c.neighbour_skin);
}

// [projection] (refused with the WCSPH scheme by check_scheme_keys).
void read_projection(const Section& s, CaseConfig& c) {
    if (c.scheme != Scheme::projection)
        return;
    ProjectionSettings& p = c.projection;
    p.solver = s.choice("solver", p.solver, kPressureSolvers);
    p.tolerance = s.number("tolerance", p.tolerance);
    p.max_iterations = static_cast<int>(s.integer("max_iterations").value_or(p.max_iterations));
    p.preconditioner = s.choice("preconditioner", p.preconditioner, kPreconditioners);
    s.require(p.solver == PressureSolver::bicgstab || s.node("preconditioner") == nullptr,
              "preconditioner", "applies only to solver = \"bicgstab\"");
    p.relaxation = s.number("relaxation", p.relaxation);
    s.require(p.solver == PressureSolver::sor || s.node("relaxation") == nullptr, "relaxation",
              "applies only to solver = \"sor\"");
    p.gamma = s.number("gamma", p.gamma);
    p.surface_diameter_over_dx = s.number("surface_diameter_over_dx", p.surface_diameter_over_dx);
    p.surface_density_ratio = s.number("surface_density_ratio", p.surface_density_ratio);
    p.correction_gradient =
        s.choice("correction_gradient", p.correction_gradient, kCorrectionGradients);
    p.fluid_collision = s.boolean("fluid_collision").value_or(p.fluid_collision);
}

void read_time(const Section& s, CaseConfig& c) {
    c.end_time = s.required_number("end_time", "simulated time to reach [s]");
    c.output_interval = s.number("output_interval", c.output_interval);
    s.require(
        c.output_interval == 0 || c.end_time / c.output_interval <= kMaxOutputs, "output_interval",
        fmt::format("{} s would write {:.3g} snapshots up to end_time = {} s; at most {:g}",
                    c.output_interval, c.end_time / c.output_interval, c.end_time, kMaxOutputs));
}

void read_output(const Section& s, CaseConfig& c) {
    c.snapshots = s.boolean("snapshots").value_or(c.snapshots);
    if (auto f = s.strings("fields")) {
        std::set<std::string> seen;
        for (const auto& name : *f)
            s.require(seen.insert(name).second, "fields",
                      fmt::format("field \"{}\" is listed twice", name));
        c.fields = *f;
    }
}

void read_runtime(const Section& s, CaseConfig& c) {
    c.particles_per_group =
        static_cast<int>(s.integer("particles_per_group").value_or(c.particles_per_group));
    c.rebalance_threshold = s.number("rebalance_threshold", c.rebalance_threshold);
    c.rebalance_window =
        static_cast<int>(s.integer("rebalance_window").value_or(c.rebalance_window));
    c.rebalance_every = static_cast<int>(s.integer("rebalance_every").value_or(c.rebalance_every));
    c.balance_cost = s.choice("balance_cost", c.balance_cost, kBalanceCost);
    c.initial_decomposition =
        s.choice("initial_decomposition", c.initial_decomposition, kInitialDecomposition);
}

// One operator's [neighbours.<operator>] table. The convex-hull keys are refused with the
// radius policy, where they would silently do nothing.
NeighbourSelection read_neighbour_selection(const Section& s) {
    NeighbourSelection n;
    n.policy = s.choice("selection", n.policy, kNeighbourPolicies);
    if (n.policy == NeighbourPolicy::radius) {
        for (const char* k : {"candidate_radius_over_dx", "union_with_radius", "hull_points"})
            s.require(s.node(k) == nullptr, k,
                      "applies only to selection = \"convex-hull\" (selection is \"radius\")");
        return n;
    }
    n.candidate_radius_over_dx = s.number("candidate_radius_over_dx", n.candidate_radius_over_dx);
    n.union_with_radius = s.boolean("union_with_radius").value_or(n.union_with_radius);
    // The projection scheme's candidates are its neighbours within the operator radius re
    // (docs/CASE_REFERENCE.md), so hull + radius would be the radius set.
    s.require(!n.union_with_radius, "union_with_radius",
              "the candidates are the particles within the operator radius, so the union with "
              "the radius set is the radius set: use selection = \"radius\"");
    n.hull_boundary = s.choice("hull_points", n.hull_boundary, kHullPoints);
    return n;
}

void read_neighbours(const Section& s, CaseConfig& c) {
    c.neighbours.gradient = read_neighbour_selection(s.sub("gradient"));
    c.neighbours.laplacian = read_neighbour_selection(s.sub("laplacian"));
    c.neighbours.free_surface = read_neighbour_selection(s.sub("free_surface"));
}

void read_checkpoint_table(const Section& s, CaseConfig& c) {
    c.checkpoint_every_steps =
        static_cast<int>(s.integer("every_steps").value_or(c.checkpoint_every_steps));
    c.checkpoint_every_minutes = s.number("every_minutes", c.checkpoint_every_minutes);
}

// Bounds of a healthy fluid state; beyond them the run stops as blown up.
void read_limits(const Section& s, CaseConfig& c) {
    c.max_speed = s.number("max_speed", c.sound_speed);
    c.min_density = s.number("min_density", 0.01 * c.rho0);
    c.max_density = s.number("max_density", 2 * c.rho0);
    s.require(c.min_density < c.rho0, "min_density",
              fmt::format("must be below fluid.rho0 = {}, got {}", c.rho0, c.min_density));
    s.require(c.max_density > c.rho0, "max_density",
              fmt::format("must be above fluid.rho0 = {}, got {}", c.rho0, c.max_density));
}

// Lattice sites along an extent (the solver rounds the same way), in floating point so that a
// hostile extent cannot overflow an integer.
double sites(double extent, double dx) {
    return std::max(1.0, std::round(extent / dx));
}

// Refuses cases that would not fit any sensible machine, before anything is allocated: the
// fluid lattice, the dummy-wall lattice around the tank, and the micro-cell grid.
void check_case_size(const Section& root, const CaseConfig& c) {
    const auto dim = static_cast<std::size_t>(c.dimension);
    const auto* dx_node = root.sub("particles").node("dx");
    double fluid = 0;
    for (const auto& b : c.blocks) {
        double n = 1;
        for (std::size_t a = 0; a < dim; ++a)
            n *= sites(b.hi[a] - b.lo[a], c.dx);
        fluid += n;
    }
    if (fluid > max_case_particles)
        root.reader().fail("particles.dx",
                           fmt::format("the fluid blocks would hold about {:.3g} particles "
                                       "(volume / dx^{}), above the limit of {:.0f} million; "
                                       "increase dx",
                                       fluid, c.dimension, max_case_particles / 1e6),
                           dx_node);

    const double support = kernel_support_factor(c.kernel) * c.h_over_dx * c.dx;
    const double layers = std::ceil(support / c.dx);
    if (c.walls == WallModel::dummy) {
        // Upper bound: the whole lattice of the tank grown by the wall layers on every side.
        double walls = 1;
        for (std::size_t a = 0; a < dim; ++a)
            walls *= sites(c.tank_hi[a] - c.tank_lo[a], c.dx) + 2 * layers;
        if (walls > max_case_particles)
            root.reader().fail(
                "particles.dx",
                fmt::format("the dummy walls around the tank would need up to {:.3g} particles "
                            "((tank / dx + wall layers)^{}), above the limit of {:.0f} million; "
                            "increase dx or make the tank smaller",
                            walls, c.dimension, max_case_particles / 1e6),
                dx_node);
    }

    // The solver's grid: the domain (and tank with its walls) plus one support on open axes,
    // in cells of one support.
    double cells = 1;
    for (std::size_t a = 0; a < dim; ++a) {
        double lo = c.domain_lo[a], hi = c.domain_hi[a];
        if (!c.periodic[a]) {
            const double wall = c.walls == WallModel::dummy ? layers * c.dx : 0.0;
            lo = std::min(lo, c.tank_lo[a] - wall) - support;
            hi = std::max(hi, c.tank_hi[a] + wall) + support;
        }
        const double n = std::max(1.0, std::floor((hi - lo) / support));
        if (dim == 3 && n > kMaxCellsPerAxis3d)
            root.reader().fail(
                "particles.dx",
                fmt::format("the domain is {:.3g} kernel supports long along {}; at most {:.0f} "
                            "in 3-D (Morton keys): increase dx or make the domain smaller",
                            n, kAxis[a], kMaxCellsPerAxis3d),
                dx_node);
        cells *= n;
    }
    if (cells > kMaxCells)
        root.reader().fail("particles.dx",
                           fmt::format("the domain would need {:.3g} micro-cells (one kernel "
                                       "support wide), above the limit of {:.0f} million; "
                                       "increase dx or make the domain smaller",
                                       cells, kMaxCells / 1e6),
                           dx_node);
}

CaseConfig build(const toml::table& root, Reader& r, const std::string& path) {
    CaseConfig c;
    c.source_file = path;
    r.check_keys(root, "", "");
    const Section top(r, root, "");

    read_case_table(top.sub("case"), c, r, path);
    read_domain(top.sub("domain"), c);
    read_fluid(top.sub("fluid"), c);

    const Section particles = top.sub("particles");
    c.dx = particles.required_number("dx", "lattice spacing [m]");
    c.jitter = particles.number("jitter", c.jitter);

    read_blocks(top, c);
    check_block_thickness(top, c);
    // The scheme first: it decides which keys of the file apply.
    c.scheme = top.sub("numerics").choice("scheme", c.scheme, kSchemes);
    check_scheme_keys(top, c.scheme);
    read_numerics(top.sub("numerics"), c);
    read_projection(top.sub("projection"), c);
    read_walls(top.sub("walls"), c);
    // The projection scheme's wall boundary condition lives on wall particles (Neumann rows of
    // the pressure Poisson equation, docs/PROJECTION.md).
    if (c.scheme == Scheme::projection && c.walls == WallModel::reflective)
        top.sub("walls").require(false, "model",
                                 "numerics.scheme = \"projection\" needs \"dummy\" walls (or "
                                 "\"none\"): its wall pressure condition lives on wall particles");
    // Fluid-wall pairs exist only with dummy wall particles: elsewhere the key would do nothing.
    if (c.walls != WallModel::dummy)
        top.sub("numerics")
            .require(top.sub("numerics").node("wall_artificial_viscosity") == nullptr,
                     "wall_artificial_viscosity",
                     "applies only to walls.model = \"dummy\" (fluid-wall pairs)");
    check_blocks_in_tank(top, c);
    read_time(top.sub("time"), c);
    read_output(top.sub("output"), c);
    read_probes(top, c);
    read_runtime(top.sub("runtime"), c);
    read_neighbours(top.sub("neighbours"), c);
    read_checkpoint_table(top.sub("checkpoint"), c);
    read_limits(top.sub("limits"), c);
    check_case_size(top, c);
    return c;
}

} // namespace

CaseConfig read_case(const std::string& path, const std::vector<std::string>& overrides) {
    Reader r(path);
    toml::table root = case_file::parse_case_file(path);
    for (const auto& o : overrides)
        case_file::apply_override(root, o, r);
    CaseConfig c = build(root, r, path);
    c.fingerprint = case_fingerprint(root);
    return c;
}

std::string case_schema_json() {
    return case_file::schema_json();
}

CaseConfig read_case_text(std::string_view text, const std::string& name,
                          const std::vector<std::string>& overrides) {
    Reader r(name);
    toml::table root = case_file::parse_case_text(text, name);
    for (const auto& o : overrides)
        case_file::apply_override(root, o, r);
    return build(root, r, name);
}

} // namespace sluice
