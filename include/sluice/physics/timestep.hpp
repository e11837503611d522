#pragma once
// Stable time step of explicit WCSPH (Monaghan 1992; Morris et al. 1997):
//   acoustic  dt <= C_cfl h / (c + |v|)
//   viscous   dt <= C_visc h^2 / nu
//   force     dt <= C_force sqrt(h / |a|)
#include "sluice/core/types.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sluice {

// Time steps are double in any build (sluice::Real may be float): simulated time and dt are.
struct TimeStepLimits {
    double acoustic = std::numeric_limits<double>::infinity();
    double viscous = std::numeric_limits<double>::infinity();
    double force = std::numeric_limits<double>::infinity();
    [[nodiscard]] double min() const { return std::min({acoustic, viscous, force}); }
};

struct TimeStepParams {
    double h = 0, nu = 0; // smoothing length, kinematic viscosity
    double cfl = 0.25, viscous_cfl = 0.125, force_cfl = 0.25;
};

// Limits for one particle with sound speed c, speed |v| and acceleration |a|.
inline TimeStepLimits particle_time_step(const TimeStepParams& prm, double c, double speed,
                                         double accel) {
    TimeStepLimits l;
    l.acoustic = prm.cfl * prm.h / (c + speed);
    if (prm.nu > 0)
        l.viscous = prm.viscous_cfl * prm.h * prm.h / prm.nu;
    if (accel > 0)
        l.force = prm.force_cfl * std::sqrt(prm.h / accel);
    return l;
}

// The limits over many particles, gathered from their extremes: the largest signal speed
// c + |v| and the largest |a|^2, with the divisions and the square root done once at the end
// instead of once per particle (they were most of the drift stage's own arithmetic).
// limits() equals the min over the particles of particle_time_step exactly: h / x and sqrt are
// correctly rounded and monotone, so the smallest limit is the one of the largest input.
struct TimeStepExtremes {
    double signal = 0; // largest c + |v|
    double accel2 = 0; // largest |a|^2
    bool any = false;
    void add(double c, double speed, double a2) {
        signal = std::max(signal, c + speed);
        accel2 = std::max(accel2, a2);
        any = true;
    }
    [[nodiscard]] TimeStepLimits limits(const TimeStepParams& prm) const {
        TimeStepLimits l;
        if (!any)
            return l;
        l.acoustic = prm.cfl * prm.h / signal;
        if (prm.nu > 0)
            l.viscous = prm.viscous_cfl * prm.h * prm.h / prm.nu;
        const double accel = std::sqrt(accel2);
        if (accel > 0)
            l.force = prm.force_cfl * std::sqrt(prm.h / accel);
        return l;
    }
};

// The sound speed a scheme's CFL limit uses: c0 for a weakly compressible scheme; none for an
// incompressible one (the projection scheme, docs/PROJECTION.md), where no acoustic wave is
// resolved and only the flow speed enters the CFL limit.
inline double cfl_sound_speed(bool incompressible, double c0) {
    return incompressible ? 0.0 : c0;
}

// Whether a step dt taken at time t moves the clock: finite, positive and not lost in t's
// rounding (t + dt > t). A limit can underflow to zero, be infinite (nothing limits the
// step), or be below t's resolution: each would make a run spin or jump past its end.
inline bool step_advances_clock(double t, double dt) {
    return std::isfinite(dt) && dt > 0 && t + dt > t;
}

inline TimeStepLimits min(const TimeStepLimits& a, const TimeStepLimits& b) {
    return {std::min(a.acoustic, b.acoustic), std::min(a.viscous, b.viscous),
            std::min(a.force, b.force)};
}

} // namespace sluice
