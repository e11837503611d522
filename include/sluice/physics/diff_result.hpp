#pragma once
// What every particle differential operator (WMLS, MPS, SPH) returns for one particle.
#include "sluice/core/types.hpp"

namespace sluice {

template <int D>
struct DiffResult {
    Vec<D> gradient = Vec<D>::Zero();
    Real laplacian = 0;
    // WMLS: true when both the gradient and the Laplacian are exact for every quadratic
    // polynomial on this stencil (docs/WMLS.md, "Degenerate stencils"). MPS and SPH: true
    // when the particle had at least one neighbour inside the support.
    bool ok = false;
    // WMLS: numerical rank of the weighted second-order design matrix (5 in 2-D, 9 in 3-D when
    // full). MPS and SPH: number of neighbours that contributed.
    int rank = 0;
};

} // namespace sluice
