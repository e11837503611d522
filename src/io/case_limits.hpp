#pragma once
// Limits and tolerances shared by the readers of a case file's sections (case_fluid.cpp,
// case_walls.cpp, case_probes.cpp, case_run_control.cpp, case_size.cpp).
#include "sluice/io/case_config.hpp"

#include <algorithm>
#include <cstddef>

namespace sluice::case_file {

constexpr const char* kAxis = "xyz";
inline constexpr double kMaxOutputs = 1e7; // snapshots or probe samples per run
inline constexpr std::size_t kMaxNameLength = 200;

// Tolerance for "inside" tests, relative to the domain size: lattice edges computed by the
// user (0.1 + 0.2) must not be refused for a rounding error.
inline double slack(const CaseConfig& c) {
    double size = 0;
    for (int a = 0; a < c.dimension; ++a)
        size = std::max(size, c.domain_hi[static_cast<std::size_t>(a)] -
                                  c.domain_lo[static_cast<std::size_t>(a)]);
    return 1e-9 * size;
}

} // namespace sluice::case_file
