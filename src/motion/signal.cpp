#include "sluice/motion/signal.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sluice {

Signal zero_signal() {
    return [](double) { return SignalValue{}; };
}

SignalValue smooth_ramp(double t, double start, double duration) {
    if (t <= start)
        return {};
    if (duration <= 0 || t >= start + duration)
        return {1, 0, 0};
    const double u = (t - start) / duration;
    const double u2 = u * u, u3 = u2 * u;
    return {u3 * (10 - 15 * u + 6 * u2), 30 * u2 * (1 - u) * (1 - u) / duration,
            60 * u * (1 - u) * (1 - 2 * u) / (duration * duration)};
}

SignalValue ramped(const SignalValue& f, const SignalValue& r) {
    return {f.value * r.value, f.rate * r.value + f.value * r.rate,
            f.accel * r.value + 2 * f.rate * r.rate + f.value * r.accel};
}

Signal sinusoid(double amplitude, double period, double phase, double start, double ramp) {
    const double w = 2 * std::numbers::pi / period;
    return [=](double t) {
        if (t <= start)
            return SignalValue{};
        const double arg = w * (t - start) + phase;
        const SignalValue f{amplitude * std::sin(arg), amplitude * w * std::cos(arg),
                            -amplitude * w * w * std::sin(arg)};
        return ramped(f, smooth_ramp(t, start, ramp));
    };
}

namespace {
// Integral over [start, t] of the smooth ramp: the antiderivative of the smoothstep,
// duration (5u^4/2 - 3u^5 + u^6) on the ramp, then t - start - duration/2.
double ramp_integral(double t, double start, double duration) {
    if (t <= start)
        return 0;
    if (duration <= 0)
        return t - start;
    if (t >= start + duration)
        return t - start - duration / 2;
    const double u = (t - start) / duration;
    const double u4 = u * u * u * u;
    return duration * u4 * (2.5 - 3 * u + u * u);
}

// Double integral over [start, t] of the smooth ramp.
double ramp_double_integral(double t, double start, double duration) {
    if (t <= start)
        return 0;
    const double s = t - start;
    if (duration <= 0)
        return s * s / 2;
    if (t >= start + duration) { // D^2/7 at the ramp's end, then at rate D/2 + (t - end)
        const double after = s - duration;
        return duration * duration / 7 + (duration / 2) * after + after * after / 2;
    }
    const double u = s / duration;
    const double u5 = u * u * u * u * u;
    return duration * duration * u5 * (0.5 - 0.5 * u + u * u / 7);
}
} // namespace

Signal constant_rate(double rate, double start, double ramp) {
    return [=](double t) {
        const SignalValue r = smooth_ramp(t, start, ramp);
        return SignalValue{rate * ramp_integral(t, start, ramp), rate * r.value, rate * r.rate};
    };
}

Signal constant_acceleration(double accel, double start, double ramp) {
    return [=](double t) {
        const SignalValue r = smooth_ramp(t, start, ramp);
        return SignalValue{accel * ramp_double_integral(t, start, ramp),
                           accel * ramp_integral(t, start, ramp), accel * r.value};
    };
}

Signal sum_of(std::vector<Signal> parts) {
    return [parts = std::move(parts)](double t) {
        SignalValue s;
        for (const Signal& p : parts) {
            const SignalValue v = p(t);
            s.value += v.value;
            s.rate += v.rate;
            s.accel += v.accel;
        }
        return s;
    };
}

} // namespace sluice
