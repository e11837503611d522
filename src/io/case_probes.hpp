#pragma once
// The [[probes]] tables of a case file: point and area pressure sensors, water-level gauges,
// surge fronts and wall forces (docs/CASE_REFERENCE.md, "[[probes]]").
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// Reads every [[probes]] table of `root` into c.probes, refusing bad ones (exit code 2, key
// named). Needs the domain, walls and time already read.
void read_probes(const Section& root, CaseConfig& c);

} // namespace sluice::case_file
