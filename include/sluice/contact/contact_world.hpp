#pragma once
// Contact between free bodies and between a free body and the fixed walls, resolved by Bullet
// (libbullet, double precision; docs/FLOATING_BODIES.md, "Contact"). Each step the bodies hand
// their state at the start of the step and the velocities their kick gave them; Bullet's
// sequential-impulse solver applies the contacts' impulses (friction, restitution, and the
// split impulse that pushes out what penetrates) and moves them over the step; the bodies take
// the velocities and the end-of-step placement it returns. The world is built afresh each step
// from the same inputs in the same order, so every rank computes the same bits, and a restart,
// which has no solver cache to restore, continues bitwise. Bullet's types stay in the .cpp.
// Pure: no particle, rank or thread is known here.
#include <Eigen/Core>

#include <memory>
#include <vector>

namespace sluice {

// A solid box, axis-aligned where it is at t = 0.
struct ContactBox {
    Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
};

// A fixed wall as a half-space: the solid is where normal . x < offset (normal into the fluid).
struct ContactPlane {
    Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
    double offset = 0;
};

// A free body for contact: its box at t = 0, its mass properties (centre of mass at t = 0,
// principal inertia along the world axes), friction and restitution (a pair of surfaces
// combines them as Bullet does: the product of the two), and whether it is planar (2-D, or a
// 3-D "plane" constraint about `normal`).
struct ContactBody {
    ContactBox box;
    double mass = 0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d inertia = Eigen::Vector3d::Ones(); // principal moments
    double friction = 0.5, restitution = 0;
    bool planar = false;
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// A body's placement and velocities: the centre of mass, the rotation from its t = 0
// placement, the velocity of the centre and the angular velocity.
struct ContactState {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d v = Eigen::Vector3d::Zero(), omega = Eigen::Vector3d::Zero();
    bool held = false; // at rest and immovable this step (before its release)
    // Out of step(): whether Bullet moved it (it was near a wall or another body); a body far
    // from everything comes back as it went in, for its own drift.
    bool resolved = false;
};

class ContactWorld {
public:
    // `dim` 2 or 3; `planes` the tank's walled faces, `fixed` the fixed boxes, `bodies` the
    // free bodies that take part; `walls_friction`, `walls_restitution` the walls' own.
    ContactWorld(int dim, std::vector<ContactPlane> planes, std::vector<ContactBox> fixed,
                 std::vector<ContactBody> bodies);
    ~ContactWorld();
    ContactWorld(const ContactWorld&) = delete;
    ContactWorld& operator=(const ContactWorld&) = delete;

    // The bodies at the start of the step with their kicked velocities (one per body, in the
    // constructor's order) -> where they are at its end and their velocities after contact.
    // Only bodies whose box, swept over the step and widened by a gap of a tenth of its
    // smallest half-width, meets a wall's, a fixed box's or another such body's go to Bullet
    // (`resolved`); when none does, no Bullet world is built at all.
    [[nodiscard]] std::vector<ContactState> step(const std::vector<ContactState>& start, double dt);
    // Contact points found in the last step (a diagnostic).
    [[nodiscard]] int last_contacts() const { return last_contacts_; }

private:
    int dim_;
    std::vector<ContactPlane> planes_;
    std::vector<ContactBox> fixed_;
    std::vector<ContactBody> bodies_;
    int last_contacts_ = 0;
};

} // namespace sluice
