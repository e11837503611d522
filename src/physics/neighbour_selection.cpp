// Neighbour-selection policies; see include/sluice/physics/neighbour_selection.hpp.
#include "sluice/physics/neighbour_selection.hpp"

#include <algorithm>

namespace sluice {

template <int D>
void select_neighbours_into(std::span<const Vec<D>> offsets, Real support, Real dx,
                            const NeighbourSelection& selection,
                            NeighbourSelectionScratch<D>& scratch, std::vector<int>& out) {
    out.clear();
    const auto add_radius_set = [&] {
        const Real s2 = support * support;
        for (std::size_t j = 0; j < offsets.size(); ++j)
            if (offsets[j].squaredNorm() < s2)
                out.push_back(static_cast<int>(j));
    };
    if (selection.policy == NeighbourPolicy::radius) {
        add_radius_set();
        return;
    }
    const Real rc = Real(selection.candidate_radius_over_dx) * dx;
    std::vector<int>& candidate = scratch.candidate;
    MappedHull<D>& hull = scratch.hull;
    mapped_hull_within_into<D>(offsets, rc * rc, HullPrefilter::inscribed_ball, scratch.hull_work,
                               hull, candidate, selection.hull_boundary);
    // Both lists ascend, and so do the candidates: the output ascends without a sort.
    for (int k : selection.hull_boundary ? hull.boundary : hull.vertices)
        out.push_back(candidate[static_cast<std::size_t>(k)]);
    if (selection.union_with_radius) {
        add_radius_set();
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }
}

template <int D>
std::vector<int> select_neighbours(std::span<const Vec<D>> offsets, Real support, Real dx,
                                   const NeighbourSelection& selection) {
    thread_local NeighbourSelectionScratch<D> scratch; // reused between calls
    std::vector<int> out;
    select_neighbours_into<D>(offsets, support, dx, selection, scratch, out);
    return out;
}

template std::vector<int> select_neighbours<2>(std::span<const Vec<2>>, Real, Real,
                                               const NeighbourSelection&);
template std::vector<int> select_neighbours<3>(std::span<const Vec<3>>, Real, Real,
                                               const NeighbourSelection&);
template void select_neighbours_into<2>(std::span<const Vec<2>>, Real, Real,
                                        const NeighbourSelection&, NeighbourSelectionScratch<2>&,
                                        std::vector<int>&);
template void select_neighbours_into<3>(std::span<const Vec<3>>, Real, Real,
                                        const NeighbourSelection&, NeighbourSelectionScratch<3>&,
                                        std::vector<int>&);

} // namespace sluice
