#pragma once
// What `sluice check` / `sluice info` tell about a validated case before anything runs:
// refusals the solver would otherwise only find after generating the particles, and warnings
// about cases that will run slowly or inaccurately.
#include "sluice/io/case_config.hpp"
#include "sluice/solver/run.hpp"

#include <string>
#include <vector>

namespace sluice {

// Throws CaseError for a case the solver would refuse (a fixed dt above the stability limit
// at rest, a periodic axis shorter than three kernel supports) or that could not reach its
// end time (a time step of zero, infinite, or below end_time's resolution). Allocates nothing.
void check_runnable(const CaseConfig& cfg, const CaseInfo& info);

struct CaseWarning {
    std::string key;     // the case key to change ("particles.dx", "fluid.sound_speed", ...)
    std::string message; // what is wrong and what it costs
};

// Thresholds of the warnings (documented in docs/CASE_REFERENCE.md, "sluice info").
inline constexpr double min_particles_across = 20; // across the smallest feature
inline constexpr double min_mesh_coverage = 0.8;   // innermost mesh wall sites per dx^(D-1)
inline constexpr double min_useful_dt = 1e-7;      // [s]
inline constexpr double min_mach_ratio = 10;       // c0 >= 10 sqrt(g H)
// c0 >= 20 sqrt(g H) where the case measures loads (pressure or force probes): at
// 10 sqrt(g H) impact pressures are not converged (docs/RECOMMENDED_PRACTICE.md).
inline constexpr double min_mach_ratio_loads = 20;

// Cases that run but will be slow or inaccurate: fewer than ~20 particles across the smallest
// fluid block or tank dimension, dt below 1e-7 s, c0 below 10 sqrt(g H) (H: highest fluid
// column, measured along gravity from the lowest point the fluid can reach).
std::vector<CaseWarning> case_warnings(const CaseConfig& cfg, const CaseInfo& info);

} // namespace sluice
