#pragma once
// What `sluice check`, `sluice info` and `sluice run` tell about a case's moving walls before
// anything runs: a motion that would carry a wall object out of the region the cell grid covers
// or, for an object inside a fixed tank, through the tank's walls (refused, exit code 2, naming
// the object's motion key and the time), and wave-makers asked for waves steeper than the
// breaking limit (warned).
#include "sluice/io/case_config.hpp"
#include "sluice/solver/case_check.hpp"

#include <string>
#include <vector>

namespace sluice {

// Samples every motion over [0, time.end_time] (at least 400 times, and at every row of a
// motion file) and throws CaseError on the first sample that leaves the allowed region.
void check_motion_paths(const CaseConfig& cfg, int layers);

std::vector<CaseWarning> motion_warnings(const CaseConfig& cfg);

// One line per motion (its kind, what it moves and, for a wave-maker, the wave number,
// wavelength, kh and the stroke the theory gives) and per damping zone: `sluice info`'s
// physics list.
std::vector<std::string> motion_summary(const CaseConfig& cfg);

} // namespace sluice
