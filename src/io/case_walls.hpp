#pragma once
// The [walls] table of a case file (model, tank faces, planes, obstacle boxes) and the check
// that the fluid starts inside the walled tank (docs/CASE_REFERENCE.md, "[walls]").
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// Reads [walls] into c, refusing bad values (exit code 2, key named). Needs the domain, fluid
// blocks and numerics already read.
void read_walls(const Section& s, CaseConfig& c);

// Fluid must start on the inner side of every wall-carrying tank face, with room for one
// lattice site before a walled upper face.
void check_blocks_in_tank(const Section& root, const CaseConfig& c);

} // namespace sluice::case_file
