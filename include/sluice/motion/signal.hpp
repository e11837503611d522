#pragma once
// A scalar function of time with its first two derivatives: one coordinate of a prescribed
// motion (a displacement along an axis, or an angle). Formulas (sinusoid, constant rate,
// constant acceleration, smooth ramps) and time series (motion/motion_series.hpp) are Signals;
// a motion is a few of them (motion/rigid_motion.hpp). Pure numerics, double throughout:
// simulated time and a wall's pose stay double whatever the particles' Real is.
#include <functional>
#include <vector>

namespace sluice {

struct SignalValue {
    double value = 0; // displacement [m] or angle [rad]
    double rate = 0;  // its time derivative
    double accel = 0; // its second time derivative
};

using Signal = std::function<SignalValue(double t)>;

// The signal that stays 0.
Signal zero_signal();

// A smooth switch from 0 (t <= start) to 1 (t >= start + duration): the quintic smoothstep
// s(u) = 10u^3 - 15u^4 + 6u^5, whose first and second derivatives vanish at both ends, so a
// ramped motion starts with no jump in velocity or acceleration (a jump in acceleration is a
// jump in the Adami wall pressure). duration = 0 is a step at `start`.
SignalValue smooth_ramp(double t, double start, double duration);

// f(t) r(t) with r the smooth ramp above (product rule for the derivatives).
SignalValue ramped(const SignalValue& f, const SignalValue& r);

// amplitude sin(2 pi (t - start) / period + phase) for t > start, ramped in over `ramp`
// seconds; 0 before start. (phase != 0 starts with an offset: the ramp takes it in smoothly.)
Signal sinusoid(double amplitude, double period, double phase, double start, double ramp);

// A displacement at constant rate u after `start`, its rate ramped in over `ramp` seconds:
// value = u (integral of the ramp), rate = u r(t), accel = u r'(t).
Signal constant_rate(double rate, double start, double ramp);

// accel/2 (t - start)^2 after start (a uniformly accelerated wall), ramped over `ramp` seconds
// in its acceleration like constant_rate is in its rate.
Signal constant_acceleration(double accel, double start, double ramp);

// The sum of several signals (e.g. a wave-maker's components).
Signal sum_of(std::vector<Signal> parts);

} // namespace sluice
