// VmHWM from /proc/self/status (memory_use.hpp).
#include "memory_use.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace sluice {

std::uint64_t peak_resident_bytes() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (!line.starts_with("VmHWM:"))
            continue;
        std::istringstream in(line.substr(6));
        std::uint64_t kib = 0;
        in >> kib; // "VmHWM:   123456 kB"
        return kib * 1024;
    }
    return 0;
}

} // namespace sluice
