#pragma once
// The tables of a case file that control the run rather than the flow: [time], [output],
// [runtime], [checkpoint] and [limits] (docs/CASE_REFERENCE.md). Each reader refuses bad
// values (exit code 2, key named); the bounds of single keys are the schema's
// (case_schema.hpp).
#include "sluice/io/case_config.hpp"

#include "toml_section.hpp"

namespace sluice::case_file {

// [time]: end time and snapshot interval (at most kMaxOutputs snapshots).
void read_time(const Section& s, CaseConfig& c);
// [output]: snapshots on or off, their fields (no duplicates).
void read_output(const Section& s, CaseConfig& c);
// [runtime]: cell-group size and load balancing (no effect on results).
void read_runtime(const Section& s, CaseConfig& c);
// [checkpoint]: every so many steps or minutes.
void read_checkpoint_table(const Section& s, CaseConfig& c);
// [limits]: the bounds of a healthy fluid state. Needs the fluid read.
void read_limits(const Section& s, CaseConfig& c);

} // namespace sluice::case_file
