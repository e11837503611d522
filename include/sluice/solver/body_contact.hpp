#pragma once
// The contact world of a case's free bodies (contact/contact_world.hpp): the bodies that take
// part (motion_law.hpp's body_in_contact), the fixed tank's walled faces and the fixed boxes.
#include "sluice/contact/contact_world.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/motion/rigid_body.hpp"

#include <memory>
#include <vector>

namespace sluice {

struct BodyContact {
    std::unique_ptr<ContactWorld> world; // null when no body takes part
    std::vector<int> index;              // per body: its place in the world, or -1
};

// `bodies` the case's free bodies, `laws` their motions, `boxes` their boxes at rest (none for a
// mesh body).
BodyContact make_body_contact(const CaseConfig& cfg, const std::vector<RigidBody>& bodies,
                              const std::vector<const MotionLaw*>& laws,
                              const std::vector<std::optional<ContactBox>>& boxes);

} // namespace sluice
