#pragma once
// The record the still-tank tests read: a 2-D case run on one thread (one cell grouping, so the
// printed figures repeat on any machine), its first probe's Shepard pressure sampled every
// `interval` seconds of simulated time from `from` to the end time, reduced to its mean and
// standard deviation (the noise), beside the hydrostatic pressure rho0 |g| (H - y) at the probe
// under the first block's top H.
#include "sluice/physics/probes.hpp"
#include "sluice/solver/simulation.hpp"

#include <algorithm>
#include <cmath>

namespace sluice::testing {

struct TankRecord {
    double p_ref = 0, mean = 0, noise = 0;
    int samples = 0;
};

inline TankRecord tank_record(const CaseConfig& cfg, double interval, double from) {
    SimulationOptions opts;
    opts.threads = 1;
    Simulation<2> sim(cfg, opts);
    const auto& probe = cfg.probes.at(0);
    const Vec<2> point(probe.position[0], probe.position[1]);
    TankRecord out;
    out.p_ref = cfg.rho0 * std::abs(cfg.gravity[1]) * (cfg.blocks.at(0).hi[1] - point[1]);
    double sum = 0, sum2 = 0, next = interval;
    while (sim.time() < cfg.end_time - 1e-9) {
        sim.step();
        if (sim.time() < next - 1e-9)
            continue;
        next += interval;
        if (sim.time() < from - 1e-9)
            continue;
        const double p = pressure_probe(sim.particles(), sim.kernel(), point);
        sum += p;
        sum2 += p * p;
        ++out.samples;
    }
    if (out.samples > 0) {
        out.mean = sum / out.samples;
        out.noise = std::sqrt(std::max(0.0, sum2 / out.samples - out.mean * out.mean));
    }
    return out;
}

} // namespace sluice::testing
