#pragma once
// Moving Particle Semi-implicit (MPS) gradient and Laplacian models of Koshizuka & Oka (1996),
// with the weight w of ls_weight.hpp (Park et al. (2014) compares against them with the PNU-MPS weight):
//   <grad f>_i = d / n0            sum_j (f_j - f_i) (x_j - x_i) / |x_j - x_i|^2 w_ij
//   <lap f>_i  = 2 d / (lambda n0) sum_j (f_j - f_i) w_ij
//   n0     = sum_j w_ij                      over a regular lattice (particle number density)
//   lambda = sum_j w_ij r_ij^2 / sum_j w_ij  over the same lattice (makes the Laplacian's
//            variance match the analytic diffusion, K&O 1996)
// d is the dimension. Both are exact only for linear/quadratic fields on the regular lattice;
// on irregular particles they are inconsistent (docs/WMLS.md, "MPS and SPH").
#include "sluice/core/types.hpp"
#include "sluice/physics/diff_result.hpp"
#include "sluice/physics/ls_weight.hpp"

#include <cmath>
#include <span>

namespace sluice {

struct MpsConstants {
    Real n0 = 0;
    Real lambda = 0;
};

// n0 and lambda from the square (2-D) or cubic (3-D) lattice of spacing l0 around a particle.
template <int D>
MpsConstants mps_lattice_constants(Real l0, Real re, LsWeight weight) {
    const int m = static_cast<int>(std::ceil(re / l0));
    Real sum_w = 0, sum_wr2 = 0;
    const int kmin = D == 3 ? -m : 0, kmax = D == 3 ? m : 0;
    for (int i = -m; i <= m; ++i)
        for (int j = -m; j <= m; ++j)
            for (int k = kmin; k <= kmax; ++k) {
                if (i == 0 && j == 0 && k == 0)
                    continue;
                const Real r2 = l0 * l0 * Real(i * i + j * j + k * k);
                const Real w = ls_weight(std::sqrt(r2), re, weight);
                sum_w += w;
                sum_wr2 += w * r2;
            }
    return {sum_w, sum_w > 0 ? sum_wr2 / sum_w : 0};
}

template <int D>
DiffResult<D> mps_derivatives(std::span<const Vec<D>> offsets, std::span<const Real> differences,
                              Real re, LsWeight weight, const MpsConstants& c) {
    DiffResult<D> out;
    for (std::size_t j = 0; j < offsets.size(); ++j) {
        const Real r2 = offsets[j].squaredNorm();
        const Real w = ls_weight(std::sqrt(r2), re, weight);
        if (w <= 0 || r2 <= 0)
            continue;
        out.gradient += (differences[j] * w / r2) * offsets[j];
        out.laplacian += differences[j] * w;
        ++out.rank;
    }
    out.gradient *= Real(D) / c.n0;
    out.laplacian *= 2 * Real(D) / (c.lambda * c.n0);
    out.ok = out.rank > 0;
    return out;
}

} // namespace sluice
