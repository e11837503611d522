#pragma once
// The [[walls.meshes]] entries of a case file: each shape's file read, placed and checked
// (docs/CASE_REFERENCE.md, "[[walls.meshes]]").
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// Reads every [[walls.meshes]] entry of [walls] into c.meshes, refusing (exit code 2, file and
// key named) a missing, unreadable, empty or oversized file, an unknown format, non-finite
// vertices, degenerate elements beyond 1 %, a solid that is not closed or whose normals point
// inwards, and a shape outside the domain. Needs the domain, particles and walls model read.
void read_wall_meshes(const Section& walls, CaseConfig& c);

} // namespace sluice::case_file
