#pragma once
// The WMLS gradient and Laplacian and the free-surface test of one particle, each over the
// neighbours its own policy selects ([neighbours.<operator>] of the case file,
// neighbour_selection.hpp): radius neighbours as Park et al. (2014) fits them, or the convex-hull
// neighbours of Lee & Lee (2011) (Lee & Lee 2011, after Randles & Libersky 2000) among them.
//
// Input: the offsets x_j - x_i of every neighbour within the influence radius re (the centre
// excluded), in a fixed order. Output per offset, in that order: the gradient and Laplacian
// coefficients (docs/WMLS.md, W7-W8), zero for a neighbour that operator does not use. When
// both operators use the same set, one fit gives both (as with radius neighbours, Park et al. 2014);
// otherwise each operator's coefficients come from the fit over its own set. The candidates of
// a convex-hull selection are the given offsets within its candidate radius: a candidate
// radius beyond re selects among the particles within re.
#include "sluice/core/types.hpp"
#include "sluice/physics/free_surface.hpp"
#include "sluice/physics/ls_weight.hpp"
#include "sluice/physics/neighbour_selection.hpp"
#include "sluice/physics/options.hpp"
#include "sluice/physics/wmls.hpp"

#include <span>
#include <vector>

namespace sluice {

struct OperatorSelections {
    NeighbourSelection gradient, laplacian, free_surface;
    [[nodiscard]] bool all_radius() const {
        return gradient.policy == NeighbourPolicy::radius &&
               laplacian.policy == NeighbourPolicy::radius &&
               free_surface.policy == NeighbourPolicy::radius;
    }
};

// Reused buffers (one per task: nothing is shared).
template <int D>
struct SelectedOperatorScratch {
    std::vector<Vec<D>> sub;
    std::vector<int> pick;
    NeighbourSelectionScratch<D> selection;
    std::vector<Vec<D>> linear;
    WmlsWorkspace<D> wmls;
    FreeSurfaceScratch<D> surface;
};

template <int D>
struct SelectedOperators {
    bool ok = false;           // both fits exact for every quadratic polynomial (WmlsStencil::ok)
    bool laplacian_ok = false; // the Laplacian's fit alone
    bool free_surface = false; // Dilts' arc test (free_surface.hpp) over its neighbours
    bool linear_ok = false;    // the first-order gradient was fitted (when asked for)
};

// gradient, laplacian: one entry per offset. linear_gradient: empty, or one entry per offset
// for the first-order gradient (docs/WMLS.md) over the gradient's neighbours, written only
// where it is well posed (linear_ok). dx scales the candidate radius; surface_diameter is the
// arc test's circle.
template <int D>
SelectedOperators<D>
selected_operators(std::span<const Vec<D>> offsets, const OperatorSelections& selections, Real re,
                   Real dx, LsWeight weight, Real surface_diameter, std::span<Vec<D>> gradient,
                   std::span<Real> laplacian, std::span<Vec<D>> linear_gradient,
                   SelectedOperatorScratch<D>& scratch);

} // namespace sluice
