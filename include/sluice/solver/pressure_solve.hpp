#pragma once
// What the pressure Poisson solve of the projection scheme reports (docs/PROJECTION.md).
#include <algorithm>

namespace sluice {

struct PressureSolveRecord {
    int iterations = 0;      // BiCGSTAB iterations (two operator products each) or SOR sweeps
    double residual = 0;     // final |bhat - A p| / |bhat| of the row-scaled system (recomputed;
                             // without a free surface / max(|bhat|, initial residual))
    bool free_level = false; // no free-surface row: the mean pressure was fixed instead
    double seconds = 0;      // wall time of the solve on this rank
    // Without a free surface: the uniform correction lambda of the scaled source of every
    // fluid row that made the singular system compatible (docs/PROJECTION.md, "No free
    // surface"), in Pa; 0 when a free surface fixes the pressure level.
    double source_shift = 0;
    // SOR: the over-relaxed sweep diverged and the solve went on with relaxation 1.
    bool relaxation_dropped = false;
};

struct PressureSolveTotals {
    long solves = 0;
    long iterations = 0;
    int max_iterations = 0;
    double max_residual = 0;
    double seconds = 0;
    long relaxation_dropped = 0; // SOR solves that went on with relaxation 1
    void add(const PressureSolveRecord& r) {
        ++solves;
        iterations += r.iterations;
        max_iterations = std::max(max_iterations, r.iterations);
        max_residual = std::max(max_residual, r.residual);
        seconds += r.seconds;
        relaxation_dropped += r.relaxation_dropped ? 1 : 0;
    }
};

} // namespace sluice
