#pragma once
// The [[motions]] tables of a case file and the wall objects' references to them
// (docs/CASE_REFERENCE.md, "[[motions]]").
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

#include <string_view>

namespace sluice::case_file {

// Reads every [[motions]] table of `root` into c.motions (a motion file read and checked),
// refusing bad ones (exit code 2, key named). Needs [case], [fluid] and [walls].model read.
void read_motions(const Section& root, CaseConfig& c);

// Reads every [[damping_zones]] table into c.damping_zones.
void read_damping_zones(const Section& root, CaseConfig& c);

// The c.motions index named by key `k` of `s` (walls.tank_motion, walls.boxes[i].motion, ...),
// -1 when the key is absent; an unknown name is refused.
int motion_reference(const Section& s, std::string_view k, const CaseConfig& c);

// What needs the whole case: every motion used by a wall object, a motion file covering the
// run, no motion with run-ahead or a periodic axis. After [time] and [runtime].
void check_motions(const Section& root, const CaseConfig& c);

} // namespace sluice::case_file
