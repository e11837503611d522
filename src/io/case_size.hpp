#pragma once
// The size of a case, checked before anything is allocated: the fluid lattice, the dummy-wall
// lattice around the tank and the micro-cell grid (docs/CASE_REFERENCE.md, particles.dx).
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// Refuses (naming particles.dx) a case whose particles or grid cells exceed the limits.
// Needs every table but the run controls read.
void check_case_size(const Section& root, const CaseConfig& c);

} // namespace sluice::case_file
