#pragma once
// A free rigid body (motion kind "free_body", docs/FLOATING_BODIES.md): its state and the
// leap-frog step that advances it under the fluid's load and gravity, with the same kick-drift
// as the fluid (physics/integrator.hpp):
//   kick:   V^{n+1/2} = V^{n-1/2} + (dt_{n-1} + dt_n)/2 A^n,   A = (F + M g)/M
//           L^{n+1/2} = L^{n-1/2} + (dt_{n-1} + dt_n)/2 T^n    (angular momentum, world frame)
//   drift:  X^{n+1} = X^n + dt_n V^{n+1/2},  R^{n+1} = exp(dt_n [Omega^{n+1/2}]x) R^n,
//           Omega^{n+1/2} = R^n I^-1 R^nT L^{n+1/2}
// F and T are the fluid's force and moment (about the centre of mass) summed by the step
// before (the load the fluid particles felt at t_{n-1}): every rank knows them once that
// step's reports are in, so the body's poses of step n are set before its graph runs, and no
// reduction waits inside a step. The one-step lag makes the coupling first order in dt (an
// error of dt dF/dt in the force; the fluid's own scheme is second order). The rotation is an
// exact rotation matrix (Rodrigues), so R stays orthonormal to round-off.
// Constraints project the load: a hinge turns about its axis through a fixed point, a planar
// body (every 2-D body) translates in the plane and turns about its normal, a fixed one stays.
// Pure numerics in double; no particle, rank or thread is known here.
#include "sluice/contact/contact_world.hpp"
#include "sluice/motion/motion_law.hpp"
#include "sluice/motion/rigid_motion.hpp"

#include <Eigen/Dense>

namespace sluice {

// Mass, centre of mass and inertia about it (world axes, the body where it is at t = 0).
struct MassProperties {
    double mass = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();
};

// A uniform box [lo, hi] of unit density: its volume as mass, its centroid, its inertia per
// unit density; 2-D (`dim` 2) per metre of width, z ignored.
MassProperties box_mass_properties(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int dim);
// A law's mass properties: what it gives (mass, centre_of_mass, inertia), the rest from
// `shape` (box_mass_properties; the law's density times its volume, its centroid, its inertia
// scaled to the mass). Without a shape the law must give all three (the case reader asks a mesh
// body for them).
MassProperties body_mass_properties(const BodyLaw& law, const std::optional<MassProperties>& shape);

// What the fluid exerts on a body: force and moment about its centre of mass.
struct BodyLoad {
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
};

// Its poses for one step (rigid_motion.hpp): at its start, its middle and its end.
struct BodyStep {
    Pose now, mid, end;
};

// A step's kick (RigidBody::kick): the half-step velocity and angular velocity it gives, the
// angular momentum, the accelerations the load gives, and the angular velocity before it.
struct BodyKick {
    bool held = true; // at rest this step (before its start, before any load, or fixed)
    double dt_prev = 0;
    Eigen::Vector3d v = Eigen::Vector3d::Zero(), omega = Eigen::Vector3d::Zero();
    Eigen::Vector3d L = Eigen::Vector3d::Zero();
    Eigen::Vector3d A = Eigen::Vector3d::Zero(), alpha = Eigen::Vector3d::Zero();
    Eigen::Vector3d omega_old = Eigen::Vector3d::Zero();
};

class RigidBody {
public:
    RigidBody() = default;
    // `law` a free_body law (its velocity, angular velocity, constraint, hinge and release
    // time), `mass` its mass properties, `gravity` the case's, `dim` 2 or 3.
    RigidBody(const MotionLaw& law, const MassProperties& mass, const Eigen::Vector3d& gravity,
              int dim);

    // Advances the body from t to t + dt (dt_prev: the step before's, 0 at the first) under
    // `fluid`, the load of the step before; returns its poses. Held at rest before the law's
    // start, and while no load is known yet (`loaded` false: the first step of a run, whose
    // wall pressures are not yet extrapolated).
    BodyStep step(double t, double dt_prev, double dt, const BodyLoad& fluid, bool loaded = true);
    // The same in two halves, so that contact (contact/contact_world.hpp) can act between
    // them: the kick, the state contact starts from, and the drift, which takes the contacts'
    // velocities and end placement when `contact` is given (free and planar bodies only).
    BodyKick kick(double t, double dt_prev, double dt, const BodyLoad& fluid, bool loaded = true);
    [[nodiscard]] ContactState contact_start(const BodyKick& k) const;
    BodyStep drift(const BodyKick& k, double dt, const ContactState* contact);
    [[nodiscard]] BodyConstraint constraint() const { return constraint_; }
    [[nodiscard]] const Eigen::Vector3d& axis() const { return axis_; }

    // The pose where the last step left it (at rest at t = 0 before the first step).
    [[nodiscard]] const Pose& pose() const { return pose_; }
    [[nodiscard]] const MassProperties& mass() const { return mass_; }
    // Centre of mass now, its velocity (the last half step's) and angular velocity.
    [[nodiscard]] const Eigen::Vector3d& centre() const { return x_; }
    [[nodiscard]] const Eigen::Matrix3d& orientation() const { return R_; }
    [[nodiscard]] const Eigen::Vector3d& velocity() const { return v_half_; }
    [[nodiscard]] Eigen::Vector3d angular_velocity() const;
    [[nodiscard]] bool released() const { return released_; }

    // The state a checkpoint keeps (and restores bitwise): x, R, V, L, released.
    [[nodiscard]] std::vector<double> state() const;
    void restore(const std::vector<double>& s);
    static constexpr std::size_t state_size = 3 + 9 + 3 + 3 + 1;

private:
    [[nodiscard]] Eigen::Vector3d omega_of(const Eigen::Matrix3d& R,
                                           const Eigen::Vector3d& L) const;
    [[nodiscard]] Pose make_pose(const Eigen::Vector3d& x, const Eigen::Matrix3d& R,
                                 const Eigen::Vector3d& v, const Eigen::Vector3d& omega,
                                 const Eigen::Vector3d& a, const Eigen::Vector3d& alpha) const;

    MassProperties mass_;
    BodyConstraint constraint_ = BodyConstraint::free;
    Eigen::Vector3d gravity_ = Eigen::Vector3d::Zero();
    Eigen::Vector3d axis_ = Eigen::Vector3d::UnitZ(); // hinge axis, plane normal (2-D: z)
    Eigen::Vector3d hinge_ = Eigen::Vector3d::Zero();
    double hinge_inertia_ = 0; // about the hinge axis through the hinge point
    double start_ = 0;
    Eigen::Vector3d v0_ = Eigen::Vector3d::Zero(), omega0_ = Eigen::Vector3d::Zero();
    int dim_ = 3;

    Eigen::Vector3d x_ = Eigen::Vector3d::Zero(); // centre of mass at the current time
    Eigen::Matrix3d R_ = Eigen::Matrix3d::Identity();
    Eigen::Vector3d v_half_ = Eigen::Vector3d::Zero(); // the last half step's
    Eigen::Vector3d L_half_ = Eigen::Vector3d::Zero(); // angular momentum, world frame
    bool released_ = false;
    Pose pose_;
};

} // namespace sluice
