#pragma once
// The size of a case, checked before anything is allocated: the fluid lattice, the dummy-wall
// lattice around the tank and the micro-cell grid (docs/CASE_REFERENCE.md, particles.dx).
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// Refuses (naming particles.dx) a case of hostile size or with more grid cells than the cell
// indices hold; whether it fits in memory is memory_estimate.hpp's, for a rank count.
// Needs every table but the run controls read.
void check_case_size(const Section& root, const CaseConfig& c);

} // namespace sluice::case_file
