// numerics.scheme and the keys it rules out, the [numerics], [projection] and
// [neighbours.<operator>] tables of a case file (case_numerics.hpp).
#include "case_numerics.hpp"

#include "case_schema.hpp"
#include "sluice/physics/kernels.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sluice::case_file {
namespace {

const std::vector<std::pair<std::string, Scheme>> kSchemes = {{"wcsph", Scheme::wcsph},
                                                              {"projection", Scheme::projection}};
const std::vector<std::pair<std::string, KernelType>> kKernels = {
    {"quintic", KernelType::quintic},
    {"wendland_c2", KernelType::wendland_c2},
    {"cubic_spline", KernelType::cubic_spline}};
const std::vector<std::pair<std::string, DensityScheme>> kDensity = {
    {"summation", DensityScheme::summation}, {"continuity", DensityScheme::continuity}};
const std::vector<std::pair<std::string, Dissipation>> kDissipation = {
    {"artificial", Dissipation::artificial}, {"riemann", Dissipation::riemann}};
const std::vector<std::pair<std::string, DensityDiffusion>> kDiffusion = {
    {"antuono", DensityDiffusion::antuono}, {"fourtakas", DensityDiffusion::fourtakas}};
const std::vector<std::pair<std::string, PressureSolver>> kPressureSolvers = {
    {"bicgstab", PressureSolver::bicgstab}, {"sor", PressureSolver::sor}};
const std::vector<std::pair<std::string, PressurePreconditioner>> kPreconditioners = {
    {"jacobi", PressurePreconditioner::jacobi},
    {"block_lu", PressurePreconditioner::block_lu},
    {"block_ilu0", PressurePreconditioner::block_ilu0},
    {"two_level", PressurePreconditioner::two_level}};
const std::vector<std::pair<std::string, CorrectionGradient>> kCorrectionGradients = {
    {"second_order", CorrectionGradient::second_order},
    {"first_order", CorrectionGradient::first_order}};
const std::vector<std::pair<std::string, CorrectionReference>> kCorrectionReferences = {
    {"minimum", CorrectionReference::minimum}, {"hydrostatic", CorrectionReference::hydrostatic}};
const std::vector<std::pair<std::string, DeviationWeight>> kDeviationWeights = {
    {"pnu_mps", DeviationWeight::pnu_mps}, {"smooth", DeviationWeight::smooth}};
const std::vector<std::pair<std::string, WallCollision>> kWallCollisions = {
    {"line_of_centres", WallCollision::line_of_centres},
    {"wall_normal", WallCollision::wall_normal}};
const std::vector<std::pair<std::string, NeighbourPolicy>> kNeighbourPolicies = {
    {"radius", NeighbourPolicy::radius}, {"convex-hull", NeighbourPolicy::convex_hull}};
const std::vector<std::pair<std::string, bool>> kHullPoints = {{"vertices", false},
                                                               {"boundary", true}};

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

} // namespace

void read_scheme(const Section& top, CaseConfig& c) {
    c.scheme = top.sub("numerics").choice("scheme", c.scheme, kSchemes);
    check_scheme_keys(top, c.scheme);
}

void read_numerics(const Section& s, CaseConfig& c) {
    c.kernel = s.choice("kernel", c.kernel, kKernels);
    // Left out, h gives each kernel a support of 3 dx (quintic: h = dx; Wendland C2 and the
    // cubic spline: h = 1.5 dx), the neighbourhoods the validation cases are measured with.
    c.h_over_dx = s.number("h_over_dx", 3.0 / kernel_support_factor(c.kernel));
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
        s.require(s.node("artificial_viscosity") == nullptr || c.artificial_viscosity == 0,
                  "artificial_viscosity",
                  "must be 0 with numerics.dissipation = \"riemann\" (the Riemann solver is "
                  "the scheme's viscosity)");
        c.delta_sph = 0;
        c.artificial_viscosity = 0;
    }
    // WCSPH's dissipation: the projection scheme refuses the key (check_scheme_keys), and its
    // force probes sum the pair terms without it.
    if (c.scheme == Scheme::projection)
        c.artificial_viscosity = 0;
    c.shifting = s.number("shifting", c.shifting);
    c.acoustic_damper = s.number("acoustic_damper", c.acoustic_damper);
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
    p.correction_reference =
        s.choice("correction_reference", p.correction_reference, kCorrectionReferences);
    p.deviation_weight = s.choice("deviation_weight", p.deviation_weight, kDeviationWeights);
    p.wall_collision = s.choice("wall_collision", p.wall_collision, kWallCollisions);
    p.fluid_collision = s.boolean("fluid_collision").value_or(p.fluid_collision);
    p.shifting = s.number("shifting", p.shifting);
}

void check_walls_for_scheme(const Section& top, const CaseConfig& c) {
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
}

void read_neighbours(const Section& s, CaseConfig& c) {
    c.neighbours.gradient = read_neighbour_selection(s.sub("gradient"));
    c.neighbours.laplacian = read_neighbour_selection(s.sub("laplacian"));
    c.neighbours.free_surface = read_neighbour_selection(s.sub("free_surface"));
}

} // namespace sluice::case_file
