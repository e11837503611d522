#include "sluice/motion/rigid_body.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>

namespace sluice {
namespace {

Eigen::Vector3d to_vector3(const std::array<double, 3>& a) {
    return {a[0], a[1], a[2]};
}

// R turned by the rotation vector w (angle |w| about w/|w|), kept orthonormal: the product
// goes through a unit quaternion, so round-off does not accumulate into R over many steps.
Eigen::Matrix3d turned(const Eigen::Vector3d& w, const Eigen::Matrix3d& R) {
    const double angle = w.norm();
    if (angle == 0)
        return R;
    const Eigen::Quaterniond q =
        (Eigen::Quaterniond(Eigen::AngleAxisd(angle, w / angle)) * Eigen::Quaterniond(R))
            .normalized();
    return q.toRotationMatrix();
}

} // namespace

MassProperties box_mass_properties(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int dim) {
    const Eigen::Vector3d e = hi - lo;
    MassProperties m;
    m.centre = 0.5 * (lo + hi);
    if (dim == 2)
        m.centre.z() = 0;
    const double a = e.x(), b = e.y(), c = dim == 3 ? e.z() : 0.0;
    m.mass = dim == 3 ? a * b * c : a * b;
    m.inertia = Eigen::Matrix3d::Zero();
    m.inertia(0, 0) = m.mass * (b * b + c * c) / 12;
    m.inertia(1, 1) = m.mass * (a * a + c * c) / 12;
    m.inertia(2, 2) = m.mass * (a * a + b * b) / 12;
    return m;
}

MassProperties body_mass_properties(const BodyLaw& law,
                                    const std::optional<MassProperties>& shape) {
    if (!shape && !(law.mass > 0 && law.centre_of_mass && law.inertia))
        throw std::invalid_argument("a body without a shape needs its mass, centre of mass and "
                                    "inertia");
    MassProperties m;
    m.mass = law.mass > 0 ? law.mass : law.density * shape->mass;
    m.centre = law.centre_of_mass ? to_vector3(*law.centre_of_mass) : shape->centre;
    if (law.inertia) {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                m.inertia(r, c) = (*law.inertia)[static_cast<std::size_t>(3 * r + c)];
    } else {
        m.inertia = shape->inertia * (m.mass / shape->mass);
    }
    return m;
}

RigidBody::RigidBody(const MotionLaw& law, const MassProperties& mass,
                     const Eigen::Vector3d& gravity, int dim)
    : mass_(mass), constraint_(law.body.constraint), gravity_(gravity), start_(law.start),
      v0_(to_vector3(law.velocity)), omega0_(to_vector3(law.body.angular_velocity)), dim_(dim) {
    if (dim == 2) {
        // Every 2-D body moves in its plane: free is planar about z; a hinge turns about z.
        if (constraint_ == BodyConstraint::free)
            constraint_ = BodyConstraint::plane;
        axis_ = Eigen::Vector3d::UnitZ();
        gravity_.z() = 0;
        v0_.z() = 0;
        omega0_ = Eigen::Vector3d(0, 0, omega0_.z());
    } else if (constraint_ == BodyConstraint::hinge || constraint_ == BodyConstraint::plane) {
        axis_ = to_vector3(law.axis).normalized();
    }
    hinge_ = to_vector3(law.centre);
    if (dim == 2)
        hinge_.z() = 0;
    const Eigen::Vector3d r = mass_.centre - hinge_;
    const Eigen::Vector3d r_perp = r - axis_ * axis_.dot(r);
    hinge_inertia_ = axis_.dot(mass_.inertia * axis_) + mass_.mass * r_perp.squaredNorm();
    x_ = mass_.centre;
    pose_ = make_pose(x_, R_, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
}

Eigen::Vector3d RigidBody::omega_of(const Eigen::Matrix3d& R, const Eigen::Vector3d& L) const {
    switch (constraint_) {
    case BodyConstraint::free:
        return R * mass_.inertia.ldlt().solve(R.transpose() * L);
    case BodyConstraint::plane:
        return axis_ * (axis_.dot(L) / axis_.dot(mass_.inertia * axis_));
    case BodyConstraint::hinge:
        return axis_ * (axis_.dot(L) / hinge_inertia_);
    case BodyConstraint::fixed:
        break;
    }
    return Eigen::Vector3d::Zero();
}

Eigen::Vector3d RigidBody::angular_velocity() const {
    return omega_of(R_, L_half_);
}

Pose RigidBody::make_pose(const Eigen::Vector3d& x, const Eigen::Matrix3d& R,
                          const Eigen::Vector3d& v, const Eigen::Vector3d& omega,
                          const Eigen::Vector3d& a, const Eigen::Vector3d& alpha) const {
    Pose p;
    p.centre = mass_.centre;
    p.d = x - mass_.centre;
    p.d_rate = v;
    p.d_accel = a;
    p.R = R;
    p.omega = omega;
    p.alpha = alpha;
    if (dim_ == 2) {
        p.angle = std::atan2(R(1, 0), R(0, 0));
        p.angle_rate = omega.z();
    } else {
        p.angle = Eigen::AngleAxisd(R).angle();
        p.angle_rate = omega.norm();
    }
    return p;
}

BodyKick RigidBody::kick(double t, double dt_prev, double dt, const BodyLoad& fluid, bool loaded) {
    BodyKick k;
    if (!released_) {
        if (t < start_ || !loaded || constraint_ == BodyConstraint::fixed)
            return k; // held
        // Released: from the law's velocities, as the fluid starts (no step before).
        released_ = true;
        dt_prev = 0;
        const Eigen::Matrix3d I_world = R_ * mass_.inertia * R_.transpose();
        switch (constraint_) {
        case BodyConstraint::free:
            v_half_ = v0_;
            L_half_ = I_world * omega0_;
            break;
        case BodyConstraint::plane:
            v_half_ = v0_ - axis_ * axis_.dot(v0_);
            L_half_ = axis_ * (axis_.dot(omega0_) * axis_.dot(mass_.inertia * axis_));
            break;
        case BodyConstraint::hinge:
            L_half_ = axis_ * (axis_.dot(omega0_) * hinge_inertia_);
            v_half_ = omega_of(R_, L_half_).cross(x_ - hinge_);
            break;
        case BodyConstraint::fixed:
            break;
        }
    }
    k.held = false;
    k.dt_prev = dt_prev;
    const double w = 0.5 * (dt_prev + dt);
    const Eigen::Vector3d F = fluid.force + mass_.mass * gravity_;
    k.omega_old = omega_of(R_, L_half_);
    // The load's effect under the constraint: the centre's acceleration A and the rate of the
    // angular momentum (about the centre; a hinge's about its axis through the hinge point).
    k.A = F / mass_.mass;
    Eigen::Vector3d torque = fluid.moment;
    if (constraint_ == BodyConstraint::plane) {
        k.A -= axis_ * axis_.dot(k.A);
        torque = axis_ * axis_.dot(torque);
    } else if (constraint_ == BodyConstraint::hinge) {
        torque = axis_ * axis_.dot(fluid.moment + (x_ - hinge_).cross(F));
    }
    k.L = L_half_ + w * torque;
    k.omega = omega_of(R_, k.L);
    k.v = v_half_ + w * k.A;
    // The angular acceleration at the start of the step (the walls' Adami extrapolation reads
    // the wall's acceleration): the rate of omega the torque gives.
    k.alpha = w > 0 ? Eigen::Vector3d((k.omega - k.omega_old) / w)
                    : Eigen::Vector3d(omega_of(R_, torque));
    return k;
}

ContactState RigidBody::contact_start(const BodyKick& k) const {
    ContactState s;
    s.x = x_;
    s.R = R_;
    s.held = k.held;
    if (!k.held) {
        s.v = k.v;
        s.omega = k.omega;
    }
    return s;
}

BodyStep RigidBody::drift(const BodyKick& k, double dt, const ContactState* contact) {
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
    if (k.held) {
        const Pose rest = make_pose(x_, R_, zero, zero, zero, zero);
        return {rest, rest, rest};
    }
    const Eigen::Vector3d& A = k.A;
    const Eigen::Vector3d& alpha = k.alpha;
    const double dt_prev = k.dt_prev;
    Eigen::Vector3d omega = k.omega, L_new = k.L;
    BodyStep out;
    if (constraint_ == BodyConstraint::hinge) {
        const Eigen::Matrix3d R_mid = turned(0.5 * dt * omega, R_);
        const Eigen::Matrix3d R_end = turned(dt * omega, R_);
        // The centre turns about the hinge: its velocity and acceleration are the rotation's.
        const auto centre_at = [&](const Eigen::Matrix3d& R) {
            return Eigen::Vector3d(hinge_ + R * (mass_.centre - hinge_));
        };
        const Eigen::Vector3d r_now = x_ - hinge_;
        const Eigen::Vector3d omega_now = k.omega_old + 0.5 * dt_prev * alpha;
        const Eigen::Vector3d a_now = alpha.cross(r_now) + omega_now.cross(omega_now.cross(r_now));
        out.now = make_pose(x_, R_, omega_now.cross(r_now), omega_now, a_now, alpha);
        const Eigen::Vector3d x_mid = centre_at(R_mid), x_end = centre_at(R_end);
        out.mid = make_pose(x_mid, R_mid, omega.cross(x_mid - hinge_), omega, a_now, alpha);
        const Eigen::Vector3d omega_end = omega + 0.5 * dt * alpha;
        out.end = make_pose(x_end, R_end, omega_end.cross(x_end - hinge_), omega_end, a_now, alpha);
        v_half_ = omega.cross(0.5 * (r_now + (x_end - hinge_)));
        x_ = x_end;
        R_ = R_end;
    } else {
        Eigen::Vector3d v_new = k.v;
        Eigen::Vector3d x_end = x_ + dt * v_new;
        Eigen::Matrix3d R_end = turned(dt * omega, R_);
        if (contact != nullptr) { // the contacts' velocities and end placement
            v_new = contact->v;
            omega = contact->omega;
            x_end = contact->x;
            R_end = contact->R;
            if (constraint_ == BodyConstraint::plane)
                L_new = axis_ * (axis_.dot(mass_.inertia * axis_) * axis_.dot(omega));
            else
                L_new = R_ * mass_.inertia * R_.transpose() * omega;
        }
        const Eigen::Matrix3d R_mid = turned(0.5 * dt * omega, R_);
        out.now = make_pose(x_, R_, v_half_ + 0.5 * dt_prev * A,
                            k.omega_old + 0.5 * dt_prev * alpha, A, alpha);
        out.mid = make_pose(x_ + 0.5 * dt * v_new, R_mid, v_new, omega, A, alpha);
        out.end = make_pose(x_end, R_end, v_new + 0.5 * dt * A, omega + 0.5 * dt * alpha, A, alpha);
        v_half_ = v_new;
        x_ = x_end;
        R_ = R_end;
    }
    L_half_ = L_new;
    pose_ = out.end;
    return out;
}

BodyStep RigidBody::step(double t, double dt_prev, double dt, const BodyLoad& fluid, bool loaded) {
    return drift(kick(t, dt_prev, dt, fluid, loaded), dt, nullptr);
}

std::vector<double> RigidBody::state() const {
    std::vector<double> s;
    s.reserve(state_size);
    for (int k = 0; k < 3; ++k)
        s.push_back(x_[k]);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            s.push_back(R_(r, c));
    for (int k = 0; k < 3; ++k)
        s.push_back(v_half_[k]);
    for (int k = 0; k < 3; ++k)
        s.push_back(L_half_[k]);
    s.push_back(released_ ? 1.0 : 0.0);
    return s;
}

void RigidBody::restore(const std::vector<double>& s) {
    if (s.size() != state_size)
        throw std::invalid_argument("RigidBody::restore: not a body's state");
    std::size_t i = 0;
    for (int k = 0; k < 3; ++k)
        x_[k] = s[i++];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            R_(r, c) = s[i++];
    for (int k = 0; k < 3; ++k)
        v_half_[k] = s[i++];
    for (int k = 0; k < 3; ++k)
        L_half_[k] = s[i++];
    released_ = s[i] != 0;
    pose_ = make_pose(x_, R_, v_half_, omega_of(R_, L_half_), Eigen::Vector3d::Zero(),
                      Eigen::Vector3d::Zero());
}

} // namespace sluice
