#pragma once
// Reads and validates a TOML case file (layout: docs/CASE_REFERENCE.md).
#include "sluice/io/case_config.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace sluice {

// Parses `path`, applies `overrides` and returns a fully validated case.
//
// Each override is "key=value" (from `--set`): the key is a dotted path such as
// "numerics.kernel" or "blocks.0.lo" (also written "blocks[0].lo"); the value is parsed as a
// TOML value, and text that is not valid TOML is taken as a string, so
// `numerics.kernel=wendland_c2` works without quotes. Overrides may only name keys the
// schema knows, and entries of [[blocks]] / [[probes]] / [[walls.planes]] that exist.
//
// Every problem (unreadable file, syntax, unknown key, wrong type, missing key, impossible
// value) throws sluice::CaseError naming the file, the offending key and the reason.
CaseConfig read_case(const std::string& path, const std::vector<std::string>& overrides = {});

// The same for a case held in memory (tests, the fuzzer); `name` stands for the file in
// messages and gives the default case name.
CaseConfig read_case_text(std::string_view text, const std::string& name,
                          const std::vector<std::string>& overrides = {});

// Every key of every table of a case file, as a JSON array of objects {table, key, type, unit,
// default, range, applies ("any", "wcsph" or "projection": the numerics.scheme that reads it;
// refused under the other), when (a further condition, "KEY = VALUE"), doc} (`sluice schema`).
std::string case_schema_json();

// Particles (fluid, or dummy walls) past which a case is refused as hostile input before
// anything is counted or allocated: at the few hundred bytes each a particle needs at least
// (perf/memory/README.md, "Memory estimate") that is hundreds of TiB, beyond any machine at any
// rank count. Whether a case fits is decided from the memory estimate per rank
// (sluice/io/memory_estimate.hpp), not from this bound.
inline constexpr double hostile_case_particles = 1e12;

} // namespace sluice
