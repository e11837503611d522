#pragma once
// A prescribed rigid motion of a wall object: a translation d(t), one Signal per axis, and a
// rotation by an angle theta(t) about a fixed axis n through a centre c that moves with the
// translation. A point of the object at x0 at t = 0 is at
//     x(t) = c + d(t) + R(n, theta(t)) (x0 - c),
// with velocity v = d' + omega x r and acceleration a = d'' + alpha x r + omega x (omega x r),
// r = R (x0 - c), omega = theta' n, alpha = theta'' n (rotation about a fixed axis). In 2-D the
// axis is z (out of the plane) and z components are zero. Poses are double (simulated time and
// the case's values stay double); they enter the particle state through Real(...).
#include "sluice/core/types.hpp"
#include "sluice/motion/signal.hpp"

#include <Eigen/Geometry>
#include <array>
#include <limits>

namespace sluice {

// The state of a rigid motion at one time: what every particle of the object needs.
struct Pose {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); // c (at t = 0)
    Eigen::Vector3d d = Eigen::Vector3d::Zero();      // translation and its derivatives
    Eigen::Vector3d d_rate = Eigen::Vector3d::Zero();
    Eigen::Vector3d d_accel = Eigen::Vector3d::Zero();
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d omega = Eigen::Vector3d::Zero(); // angular velocity
    Eigen::Vector3d alpha = Eigen::Vector3d::Zero(); // angular acceleration
    double angle = 0;                                // theta, about the motion's axis
    double angle_rate = 0;                           // its rate

    [[nodiscard]] Eigen::Vector3d arm(const Eigen::Vector3d& x0) const { return R * (x0 - centre); }
    [[nodiscard]] Eigen::Vector3d position(const Eigen::Vector3d& x0) const {
        return centre + d + arm(x0);
    }
    [[nodiscard]] Eigen::Vector3d velocity(const Eigen::Vector3d& x0) const {
        return d_rate + omega.cross(arm(x0));
    }
    [[nodiscard]] Eigen::Vector3d acceleration(const Eigen::Vector3d& x0) const {
        const Eigen::Vector3d r = arm(x0);
        return d_accel + alpha.cross(r) + omega.cross(omega.cross(r));
    }
    // The object's point (its position at t = 0) that is at x now: x0 = c + R^T (x - c - d).
    [[nodiscard]] Eigen::Vector3d body_point(const Eigen::Vector3d& x) const {
        return centre + R.transpose() * (x - centre - d);
    }
    // A direction fixed in the object (e.g. a sensor's normal), turned with it.
    [[nodiscard]] Eigen::Vector3d direction(const Eigen::Vector3d& n0) const { return R * n0; }
};

// The axis-aligned box [lo, hi] of an object's t = 0 placement moved by a pose: the box around
// its moved corners (the first `dim` axes; the others stay as given).
struct Bounds {
    Eigen::Vector3d lo, hi;
};
inline Bounds moved_bounds(const Bounds& at_rest, const Pose& pose, int dim) {
    const double inf = std::numeric_limits<double>::infinity();
    Bounds out{Eigen::Vector3d::Constant(inf), Eigen::Vector3d::Constant(-inf)};
    for (int corner = 0; corner < (1 << dim); ++corner) {
        Eigen::Vector3d c = at_rest.lo;
        for (int a = 0; a < dim; ++a)
            c[a] = (corner >> a) & 1 ? at_rest.hi[a] : at_rest.lo[a];
        const Eigen::Vector3d x = pose.position(c);
        out.lo = out.lo.cwiseMin(x);
        out.hi = out.hi.cwiseMax(x);
    }
    for (int a = dim; a < 3; ++a) {
        out.lo[a] = at_rest.lo[a];
        out.hi[a] = at_rest.hi[a];
    }
    return out;
}

struct RigidMotion {
    std::array<Signal, 3> translation{zero_signal(), zero_signal(), zero_signal()};
    Signal angle = zero_signal();
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); // unit; z in 2-D
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();

    [[nodiscard]] Pose pose(double t) const {
        Pose p;
        p.centre = centre;
        for (int k = 0; k < 3; ++k) {
            const SignalValue s = translation[static_cast<std::size_t>(k)](t);
            p.d[k] = s.value;
            p.d_rate[k] = s.rate;
            p.d_accel[k] = s.accel;
        }
        const SignalValue th = angle(t);
        p.angle = th.value;
        p.angle_rate = th.rate;
        p.R = Eigen::AngleAxisd(th.value, axis).toRotationMatrix();
        p.omega = th.rate * axis;
        p.alpha = th.accel * axis;
        return p;
    }
};

// A D-vector of the particle state as a 3-vector of the pose's arithmetic, and back.
template <int D>
Eigen::Vector3d to_pose_point(const Vec<D>& x) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int k = 0; k < D; ++k)
        p[k] = double(x[k]);
    return p;
}
template <int D>
Vec<D> from_pose_point(const Eigen::Vector3d& p) {
    Vec<D> x;
    for (int k = 0; k < D; ++k)
        x[k] = Real(p[k]);
    return x;
}

} // namespace sluice
