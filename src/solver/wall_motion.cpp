#include "sluice/solver/wall_motion.hpp"

#include "sluice/io/errors.hpp"
#include "sluice/solver/initial_state.hpp"

#include <fmt/format.h>

#include <cstring>
#include <limits>
#include <stdexcept>

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
    // Free bodies: their mass properties (from a box's shape where the law leaves them out).
    const Eigen::Vector3d g(cfg.gravity[0], cfg.gravity[1], cfg.gravity[2]);
    for (std::size_t k = 0; k < objects_.size(); ++k) {
        Object& o = objects_[k];
        const MotionLaw& law = cfg.motions[static_cast<std::size_t>(o.motion)];
        if (law.kind != MotionKind::free_body)
            continue;
        std::optional<MassProperties> shape;
        std::optional<Bounds> bounds;
        for (std::size_t b = 0; b < cfg.boxes.size(); ++b)
            if (wall_object_index_of_box(b) == o.wall_object) {
                const auto& box = cfg.boxes[b];
                const Eigen::Vector3d lo(box.lo[0], box.lo[1], box.lo[2]);
                const Eigen::Vector3d hi(box.hi[0], box.hi[1], box.hi[2]);
                shape = box_mass_properties(lo, hi, D);
                bounds = Bounds{lo, hi};
            }
        body_bounds_.push_back(bounds);
        o.body = static_cast<int>(bodies_.size());
        bodies_.emplace_back(law, body_mass_properties(law.body, shape), g, D);
        body_objects_.push_back(static_cast<int>(k));
    }
    loads_.assign(bodies_.size(), {});
    // Contact between the bodies that take part, the fixed walls and each other.
    std::vector<const MotionLaw*> laws;
    std::vector<std::optional<ContactBox>> boxes;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        laws.push_back(&cfg.motions[static_cast<std::size_t>(
            objects_[static_cast<std::size_t>(body_objects_[b])].motion)]);
        boxes.push_back(body_bounds_[b] ? std::optional<ContactBox>(
                                              ContactBox{body_bounds_[b]->lo, body_bounds_[b]->hi})
                                        : std::nullopt);
    }
    contact_ = make_body_contact(cfg, bodies_, laws, boxes);
    tank_lo_ = cfg.tank_lo;
    tank_hi_ = cfg.tank_hi;
    tank_faces_ = cfg.tank_faces;
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
    // The objects' id runs, for object_of's bisection.
    ParticleId end = 0; // of the object before
    for (Object& o : objects_) {
        if (o.x0.empty()) // holds no particle: an empty run where the next one starts
            o.first = end;
        if (o.first < end)
            throw std::logic_error("WallMotion: moving objects not laid in id order");
        firsts_.push_back(o.first);
        end = o.first + o.x0.size();
    }
    first_moving_ = firsts_.front();
}

template <int D>
void WallMotion<D>::prepare(double t, double dt_prev, double dt) {
    frames_.now.clear();
    frames_.mid.clear();
    frames_.end.clear();
    // The bodies' kicks, then contact between them and the walls, then their drifts.
    std::vector<BodyKick> kicks;
    kicks.reserve(bodies_.size());
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        kicks.push_back(bodies_[b].kick(t, dt_prev, dt, loads_[b], loads_known_));
    std::vector<ContactState> after;
    if (contact_.world) {
        std::vector<ContactState> start;
        for (std::size_t b = 0; b < bodies_.size(); ++b)
            if (contact_.index[b] >= 0)
                start.push_back(bodies_[b].contact_start(kicks[b]));
        after = contact_.world->step(start, dt);
    }
    for (const Object& o : objects_) {
        if (o.body >= 0) {
            const auto b = static_cast<std::size_t>(o.body);
            const int c = contact_.index[b];
            const ContactState* touched = c >= 0 && after[static_cast<std::size_t>(c)].resolved
                                              ? &after[static_cast<std::size_t>(c)]
                                              : nullptr;
            const BodyStep s = bodies_[b].drift(kicks[b], dt, touched);
            if (body_bounds_[b] && c < 0)
                check_within_tank(o.name, moved_bounds(*body_bounds_[b], s.end, D), t + dt);
            frames_.now.push_back(s.now);
            frames_.mid.push_back(s.mid);
            frames_.end.push_back(s.end);
        } else {
            frames_.now.push_back(o.rigid.pose(t));
            frames_.mid.push_back(o.rigid.pose(t + dt / 2));
            frames_.end.push_back(o.rigid.pose(t + dt));
        }
    }
}

template <int D>
void WallMotion<D>::check_within_tank(const std::string& name, const Bounds& b, double t) const {
    for (const std::string& face : tank_faces_) {
        const auto a = static_cast<std::size_t>(face[0] - 'x');
        if (a >= static_cast<std::size_t>(D))
            continue;
        const bool low = face[1] == '-';
        const double into = low ? tank_lo_[a] - b.lo[static_cast<Eigen::Index>(a)]
                                : b.hi[static_cast<Eigen::Index>(a)] - tank_hi_[a];
        if (into > 0)
            throw RunError(fmt::format(
                "free body \"{}\" reaches the tank's {} wall at t = {:.6g} s ({:.3g} m into it): "
                "contact between free bodies and walls is not modelled, so the run stops here "
                "(the last snapshot is the state before)",
                name, face, t, into));
    }
}

template <int D>
std::vector<Pose> WallMotion<D>::poses(double t) const {
    std::vector<Pose> p;
    p.reserve(objects_.size());
    for (const Object& o : objects_)
        p.push_back(o.body >= 0 ? bodies_[static_cast<std::size_t>(o.body)].pose()
                                : o.rigid.pose(t));
    return p;
}

template <int D>
void WallMotion<D>::pack_loads(std::span<const BodyLoadSums> groups,
                               std::vector<std::byte>& out) const {
    BodyLoadSums total;
    total.reset(bodies_.size());
    for (const BodyLoadSums& g : groups)
        if (g.body.size() == bodies_.size())
            total.add(g);
    const std::size_t at = out.size();
    out.resize(at + load_bytes());
    out[at] = std::byte{total.overflow ? std::uint8_t(1) : std::uint8_t(0)};
    std::size_t pos = at + 1;
    for (const auto& b : total.body)
        for (const ExactSum& s : b) {
            s.to_bytes(out.data() + pos);
            pos += ExactSum::bytes;
        }
}

template <int D>
bool WallMotion<D>::agree_loads(const std::vector<std::span<const std::byte>>& ranks) {
    BodyLoadSums total;
    total.reset(bodies_.size());
    for (const auto& r : ranks) {
        if (r.size() != load_bytes())
            throw std::logic_error("agree_loads: a rank's share has the wrong size");
        total.overflow = total.overflow || r[0] != std::byte{0};
        std::size_t pos = 1;
        for (auto& b : total.body)
            for (ExactSum& s : b) {
                s.add(ExactSum::from_bytes(r.data() + pos));
                pos += ExactSum::bytes;
            }
    }
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        for (int k = 0; k < 3; ++k) {
            loads_[b].force[k] = total.body[b][static_cast<std::size_t>(k)].value();
            loads_[b].moment[k] = total.body[b][static_cast<std::size_t>(3 + k)].value();
        }
    loads_known_ = true;
    return !total.overflow;
}

template <int D>
std::vector<double> WallMotion<D>::body_state() const {
    std::vector<double> s;
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const auto st = bodies_[b].state();
        s.insert(s.end(), st.begin(), st.end());
        for (int k = 0; k < 3; ++k)
            s.push_back(loads_[b].force[k]);
        for (int k = 0; k < 3; ++k)
            s.push_back(loads_[b].moment[k]);
    }
    return s;
}

template <int D>
void WallMotion<D>::restore_body_state(const std::vector<double>& s) {
    const std::size_t per = RigidBody::state_size + 6;
    if (s.size() != per * bodies_.size())
        throw std::invalid_argument("the checkpoint's free bodies are not this case's");
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const auto first = s.begin() + static_cast<std::ptrdiff_t>(b * per);
        bodies_[b].restore(std::vector<double>(first, first + RigidBody::state_size));
        for (int k = 0; k < 3; ++k) {
            loads_[b].force[k] = s[b * per + RigidBody::state_size + static_cast<std::size_t>(k)];
            loads_[b].moment[k] =
                s[b * per + RigidBody::state_size + 3 + static_cast<std::size_t>(k)];
        }
    }
    loads_known_ = true;
}

template class WallMotion<2>;
template class WallMotion<3>;

} // namespace sluice
