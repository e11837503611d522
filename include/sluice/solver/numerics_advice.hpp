#pragma once
// Warnings of `sluice info` about the scheme's numerics where a case departs from
// docs/RECOMMENDED_PRACTICE.md in a way that costs accuracy (figures: perf/defaults/README.md).
#include "sluice/io/case_config.hpp"
#include "sluice/solver/case_check.hpp"

#include <vector>

namespace sluice {

// The cell Reynolds number below which the laminar viscosity acts on the particle scale, so
// that the flow's answer is its viscosity (Poiseuille, Taylor–Green): Re_dx = U dx / nu with
// U = c0 / 10, the largest speed a WCSPH case is set up for (Mach 0.1).
inline constexpr double max_viscous_cell_reynolds = 10;

// In a WCSPH case whose laminar viscosity is resolved at dx (Re_dx below the bound): a kernel
// other than the quintic (2-3x the errors on Poiseuille and Taylor–Green) and artificial
// viscosity (it adds alpha h c0 / 8 in 2-D, / 10 in 3-D, to the viscosity: Monaghan 2005,
// section 4.5). In a free-surface case (gravity, Re_dx above it) without artificial viscosity:
// a larger still-water noise floor and unbounded impact peaks.
std::vector<CaseWarning> numerics_warnings(const CaseConfig& cfg);

} // namespace sluice
