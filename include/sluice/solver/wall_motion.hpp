#pragma once
// The motion of the case's wall objects (docs/ARCHITECTURE.md, "Moving walls"): which wall
// particles each moving object holds (a contiguous run of ids, laid at t = 0), their positions
// at t = 0 in every rank's copy, and the objects' poses for a step. The stages of a step move
// the particles with it: the walls stage reads a wall's velocity and acceleration now, the
// kick its mid-step velocity, the drift its end-of-step position and velocity; nothing else of
// the runtime knows that walls move (they are rebinned, migrated and balanced as particles).
// A prescribed object's poses are motion/rigid_motion.hpp's; a free body's
// (motion/rigid_body.hpp) come from the fluid's load on it, which the acceleration stage sums
// per cell group (BodyLoadSums), the step's report carries between ranks and agree_loads()
// hands the bodies for the next step (docs/FLOATING_BODIES.md).
#include "sluice/core/particles.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/motion/rigid_body.hpp"
#include "sluice/motion/rigid_motion.hpp"
#include "sluice/physics/eos.hpp"
#include "sluice/solver/body_contact.hpp"
#include "sluice/solver/body_load_sums.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sluice {

template <int D>
class WallMotion {
public:
    struct Object {
        std::string name;                // the motion's
        int motion = -1;                 // CaseConfig::motions index
        int wall_object = -1;            // 0 tank, then boxes, then meshes (initial_state.hpp)
        RigidMotion rigid;               // prescribed (a free body's is at rest)
        int body = -1;                   // index into bodies() for a free body, else -1
        ParticleId first = 0;            // ids [first, first + x0.size())
        std::vector<Eigen::Vector3d> x0; // positions at t = 0
    };
    // The poses of every object at the start of a step, at its middle and at its end.
    struct Frames {
        std::vector<Pose> now, mid, end;
    };

    // Nothing moves.
    WallMotion() = default;
    // The moving objects of the case, their particles found by laying the walls once (every
    // rank, as the distributed start does).
    WallMotion(const CaseConfig& cfg, const Eos& eos, int layers);

    [[nodiscard]] bool empty() const { return objects_.empty(); }
    [[nodiscard]] const std::vector<Object>& objects() const { return objects_; }
    // The free bodies, in the order of their objects; each one's object index.
    [[nodiscard]] const std::vector<RigidBody>& bodies() const { return bodies_; }
    [[nodiscard]] int body_object(std::size_t b) const { return body_objects_[b]; }
    // The free body particle `id` belongs to, or -1.
    [[nodiscard]] int body_of(ParticleId id) const {
        const int k = object_of(id);
        return k < 0 ? -1 : objects_[static_cast<std::size_t>(k)].body;
    }

    // The index of the moving object that particle `id` belongs to, or -1.
    // Called for every particle of a step's kick and drift: fluid ids (below every wall's) are
    // rejected at once, the rest found by bisection over the objects' id runs, which are laid
    // in object order.
    [[nodiscard]] int object_of(ParticleId id) const {
        if (id < first_moving_ || firsts_.empty())
            return -1;
        const auto it = std::upper_bound(firsts_.begin(), firsts_.end(), id);
        const auto k = static_cast<std::size_t>(it - firsts_.begin()) - 1;
        const Object& o = objects_[k];
        return id - o.first < o.x0.size() ? static_cast<int>(k) : -1;
    }
    [[nodiscard]] const Eigen::Vector3d& body_point(int object, ParticleId id) const {
        const Object& o = objects_[static_cast<std::size_t>(object)];
        return o.x0[id - o.first];
    }

    // Sets the poses at t, t + dt/2 and t + dt for the step about to run (Simulation, before
    // its graph), the same on every rank; the stages read them through frames(). Advances the
    // free bodies over the step (dt_prev: the step before's) under the last agreed loads.
    void prepare(double t, double dt_prev, double dt);
    [[nodiscard]] const Frames& frames() const { return frames_; }
    // The poses of every object now (at `t`, the time the last step reached: a free body's
    // pose is the one it is in).
    [[nodiscard]] std::vector<Pose> poses(double t) const;

    // The step's load on the free bodies: this rank's share (the groups' sums) as the bytes
    // its step report carries, and the total over every rank's bytes (any order: the sums
    // are exact), which the next prepare() applies. agree_loads returns false when a share
    // overflowed (a state that blew up).
    [[nodiscard]] std::size_t load_bytes() const {
        return 1 + bodies_.size() * 6 * ExactSum::bytes;
    }
    void pack_loads(std::span<const BodyLoadSums> groups, std::vector<std::byte>& out) const;
    bool agree_loads(const std::vector<std::span<const std::byte>>& ranks);
    // The loads the last step's agreement gave (force; moment about the centre of mass).
    [[nodiscard]] const std::vector<BodyLoad>& loads() const { return loads_; }

    // The bodies' state and loads for a checkpoint, and back (bitwise).
    [[nodiscard]] std::vector<double> body_state() const;
    void restore_body_state(const std::vector<double>& s);

private:
    void check_within_tank(const std::string& name, const Bounds& b, double t) const;

    std::vector<Object> objects_;
    std::vector<ParticleId> firsts_; // objects_[k].first, ascending
    ParticleId first_moving_ = 0;    // the lowest id of any moving object
    std::vector<RigidBody> bodies_;
    std::vector<int> body_objects_;
    std::vector<BodyLoad> loads_;
    // Where a body's box is at rest, and the tank's walled faces: a body that takes no part in
    // contact stops the run in prepare() when it would cross a tank face.
    std::vector<std::optional<Bounds>> body_bounds_;
    BodyContact contact_; // solver/body_contact.hpp
    std::array<double, 3> tank_lo_{}, tank_hi_{};
    std::vector<std::string> tank_faces_;
    bool loads_known_ = false; // once a step's agreement (or a checkpoint) has given them
    Frames frames_;
};

} // namespace sluice

namespace sluice {

// The wall kinematics dummy_wall_state (physics/walls.hpp) takes: a moving object's particles
// at its pose `now`, every other wall at rest.
template <int D>
struct MovingWalls {
    static constexpr bool moving = true;
    const WallMotion<D>& motion;
    const std::vector<Pose>& now;
    const std::vector<ParticleId>& id;

    void operator()(std::uint32_t w, Vec<D>& v_w, Vec<D>& a_w) const {
        const int k = motion.object_of(id[w]);
        if (k < 0) {
            v_w.setZero();
            a_w.setZero();
            return;
        }
        const Eigen::Vector3d& x0 = motion.body_point(k, id[w]);
        const Pose& p = now[static_cast<std::size_t>(k)];
        v_w = from_pose_point<D>(p.velocity(x0));
        a_w = from_pose_point<D>(p.acceleration(x0));
    }
};

} // namespace sluice
