#pragma once
// The peak resident memory of this process so far (Linux: VmHWM of /proc/self/status), for the
// per-rank log lines that perf/memory reads. Private to src/solver.
#include <cstdint>

namespace sluice {

// Bytes; 0 where /proc/self/status has no VmHWM (not Linux).
std::uint64_t peak_resident_bytes();

} // namespace sluice
