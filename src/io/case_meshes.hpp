#pragma once
// The [[walls.meshes]] entries of a case file: each shape's file read, placed and checked
// (docs/CASE_REFERENCE.md, "[[walls.meshes]]").
#include "sluice/geometry/shape_report.hpp"
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// Reads every [[walls.meshes]] entry of [walls] into c.meshes, refusing (exit code 2, file and
// key named) a missing, unreadable, empty or oversized file, an unknown format, non-finite
// vertices, degenerate elements beyond 1 %, a solid that is not closed or whose normals point
// inwards, and a shape outside the domain. Needs the domain, particles and walls model read.
void read_wall_meshes(const Section& walls, CaseConfig& c);

// The shape keys of one entry (file, scale, rotation, translation, flip_normals, section_z)
// into m, the file read, placed, indexed and checked (readable, degenerate elements below 1 %,
// inside the domain); returns its report. [[walls.meshes]] and [[blocks]] with shape = "mesh".
ShapeReport read_shape_file(const Section& s, const CaseConfig& c, WallMesh& m);

// Refuses (naming `file`, or `role` when `instead` is offered) a shape that is not closed, and
// (naming flip_normals) one whose normals point inwards.
void require_closed_outward(const Section& s, const CaseConfig& c, const WallMesh& m,
                            const ShapeReport& r, const std::string& what,
                            const std::string& instead);

} // namespace sluice::case_file
