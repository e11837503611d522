#include "sluice/solver/wall_motion.hpp"

#include "sluice/solver/initial_state.hpp"

#include <limits>

namespace sluice {

template <int D>
WallMotion<D>::WallMotion(const CaseConfig& cfg, const Eos& eos, int layers) {
    // One object per wall object that has a motion, in the order their particles are laid.
    const auto add = [&](int wall_object, int motion) {
        if (motion < 0)
            return;
        Object o;
        o.motion = motion;
        o.wall_object = wall_object;
        o.name = cfg.motions[static_cast<std::size_t>(motion)].name;
        o.rigid = make_motion(cfg.motions[static_cast<std::size_t>(motion)]);
        o.first = std::numeric_limits<ParticleId>::max();
        objects_.push_back(std::move(o));
    };
    add(0, cfg.tank_motion);
    for (std::size_t b = 0; b < cfg.boxes.size(); ++b)
        add(wall_object_index_of_box(b), cfg.boxes[b].motion);
    for (std::size_t m = 0; m < cfg.meshes.size(); ++m)
        add(wall_object_index_of_mesh(cfg, m), cfg.meshes[m].motion);
    if (objects_.empty())
        return;
    // Walls are laid after the fluid: their ids start where the fluid's end.
    const ParticleId first_wall =
        visit_fluid_blocks<D>(cfg, eos, 0, [](const InitialParticle<D>&) {});
    visit_wall_particles<D>(cfg, layers, first_wall, [&](const InitialParticle<D>& q) {
        for (Object& o : objects_)
            if (o.wall_object == q.object) {
                if (o.x0.empty())
                    o.first = q.id;
                o.x0.push_back(to_pose_point<D>(q.x));
            }
    });
}

template <int D>
void WallMotion<D>::prepare(double t, double dt) {
    frames_.now = poses(t);
    frames_.mid = poses(t + dt / 2);
    frames_.end = poses(t + dt);
}

template <int D>
std::vector<Pose> WallMotion<D>::poses(double t) const {
    std::vector<Pose> p;
    p.reserve(objects_.size());
    for (const Object& o : objects_)
        p.push_back(o.rigid.pose(t));
    return p;
}

template class WallMotion<2>;
template class WallMotion<3>;

} // namespace sluice
