#include "sluice/motion/motion_law.hpp"

#include "sluice/motion/motion_series.hpp"
#include "sluice/motion/wave_theory.hpp"

#include <numbers>
#include <stdexcept>

namespace sluice {
namespace {

constexpr double kDegree = std::numbers::pi / 180;

Eigen::Vector3d vec(const MotionLaw::V3& v) {
    return {v[0], v[1], v[2]};
}

// A scalar signal s(t) along a fixed unit direction e: the translation's three components.
void along(RigidMotion& m, const Eigen::Vector3d& e, const Signal& s) {
    for (int k = 0; k < 3; ++k) {
        if (e[k] == 0)
            continue;
        const double ek = e[k];
        m.translation[static_cast<std::size_t>(k)] = [s, ek](double t) {
            const SignalValue v = s(t);
            return SignalValue{ek * v.value, ek * v.rate, ek * v.accel};
        };
    }
}

// A vector quantity q as the product of its length and its direction.
void along_vector(RigidMotion& m, const MotionLaw::V3& q,
                  const std::function<Signal(double)>& signal_of_length) {
    const Eigen::Vector3d v = vec(q);
    const double n = v.norm();
    if (n > 0)
        along(m, v / n, signal_of_length(n));
}

} // namespace

bool body_in_contact(const MotionLaw& law, bool is_box) {
    if (!is_box || law.kind != MotionKind::free_body)
        return false;
    const BodyConstraint c = law.body.constraint;
    const auto& n = law.axis;
    const bool axis_aligned = (n[0] != 0) + (n[1] != 0) + (n[2] != 0) == 1;
    return c == BodyConstraint::free || (c == BodyConstraint::plane && axis_aligned);
}

RigidMotion make_motion(const MotionLaw& law) {
    RigidMotion m;
    m.centre = vec(law.centre);
    const Eigen::Vector3d axis = vec(law.axis);
    m.axis = axis.norm() > 0 ? Eigen::Vector3d(axis.normalized()) : Eigen::Vector3d::UnitZ();
    switch (law.kind) {
    case MotionKind::sway:
        along_vector(m, law.amplitude, [&](double a) {
            return sinusoid(a, law.period, law.phase * kDegree, law.start, law.ramp);
        });
        break;
    case MotionKind::roll:
        m.angle =
            sinusoid(law.angle * kDegree, law.period, law.phase * kDegree, law.start, law.ramp);
        break;
    case MotionKind::constant_velocity:
        along_vector(m, law.velocity,
                     [&](double u) { return constant_rate(u, law.start, law.ramp); });
        break;
    case MotionKind::constant_acceleration:
        along_vector(m, law.acceleration,
                     [&](double a) { return constant_acceleration(a, law.start, law.ramp); });
        break;
    case MotionKind::file: {
        // Shifted by `start`: the series' t = 0 is the run's t = start.
        std::vector<double> t = law.series_t;
        for (double& s : t)
            s += law.start;
        for (std::size_t k = 0; k < 3; ++k) {
            std::vector<double> d;
            bool moves = false;
            for (const auto& row : law.series_d) {
                d.push_back(row[k]);
                moves = moves || row[k] != law.series_d.front()[k];
            }
            if (moves)
                m.translation[k] = series_signal(t, std::move(d));
        }
        std::vector<double> a;
        bool turns = false;
        for (double deg : law.series_angle) {
            a.push_back(deg * kDegree);
            turns = turns || deg != law.series_angle.front();
        }
        if (turns)
            m.angle = series_signal(t, std::move(a));
        break;
    }
    case MotionKind::piston:
        along(m, vec(law.direction).normalized(),
              piston_displacement(RegularWave{law.wave_height, law.wave_period, law.depth, law.g},
                                  0.0, law.start, law.ramp, law.second_order));
        break;
    case MotionKind::flap: {
        // flap_angle is the paddle's lean towards the waves (+x); about +z that is -theta.
        const Signal lean =
            flap_angle(RegularWave{law.wave_height, law.wave_period, law.depth, law.g}, 0.0,
                       law.start, law.ramp);
        m.angle = [lean](double t) {
            const SignalValue v = lean(t);
            return SignalValue{-v.value, -v.rate, -v.accel};
        };
        break;
    }
    case MotionKind::piston_irregular: {
        JonswapSea sea;
        sea.hs = law.hs;
        sea.tp = law.tp;
        sea.depth = law.depth;
        sea.gamma = law.gamma;
        sea.g = law.g;
        sea.components = law.components;
        sea.seed = law.seed;
        along(m, vec(law.direction).normalized(), piston_irregular(sea, law.start, law.ramp));
        break;
    }
    case MotionKind::free_body: // at rest: the solver integrates its motion
        break;
    }
    return m;
}

} // namespace sluice
