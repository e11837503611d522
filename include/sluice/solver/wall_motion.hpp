#pragma once
// The prescribed motion of the case's wall objects (docs/ARCHITECTURE.md, "Moving walls"):
// which wall particles each moving object holds (a contiguous run of ids, laid at t = 0),
// their positions at t = 0 in every rank's copy, and the objects' poses for a step. The stages
// of a step move the particles with it: the walls stage reads a wall's velocity and
// acceleration now, the kick its mid-step velocity, the drift its end-of-step position and
// velocity; nothing else of the runtime knows that walls move (they are rebinned, migrated and
// balanced as particles). Set-up and look-ups only: the poses are motion/rigid_motion.hpp's.
#include "sluice/core/particles.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/motion/rigid_motion.hpp"
#include "sluice/physics/eos.hpp"

#include <string>
#include <vector>

namespace sluice {

template <int D>
class WallMotion {
public:
    struct Object {
        std::string name;     // the motion's
        int motion = -1;      // CaseConfig::motions index
        int wall_object = -1; // 0 tank, then boxes, then meshes (initial_state.hpp)
        RigidMotion rigid;
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

    // The index of the moving object that particle `id` belongs to, or -1.
    [[nodiscard]] int object_of(ParticleId id) const {
        for (std::size_t k = 0; k < objects_.size(); ++k) {
            const Object& o = objects_[k];
            if (id >= o.first && id - o.first < o.x0.size())
                return static_cast<int>(k);
        }
        return -1;
    }
    [[nodiscard]] const Eigen::Vector3d& body_point(int object, ParticleId id) const {
        const Object& o = objects_[static_cast<std::size_t>(object)];
        return o.x0[id - o.first];
    }

    // Sets the poses at t, t + dt/2 and t + dt for the step about to run (Simulation, before
    // its graph), the same on every rank; the stages read them through frames().
    void prepare(double t, double dt);
    [[nodiscard]] const Frames& frames() const { return frames_; }
    // The poses of every object at one time (probes, output).
    [[nodiscard]] std::vector<Pose> poses(double t) const;

private:
    std::vector<Object> objects_;
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
