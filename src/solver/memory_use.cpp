// VmRSS and VmHWM from /proc/self/status (memory_use.hpp).
#include "memory_use.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace sluice {

ResidentMemory resident_memory() {
    ResidentMemory m;
    std::ifstream status("/proc/self/status");
    std::string line;
    const auto kib = [](const std::string& rest) {
        std::istringstream in(rest);
        std::uint64_t v = 0;
        in >> v; // "VmHWM:   123456 kB"
        return v * 1024;
    };
    while (std::getline(status, line)) {
        if (line.starts_with("VmHWM:"))
            m.peak = kib(line.substr(6));
        else if (line.starts_with("VmRSS:"))
            m.now = kib(line.substr(6));
    }
    return m;
}

} // namespace sluice
