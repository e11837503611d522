// libFuzzer target for the case reader: any input must either give a validated case whose
// derived numbers are sane, or a CaseError. Any other exception, a crash, a sanitizer report,
// a hang or a large allocation is a bug. Build and run: scripts/fuzz.sh (preset `fuzz`).
//
// Input: TOML text, optionally followed by a NUL byte and --set overrides, one per line
// (TOML text cannot contain NUL, so nothing is lost by the split).
#include "sluice/io/case_reader.hpp"
#include "sluice/io/errors.hpp"
#include "sluice/solver/case_check.hpp"
#include "sluice/solver/case_memory.hpp"
#include "sluice/solver/run.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

void require(bool ok, const char* what) {
    if (!ok) {
        std::fprintf(stderr, "fuzz_case_reader: accepted case violates: %s\n", what);
        std::abort();
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    std::string_view text = input;
    std::vector<std::string> overrides;
    if (const auto nul = input.find('\0'); nul != std::string_view::npos) {
        text = input.substr(0, nul);
        std::string_view rest = input.substr(nul + 1);
        while (!rest.empty() && overrides.size() < 4) {
            const auto eol = rest.find('\n');
            overrides.emplace_back(rest.substr(0, eol));
            rest = eol == std::string_view::npos ? std::string_view() : rest.substr(eol + 1);
        }
    }
    try {
        const sluice::CaseConfig cfg = sluice::read_case_text(text, "fuzz.toml", overrides);
        // As the commands do: refused from the memory estimate before counting (1 rank, 1 GiB).
        const sluice::MemoryLimit limit{1024.0 * 1024 * 1024, "1 GiB"};
        sluice::check_memory(cfg, sluice::case_memory_before_counting(cfg, 1), limit);
        const sluice::CaseInfo info = sluice::describe_case(cfg);
        sluice::check_memory(cfg, info.memory, limit);
        sluice::check_runnable(cfg, info);
        (void)sluice::case_warnings(cfg, info);
        // What the solver relies on for an accepted case.
        require(info.fluid_particles >= 1, "at least one fluid particle");
        require(static_cast<double>(info.fluid_particles) <= sluice::hostile_case_particles,
                "fluid particles within the limit");
        require(static_cast<double>(info.wall_particles) <= sluice::hostile_case_particles,
                "wall particles within the limit");
        require(std::isfinite(info.dt_estimate) && info.dt_estimate > 0, "a finite dt > 0");
        require(cfg.end_time + info.dt_estimate > cfg.end_time, "a step that advances the clock");
        require(std::isfinite(info.memory.total()) && info.memory.total() <= limit.bytes,
                "a finite memory estimate within the limit");
        require(cfg.dx > 0 && cfg.h_over_dx > 0 && cfg.end_time > 0, "positive scales");
    } catch (const sluice::CaseError&) {
        // The expected way to refuse.
    }
    return 0;
}
