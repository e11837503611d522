// Per-operator neighbour sets of the WMLS operators; see selected_operators.hpp.
#include "sluice/physics/selected_operators.hpp"

#include "sluice/physics/free_surface.hpp"
#include "sluice/physics/neighbour_selection.hpp"
#include "sluice/physics/wmls.hpp"

#include <algorithm>

namespace sluice {
namespace {

// The offsets an operator uses: all of them (radius: every given offset is within re), or
// the selected ones gathered in scratch.sub with their indices in scratch.pick.
template <int D>
std::span<const Vec<D>> operator_set(std::span<const Vec<D>> offsets, const NeighbourSelection& s,
                                     Real re, Real dx, SelectedOperatorScratch<D>& scratch) {
    if (s.policy == NeighbourPolicy::radius)
        return offsets;
    select_neighbours_into<D>(offsets, re, dx, s, scratch.selection, scratch.pick);
    scratch.sub.clear();
    for (int k : scratch.pick)
        scratch.sub.push_back(offsets[static_cast<std::size_t>(k)]);
    return scratch.sub;
}

} // namespace

template <int D>
SelectedOperators<D>
selected_operators(std::span<const Vec<D>> offsets, const OperatorSelections& selections, Real re,
                   Real dx, LsWeight weight, Real surface_diameter, std::span<Vec<D>> gradient,
                   std::span<Real> laplacian, std::span<Vec<D>> linear_gradient,
                   SelectedOperatorScratch<D>& scratch) {
    SelectedOperators<D> out;
    std::fill(gradient.begin(), gradient.end(), Vec<D>::Zero());
    std::fill(laplacian.begin(), laplacian.end(), Real(0));
    std::fill(linear_gradient.begin(), linear_gradient.end(), Vec<D>::Zero());
    // One fit over one operator's set; writes the coefficients the flags ask for.
    const auto fit = [&](const NeighbourSelection& s, bool grad, bool lap) {
        const std::span<const Vec<D>> set = operator_set<D>(offsets, s, re, dx, scratch);
        const bool all = s.policy == NeighbourPolicy::radius;
        const auto index = [&](std::size_t m) {
            return all ? m : static_cast<std::size_t>(scratch.pick[m]);
        };
        const WmlsFit st = wmls_stencil_into<D>(set, re, weight, scratch.wmls);
        for (std::size_t m = 0; m < set.size(); ++m) {
            if (grad)
                gradient[index(m)] = scratch.wmls.gradient[m];
            if (lap)
                laplacian[index(m)] = scratch.wmls.laplacian[m];
        }
        if (grad && !linear_gradient.empty()) {
            scratch.linear.resize(set.size());
            out.linear_ok =
                wmls_linear_gradient<D>(set, re, weight, std::span<Vec<D>>(scratch.linear));
            if (out.linear_ok)
                for (std::size_t m = 0; m < set.size(); ++m)
                    linear_gradient[index(m)] = scratch.linear[m];
        }
        return st.ok;
    };
    if (selections.gradient == selections.laplacian) {
        out.ok = out.laplacian_ok = fit(selections.gradient, true, true);
    } else {
        const bool grad_ok = fit(selections.gradient, true, false);
        out.laplacian_ok = fit(selections.laplacian, false, true);
        out.ok = grad_ok && out.laplacian_ok;
    }
    out.free_surface =
        is_free_surface<D>(operator_set<D>(offsets, selections.free_surface, re, dx, scratch),
                           surface_diameter, scratch.surface);
    return out;
}

#define SLUICE_SELECTED_OPERATORS(D)                                                               \
    template SelectedOperators<D> selected_operators<D>(                                           \
        std::span<const Vec<D>>, const OperatorSelections&, Real, Real, LsWeight, Real,            \
        std::span<Vec<D>>, std::span<Real>, std::span<Vec<D>>, SelectedOperatorScratch<D>&);
SLUICE_SELECTED_OPERATORS(2)
SLUICE_SELECTED_OPERATORS(3)
#undef SLUICE_SELECTED_OPERATORS

} // namespace sluice
