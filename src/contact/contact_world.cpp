// ContactWorld (contact_world.hpp) on Bullet's rigid-body world: static planes for the tank's
// faces, static boxes for the fixed obstacles, a compound of one box for each free body (its
// origin the centre of mass), then one step of Bullet's own integrator and sequential-impulse
// contact solver, without gravity or forces (the caller has kicked the bodies already).
#include "sluice/contact/contact_world.hpp"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace sluice {
namespace {

btVector3 bt(const Eigen::Vector3d& v) {
    return {v.x(), v.y(), v.z()};
}
Eigen::Vector3d eigen(const btVector3& v) {
    return {v.x(), v.y(), v.z()};
}
btMatrix3x3 bt(const Eigen::Matrix3d& R) {
    return {R(0, 0), R(0, 1), R(0, 2), R(1, 0), R(1, 1), R(1, 2), R(2, 0), R(2, 1), R(2, 2)};
}
Eigen::Matrix3d eigen(const btMatrix3x3& m) {
    Eigen::Matrix3d R;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            R(r, c) = m[r][c];
    return R;
}

// A box shape of these half extents whose collision margin (Bullet keeps it inside the box)
// is small against the box: 4 cm, Bullet's default, is more than many a body.
std::unique_ptr<btBoxShape> box_shape(const Eigen::Vector3d& half) {
    auto s = std::make_unique<btBoxShape>(bt(half));
    s->setMargin(std::min(0.04, 0.1 * half.minCoeff()));
    return s;
}

// In 2-D the boxes are slabs along z (their z extent is none): as deep as they are wide.
Eigen::Vector3d half_extent(const ContactBox& b, int dim) {
    Eigen::Vector3d half = 0.5 * (b.hi - b.lo);
    if (dim == 2)
        half.z() = std::max(half.x(), half.y());
    return half;
}

// The axis-aligned box around a body's box placed at (x, R), swept by its velocities over dt
// and widened by `gap`.
struct Aabb {
    Eigen::Vector3d lo, hi;
    [[nodiscard]] bool meets(const Aabb& o, int dim) const {
        for (int a = 0; a < dim; ++a)
            if (hi[a] < o.lo[a] || o.hi[a] < lo[a])
                return false;
        return true;
    }
};
Aabb swept_box(const ContactBody& b, const ContactState& s, double dt, int dim) {
    const Eigen::Vector3d half = 0.5 * (b.box.hi - b.box.lo);
    const Eigen::Vector3d centre = s.x + s.R * (0.5 * (b.box.lo + b.box.hi) - b.centre);
    Eigen::Vector3d reach = s.R.cwiseAbs() * half;
    double radius2 = 0, smallest = half.x();
    for (int a = 0; a < dim; ++a) {
        radius2 += half[a] * half[a];
        smallest = std::min(smallest, half[a]);
    }
    const double sweep = (s.v.norm() + s.omega.norm() * std::sqrt(radius2)) * dt;
    const double widen = sweep + 0.1 * smallest;
    for (int a = 0; a < 3; ++a)
        reach[a] += widen;
    return {centre - reach, centre + reach};
}

} // namespace

ContactWorld::ContactWorld(int dim, std::vector<ContactPlane> planes, std::vector<ContactBox> fixed,
                           std::vector<ContactBody> bodies)
    : dim_(dim), planes_(std::move(planes)), fixed_(std::move(fixed)), bodies_(std::move(bodies)) {}

ContactWorld::~ContactWorld() = default;

std::vector<ContactState> ContactWorld::step(const std::vector<ContactState>& start, double dt) {
    // Which bodies may touch something this step.
    const std::size_t n = bodies_.size();
    std::vector<Aabb> boxes;
    for (std::size_t k = 0; k < n; ++k)
        boxes.push_back(swept_box(bodies_[k], start[k], dt, dim_));
    std::vector<bool> near(n, false);
    for (std::size_t k = 0; k < n; ++k) {
        if (start[k].held)
            continue;
        for (const ContactPlane& p : planes_) {
            // The box's lowest point along the plane's normal against the plane.
            double lowest = 0;
            for (int a = 0; a < 3; ++a)
                lowest += p.normal[a] * (p.normal[a] > 0 ? boxes[k].lo[a] : boxes[k].hi[a]);
            near[k] = near[k] || lowest <= p.offset;
        }
        for (const ContactBox& f : fixed_)
            near[k] = near[k] || boxes[k].meets({f.lo, f.hi}, dim_);
        for (std::size_t j = 0; j < n; ++j)
            if (j != k && boxes[k].meets(boxes[j], dim_)) {
                near[k] = true;
                near[j] = near[j] || !start[j].held;
            }
    }
    last_contacts_ = 0;
    if (std::none_of(near.begin(), near.end(), [](bool b) { return b; })) {
        std::vector<ContactState> same = start;
        for (ContactState& s : same)
            s.resolved = false;
        return same;
    }
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, 0, 0));
    btContactSolverInfo& solver_info = world.getSolverInfo();
    solver_info.m_numIterations = 50;
    solver_info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;
    // Penetration is pushed out by the split impulse alone, which moves the bodies without
    // changing their velocities: otherwise (Bullet's default for penetrations under 4 cm) the
    // push-out enters the velocity and a contact of restitution 0 bounces.
    solver_info.m_splitImpulse = 1;
    solver_info.m_splitImpulsePenetrationThreshold = 1e30;
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> rigid;
    const auto add = [&](std::unique_ptr<btCollisionShape> shape, double mass,
                         const btVector3& inertia, const btTransform& at, double friction,
                         double restitution) {
        btRigidBody::btRigidBodyConstructionInfo info(mass, nullptr, shape.get(), inertia);
        info.m_startWorldTransform = at;
        info.m_friction = friction;
        info.m_restitution = restitution;
        rigid.push_back(std::make_unique<btRigidBody>(info));
        shapes.push_back(std::move(shape));
        world.addRigidBody(rigid.back().get());
        return rigid.back().get();
    };
    // Walls: friction and restitution 1, so that a pair's product is the body's own. A tank
    // face is a thick slab behind its plane rather than Bullet's plane shape: box against box
    // finds the whole face contact (up to four points) in one pass, which a world built afresh
    // each step needs (against a plane Bullet finds one point a step and relies on keeping
    // points from step to step; a box on the floor then rocks and walks).
    double size = 1;
    for (const ContactPlane& p : planes_)
        size = std::max(size, std::abs(p.offset));
    for (const ContactBody& b : bodies_)
        size = std::max({size, b.box.lo.cwiseAbs().maxCoeff(), b.box.hi.cwiseAbs().maxCoeff()});
    for (const ContactPlane& p : planes_) {
        Eigen::Vector3d half = Eigen::Vector3d::Constant(4 * size);
        int axis = 0;
        p.normal.cwiseAbs().maxCoeff(&axis);
        half[axis] = size;
        // The slab's face is the plane n . x = offset; the slab lies on the side n . x < offset.
        const Eigen::Vector3d centre = p.normal * (p.offset - size);
        add(box_shape(half), 0, btVector3(0, 0, 0),
            btTransform(btMatrix3x3::getIdentity(), bt(centre)), 1, 1);
    }
    for (const ContactBox& b : fixed_)
        add(box_shape(half_extent(b, dim_)), 0, btVector3(0, 0, 0),
            btTransform(btMatrix3x3::getIdentity(), bt(Eigen::Vector3d(0.5 * (b.lo + b.hi)))), 1,
            1);
    std::vector<btRigidBody*> moving(n, nullptr);
    for (std::size_t k = 0; k < n; ++k) {
        if (!near[k] && !start[k].held)
            continue;
        const ContactBody& b = bodies_[k];
        const ContactState& s = start[k];
        // The rigid body's origin is the centre of mass: a box centred on it is a box shape
        // (box-box contact), one off it a compound holding the box at its offset.
        auto box = box_shape(half_extent(b.box, dim_));
        Eigen::Vector3d offset = 0.5 * (b.box.lo + b.box.hi) - b.centre;
        if (dim_ == 2)
            offset.z() = 0;
        std::unique_ptr<btCollisionShape> shape;
        if (offset.norm() <= 1e-12 * size) {
            shape = std::move(box);
        } else {
            auto compound = std::make_unique<btCompoundShape>();
            compound->addChildShape(btTransform(btMatrix3x3::getIdentity(), bt(offset)), box.get());
            shapes.push_back(std::move(box));
            shape = std::move(compound);
        }
        const double mass = s.held ? 0.0 : b.mass;
        btRigidBody* r = add(std::move(shape), mass, s.held ? btVector3(0, 0, 0) : bt(b.inertia),
                             btTransform(bt(s.R), bt(s.x)), b.friction, b.restitution);
        r->setActivationState(DISABLE_DEACTIVATION);
        if (!s.held) {
            r->setLinearVelocity(bt(s.v));
            r->setAngularVelocity(bt(s.omega));
            if (b.planar) { // translation in the plane, rotation about its normal
                const Eigen::Vector3d axis = b.normal.cwiseAbs();
                r->setLinearFactor(bt(Eigen::Vector3d(Eigen::Vector3d::Ones() - axis)));
                r->setAngularFactor(bt(axis));
            }
        }
        moving[k] = r;
    }
    world.stepSimulation(dt, 0); // one step of dt (no sub-steps)
    last_contacts_ = 0;
    for (int m = 0; m < dispatcher.getNumManifolds(); ++m)
        last_contacts_ += dispatcher.getManifoldByIndexInternal(m)->getNumContacts();
    std::vector<ContactState> end(start.size());
    for (std::size_t k = 0; k < n; ++k) {
        if (start[k].held || !near[k]) {
            end[k] = start[k];
            end[k].resolved = false;
            continue;
        }
        end[k].resolved = true;
        const btTransform& t = moving[k]->getWorldTransform();
        end[k].x = eigen(t.getOrigin());
        end[k].R = eigen(t.getBasis());
        end[k].v = eigen(moving[k]->getLinearVelocity());
        end[k].omega = eigen(moving[k]->getAngularVelocity());
    }
    for (auto& r : rigid)
        world.removeRigidBody(r.get());
    return end;
}

} // namespace sluice
