#include "sluice/solver/body_contact.hpp"

namespace sluice {

BodyContact make_body_contact(const CaseConfig& cfg, const std::vector<RigidBody>& bodies,
                              const std::vector<const MotionLaw*>& laws,
                              const std::vector<std::optional<ContactBox>>& boxes) {
    BodyContact out;
    out.index.assign(bodies.size(), -1);
    std::vector<ContactBody> taking_part;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        if (!body_in_contact(*laws[b], boxes[b].has_value()))
            continue;
        const RigidBody& body = bodies[b];
        ContactBody c;
        c.box = *boxes[b];
        c.mass = body.mass().mass;
        c.centre = body.mass().centre;
        c.inertia = body.mass().inertia.diagonal();
        c.friction = laws[b]->body.friction;
        c.restitution = laws[b]->body.restitution;
        c.planar = body.constraint() == BodyConstraint::plane;
        c.normal = body.axis();
        out.index[b] = static_cast<int>(taking_part.size());
        taking_part.push_back(c);
    }
    if (taking_part.empty())
        return out;
    std::vector<ContactPlane> planes;
    if (cfg.tank_motion < 0 && cfg.walls == WallModel::dummy)
        for (const std::string& face : cfg.tank_faces) {
            const auto a = static_cast<std::size_t>(face[0] - 'x');
            if (a >= static_cast<std::size_t>(cfg.dimension))
                continue;
            ContactPlane p;
            p.normal = Eigen::Vector3d::Zero();
            const bool low = face[1] == '-';
            p.normal[static_cast<Eigen::Index>(a)] = low ? 1.0 : -1.0;
            p.offset = low ? cfg.tank_lo[a] : -cfg.tank_hi[a];
            planes.push_back(p);
        }
    std::vector<ContactBox> fixed;
    for (const WallBox& box : cfg.boxes)
        if (box.motion < 0)
            fixed.push_back({Eigen::Vector3d(box.lo[0], box.lo[1], box.lo[2]),
                             Eigen::Vector3d(box.hi[0], box.hi[1], box.hi[2])});
    out.world = std::make_unique<ContactWorld>(cfg.dimension, std::move(planes), std::move(fixed),
                                               std::move(taking_part));
    return out;
}

} // namespace sluice
