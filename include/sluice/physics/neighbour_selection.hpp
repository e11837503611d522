#pragma once
// Which neighbours an operator uses: the policy a case file chooses per operator
// ([neighbours.<operator>] of the case file; physics/options.hpp). A pure function of the
// candidates' offsets.
//
//  * radius: every candidate with 0 <= |r| < support (the usual SPH neighbour set).
//  * convex-hull (Randles & Libersky 2000; Lee & Lee 2011): the candidates with
//    0 < |r| <= candidate radius are mapped by r' = r/|r|^2 and the hull corners of the
//    images are kept (with `hull_boundary`, also the images on a hull edge/facet, e.g. the
//    diagonal neighbours of a square lattice, which lie exactly on the edges of the diamond
//    of the four nearest). These are the nearest particles in every direction, however
//    uneven the spacing. With `union_with_radius` the radius set is added (an operator that
//    needs more equations than the hull gives, e.g. a second-order least-squares fit).
// A candidate at r = 0 (a coincident particle) has no image and is never a hull neighbour.
#include "sluice/core/types.hpp"
#include "sluice/physics/mapped_hull.hpp"
#include "sluice/physics/options.hpp"

#include <span>
#include <vector>

namespace sluice {

// `offsets` are x_j - x_i of the candidates (the centre particle itself excluded); `dx` the
// lattice spacing that scales `candidate_radius_over_dx`. Returns ascending indices.
template <int D>
[[nodiscard]] std::vector<int> select_neighbours(std::span<const Vec<D>> offsets, Real support,
                                                 Real dx, const NeighbourSelection& selection);

// Buffers of select_neighbours_into, reused from call to call (one per task: nothing shared).
template <int D>
struct NeighbourSelectionScratch {
    std::vector<int> candidate; // indices of the offsets within the candidate radius
    MappedHull<D> hull;         // hull.images: their inverse-square images
    MappedHullWork<D> hull_work;
};

// The same into `out` (the solver's form: no allocation once the buffers have grown).
template <int D>
void select_neighbours_into(std::span<const Vec<D>> offsets, Real support, Real dx,
                            const NeighbourSelection& selection,
                            NeighbourSelectionScratch<D>& scratch, std::vector<int>& out);

} // namespace sluice
