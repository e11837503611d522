// The keys of every table of a case file (case_schema.hpp; docs/CASE_REFERENCE.md).
#include "case_schema.hpp"

namespace sluice::case_file {

const std::map<std::string, std::vector<std::string>, std::less<>> kSchema = {
    {"",
     {"case", "domain", "fluid", "particles", "blocks", "numerics", "walls", "time", "output",
      "probes", "runtime", "neighbours", "checkpoint", "limits", "projection"}},
    {"case", {"name", "description", "dimension"}},
    {"domain", {"lo", "hi", "periodic"}},
    {"fluid",
     {"rho0", "viscosity", "sound_speed", "gravity", "eos", "gamma", "background_pressure"}},
    {"particles", {"dx", "jitter"}},
    {"blocks",
     {"lo", "hi", "shape", "velocity", "profile", "amplitude", "angular_velocity", "strain_rate",
      "hydrostatic"}},
    {"numerics",
     {"scheme", "kernel", "h_over_dx", "density", "delta_sph", "density_diffusion",
      "artificial_viscosity", "wall_artificial_viscosity", "dissipation", "shifting", "cfl",
      "viscous_cfl", "force_cfl", "dt", "neighbour_skin"}},
    {"walls",
     {"model", "tank_lo", "tank_hi", "tank_faces", "restitution", "no_slip", "planes", "boxes"}},
    {"walls.planes", {"point", "normal"}},
    {"walls.boxes", {"lo", "hi"}},
    {"time", {"end_time", "output_interval"}},
    {"output", {"snapshots", "fields"}},
    {"probes",
     {"name", "type", "position", "x", "y", "interval", "diameter", "face", "box", "lo", "hi",
      "moment_about", "direction", "min_thickness"}},
    {"neighbours", {"gradient", "laplacian", "free_surface"}},
    {"neighbours.gradient",
     {"selection", "candidate_radius_over_dx", "union_with_radius", "hull_points"}},
    {"neighbours.laplacian",
     {"selection", "candidate_radius_over_dx", "union_with_radius", "hull_points"}},
    {"neighbours.free_surface",
     {"selection", "candidate_radius_over_dx", "union_with_radius", "hull_points"}},
    {"runtime",
     {"particles_per_group", "rebalance_threshold", "rebalance_window", "rebalance_every",
      "balance_cost", "initial_decomposition"}},
    {"checkpoint", {"every_steps", "every_minutes"}},
    {"projection",
     {"solver", "tolerance", "max_iterations", "relaxation", "gamma", "surface_diameter_over_dx",
      "surface_density_ratio", "correction_gradient", "fluid_collision"}},
    {"limits", {"max_speed", "min_density", "max_density"}},
};
const std::set<std::string, std::less<>> kArrayTables = {"blocks", "probes", "walls.planes",
                                                         "walls.boxes"};

} // namespace sluice::case_file
