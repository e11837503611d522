#pragma once
// SPH gradient and Laplacian of a scalar field, in the forms the WCSPH solver uses
// (kernels.hpp, momentum.hpp), for comparison with WMLS and MPS on the same particles:
//   <grad f>_i = sum_j V_j (f_j - f_i) grad_i W_ij                       (difference form,
//                exact for constants; Monaghan 1992)
//   <lap f>_i  = 2 sum_j V_j (f_i - f_j) (x_ij . grad_i W_ij) / (r_ij^2 + eta^2),
//                eta^2 = 0.01 h^2                                          (Morris et al. 1997)
// with x_ij = x_i - x_j and one volume V for every neighbour (uniform particles: V = l0^D).
#include "sluice/core/types.hpp"
#include "sluice/physics/diff_result.hpp"

#include <cmath>
#include <span>

namespace sluice {

template <int D, class K>
DiffResult<D> sph_derivatives(std::span<const Vec<D>> offsets, std::span<const Real> differences,
                              const K& kernel, Real volume) {
    DiffResult<D> out;
    const Real eta2 = Real(0.01) * kernel.h * kernel.h;
    const Real support = kernel.support();
    for (std::size_t j = 0; j < offsets.size(); ++j) {
        const Real r2 = offsets[j].squaredNorm();
        const Real r = std::sqrt(r2);
        if (r <= 0 || r >= support)
            continue;
        const Real dW = kernel.dW(r);
        // grad_i W_ij = dW/dr (x_i - x_j) / r = -dW/dr offset / r; x_ij . grad_i W_ij = r dW/dr.
        out.gradient -= (volume * differences[j] * dW / r) * offsets[j];
        out.laplacian -= 2 * volume * differences[j] * r * dW / (r2 + eta2);
        ++out.rank;
    }
    out.ok = out.rank > 0;
    return out;
}

} // namespace sluice
