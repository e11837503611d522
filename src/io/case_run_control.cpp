// The [time], [output], [runtime], [checkpoint] and [limits] tables of a case file
// (case_run_control.hpp).
#include "case_run_control.hpp"

#include "case_limits.hpp"

#include <fmt/format.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sluice::case_file {
namespace {

const std::vector<std::pair<std::string, BalanceCost>> kBalanceCost = {
    {"time", BalanceCost::time}, {"particles", BalanceCost::particles}};
const std::vector<std::pair<std::string, InitialDecomposition>> kInitialDecomposition = {
    {"balanced", InitialDecomposition::balanced}, {"key-range", InitialDecomposition::key_range}};

} // namespace

void read_time(const Section& s, CaseConfig& c) {
    c.end_time = s.required_number("end_time", "simulated time to reach [s]");
    c.output_interval = s.number("output_interval", c.output_interval);
    s.require(
        c.output_interval == 0 || c.end_time / c.output_interval <= kMaxOutputs, "output_interval",
        fmt::format("{} s would write {:.3g} snapshots up to end_time = {} s; at most {:g}",
                    c.output_interval, c.end_time / c.output_interval, c.end_time, kMaxOutputs));
}

void read_output(const Section& s, CaseConfig& c) {
    c.snapshots = s.boolean("snapshots").value_or(c.snapshots);
    if (auto f = s.strings("fields")) {
        std::set<std::string> seen;
        for (const auto& name : *f)
            s.require(seen.insert(name).second, "fields",
                      fmt::format("field \"{}\" is listed twice", name));
        c.fields = *f;
    }
}

void read_runtime(const Section& s, CaseConfig& c) {
    c.particles_per_group =
        static_cast<int>(s.integer("particles_per_group").value_or(c.particles_per_group));
    c.rebalance_threshold = s.number("rebalance_threshold", c.rebalance_threshold);
    c.rebalance_window =
        static_cast<int>(s.integer("rebalance_window").value_or(c.rebalance_window));
    c.rebalance_every = static_cast<int>(s.integer("rebalance_every").value_or(c.rebalance_every));
    c.balance_cost = s.choice("balance_cost", c.balance_cost, kBalanceCost);
    c.initial_decomposition =
        s.choice("initial_decomposition", c.initial_decomposition, kInitialDecomposition);
    c.run_ahead = s.boolean("run_ahead").value_or(c.run_ahead);
}

void read_checkpoint_table(const Section& s, CaseConfig& c) {
    c.checkpoint_every_steps =
        static_cast<int>(s.integer("every_steps").value_or(c.checkpoint_every_steps));
    c.checkpoint_every_minutes = s.number("every_minutes", c.checkpoint_every_minutes);
}

// Bounds of a healthy fluid state; beyond them the run stops as blown up.
void read_limits(const Section& s, CaseConfig& c) {
    c.max_speed = s.number("max_speed", c.sound_speed);
    c.min_density = s.number("min_density", 0.01 * c.rho0);
    c.max_density = s.number("max_density", 2 * c.rho0);
    s.require(c.min_density < c.rho0, "min_density",
              fmt::format("must be below fluid.rho0 = {}, got {}", c.rho0, c.min_density));
    s.require(c.max_density > c.rho0, "max_density",
              fmt::format("must be above fluid.rho0 = {}, got {}", c.rho0, c.max_density));
}

} // namespace sluice::case_file
