#pragma once
// The resident memory of this process, now and at its peak so far (Linux: VmRSS and VmHWM of
// /proc/self/status), for the per-rank log lines that perf/memory reads. Private to src/solver.
#include <cstdint>

namespace sluice {

struct ResidentMemory {
    std::uint64_t now = 0, peak = 0; // bytes; 0 where /proc/self/status lacks them (not Linux)
};

ResidentMemory resident_memory();

} // namespace sluice
