#pragma once
// The case options that physics formulas take: which kernel, equation of state, density
// diffusion form and neighbour set. They live here, in physics, so that physics needs nothing
// of io; io/case_config.hpp includes this header and the case file sets them
// (docs/CASE_REFERENCE.md).

namespace sluice {

enum class KernelType { quintic, wendland_c2, cubic_spline };
// Form of the delta-SPH density diffusion term (docs/CASE_REFERENCE.md, [numerics]).
enum class DensityDiffusion { antuono, fourtakas };
enum class EosType { linear, tait };

// Which neighbours an operator uses (Randles & Libersky 2000 as in Lee & Lee (2011)).
enum class NeighbourPolicy {
    radius,     // every particle within the operator's support
    convex_hull // the hull vertices of the inverse-square images of the candidates
};
struct NeighbourSelection {
    NeighbourPolicy policy = NeighbourPolicy::radius;
    double candidate_radius_over_dx = 3.1; // convex-hull: candidates within this many dx
    bool union_with_radius = false;        // convex-hull: also every particle within the support
    bool hull_boundary = true; // convex-hull: keep points on hull edges/faces, not only corners

    bool operator==(const NeighbourSelection&) const = default;
};

} // namespace sluice
