#pragma once
// The per-group sums of the fluid's load on the free bodies (solver/wall_motion.hpp), kept in
// the step's group results (step_units.hpp).
#include "sluice/core/exact_sum.hpp"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace sluice {

// A cell group's share of each free body's load: force (x, y, z) and moment about the body's
// centre of mass (x, y, z), as order-independent sums (core/exact_sum.hpp), so that the total
// is bitwise the same for any threads, groups and ranks.
struct BodyLoadSums {
    std::vector<std::array<ExactSum, 6>> body; // per free body
    bool overflow = false;                     // a term too large to add (a blown-up state)

    void reset(std::size_t bodies) {
        body.assign(bodies, {});
        overflow = false;
    }
    void add(std::size_t b, const Eigen::Vector3d& f, const Eigen::Vector3d& m) {
        for (int k = 0; k < 3; ++k) {
            overflow = !body[b][static_cast<std::size_t>(k)].add(f[k]) || overflow;
            overflow = !body[b][static_cast<std::size_t>(3 + k)].add(m[k]) || overflow;
        }
    }
    void add(const BodyLoadSums& o) {
        for (std::size_t b = 0; b < body.size(); ++b)
            for (std::size_t k = 0; k < 6; ++k)
                body[b][k].add(o.body[b][k]);
        overflow = overflow || o.overflow;
    }
};

} // namespace sluice
