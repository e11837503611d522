#pragma once
// The [case], [domain], [fluid], [particles] and [[blocks]] tables of a case file: what the
// fluid is and where it starts (docs/CASE_REFERENCE.md). Each reader refuses bad values (exit
// code 2, key named); the bounds of single keys are the schema's (case_schema.hpp).
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

#include <string>

namespace sluice::case_file {

// [case]: dimension (also set on the reader: vector lengths depend on it), name (default: the
// stem of `path`), description.
void read_case_table(const Section& s, CaseConfig& c, Reader& r, const std::string& path);
// [domain]: corners and periodic axes.
void read_domain(const Section& s, CaseConfig& c);
// [fluid]: density, viscosity, sound speed, gravity, equation of state.
void read_fluid(const Section& s, CaseConfig& c);
// [particles]: lattice spacing and jitter.
void read_particles(const Section& s, CaseConfig& c);
// Every [[blocks]] table of `root`: inside the domain, not overlapping, with its shape and
// velocity profile. Needs the domain and the fluid.
void read_blocks(const Section& root, CaseConfig& c);
// A block thinner than dx/2 along an axis would hold no particle. Needs particles.dx.
void check_block_thickness(const Section& root, const CaseConfig& c);

} // namespace sluice::case_file
