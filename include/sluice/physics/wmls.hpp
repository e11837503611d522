#pragma once
// Weighted moving least squares (WMLS) gradient and Laplacian of Park et al. (2014,
// section 2.2; their eqs. 3-11 are missing from the text and re-derived in docs/WMLS.md).
// f_j - f_i is fitted by the second-order Taylor polynomial of f about x_i over the
// neighbours j, weighted by w(|x_j - x_i|); the fitted first derivatives are the gradient and
// the sum of the fitted pure second derivatives the Laplacian. 5 unknowns in 2-D, 9 in 3-D.
//
// The fit is linear in the data, so it is computed once per particle as coefficients c_j with
//   grad f_i = sum_j c^grad_j (f_j - f_i),   lap f_i = sum_j c^lap_j (f_j - f_i)
// (`wmls_stencil`), which a Poisson solver can reuse for every iterate; `wmls_derivatives`
// applies them to one field.
//
// Solver: column-pivoted Householder QR of the weighted design matrix with columns scaled by
// powers of re (rank revealing; never forms the normal equations, whose condition number is
// the square of the design matrix's). Stencils whose numerical rank is below the number of
// unknowns fall back to a truncated SVD (docs/WMLS.md, "Degenerate stencils"); the result is
// always finite.
#include "sluice/core/types.hpp"
#include "sluice/physics/diff_result.hpp"
#include "sluice/physics/ls_weight.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <span>
#include <vector>

namespace sluice {

// Number of Taylor coefficients fitted: D first and D (D + 1) / 2 second derivatives.
template <int D>
inline constexpr int wmls_unknowns = D + D*(D + 1) / 2;

// A pivot (QR) or singular value (SVD) of the scaled weighted design matrix at or below this
// fraction of the largest counts as zero. The scaled matrix of a full, irregular stencil has
// a ratio of order 1e-1 (perf/wmls/README.md gives the measured minimum); below 1e-3 the
// fitted second derivatives amplify the Taylor remainder by more than 1000.
inline constexpr Real wmls_rank_tolerance = Real(1e-3);

// Scaled weighted design matrix B (N x wmls_unknowns<D>) of the fit, row j:
//   sqrt(w_j) (s, s_a^2 / 2, s_a s_b (a < b)),  s = (x_j - x_i) / re,
// unknowns (re f_a, re^2 f_aa, re^2 f_ab) in that order (docs/WMLS.md, eq. W5).
template <int D>
Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>
wmls_design_matrix(std::span<const Vec<D>> offsets, Real re, LsWeight weight);

// Per-neighbour coefficients of the operators at one particle (columns follow `offsets`).
template <int D>
struct WmlsStencil {
    Eigen::Matrix<Real, D, Eigen::Dynamic> gradient;
    Eigen::Matrix<Real, 1, Eigen::Dynamic> laplacian;
    bool ok = false; // both operators exact for every quadratic polynomial on this stencil
    int rank = 0;    // numerical rank of the second-order design matrix
};

// offsets: x_j - x_i of the neighbours; re: influence radius (neighbours at r >= re get
// weight 0 and coefficient 0).
template <int D>
WmlsStencil<D> wmls_stencil(std::span<const Vec<D>> offsets, Real re, LsWeight weight);

// Storage of the fits of one task, reused from particle to particle: after the first few
// particles the regular (full-rank) fit allocates nothing but the QR's copy of the design
// matrix when the neighbour count changes (a per-particle WmlsStencil allocated about 15
// times, 3 % of a projection step). The results are bitwise those of wmls_stencil: the same
// operations on the same column-major layout.
template <int D>
struct WmlsWorkspace {
    using MatX = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
    std::vector<Real, Eigen::aligned_allocator<Real>> design, coefficients; // N x M, N x (D + 1)
    std::vector<Real> sqrt_w;
    MatX targets, y;
    Eigen::ColPivHouseholderQR<MatX> qr;
    Eigen::Matrix<Real, 1, Eigen::Dynamic> householder;
    // Output, one entry per offset: the coefficients of wmls_stencil's gradient and laplacian.
    std::vector<Vec<D>> gradient;
    std::vector<Real> laplacian;
};

struct WmlsFit {
    bool ok = false; // WmlsStencil::ok
    int rank = 0;    // WmlsStencil::rank
};

// wmls_stencil with its coefficients left in ws.gradient and ws.laplacian.
template <int D>
WmlsFit wmls_stencil_into(std::span<const Vec<D>> offsets, Real re, LsWeight weight,
                          WmlsWorkspace<D>& ws);

// differences: f_j - f_i, in the order of the stencil's offsets.
template <int D>
DiffResult<D> apply_stencil(const WmlsStencil<D>& stencil, std::span<const Real> differences);

template <int D>
DiffResult<D> wmls_derivatives(std::span<const Vec<D>> offsets, std::span<const Real> differences,
                               Real re, LsWeight weight);

// First-order WMLS gradient (the fit of f_j - f_i by g.(x_j - x_i) alone; docs/WMLS.md,
// "First-order gradient"): grad f_i = sum_j c_j (f_j - f_i) with
//   c_j = M^-1 w_j r_j,   M = sum_k w_k r_k r_k^T,   r_j = x_j - x_i,
// exact for every linear field (sum_j c_j r_j^T = I). It needs only D independent directions,
// so it stays well posed on the one-sided stencils of a free surface where the second-order
// fit is truncated. Computed in the scaled variable s = r / re. Returns false and leaves
// `out` untouched when M is numerically singular (smallest eigenvalue below
// wmls_rank_tolerance^2 times the largest: the same threshold as the pivots of the
// second-order fit, squared because M = B^T B).
template <int D>
bool wmls_linear_gradient(std::span<const Vec<D>> offsets, Real re, LsWeight weight,
                          std::span<Vec<D>> out) {
    Mat<D> M = Mat<D>::Zero();
    for (const Vec<D>& r : offsets) {
        const Vec<D> s = r / re;
        M += ls_weight(r.norm(), re, weight) * (s * s.transpose());
    }
    const Eigen::SelfAdjointEigenSolver<Mat<D>> eig(M, Eigen::EigenvaluesOnly);
    const Vec<D>& ev = eig.eigenvalues(); // ascending
    if (!(ev[D - 1] > 0) || !(ev[0] > wmls_rank_tolerance * wmls_rank_tolerance * ev[D - 1]))
        return false;
    const Mat<D> M_inv = M.inverse();
    for (std::size_t j = 0; j < offsets.size(); ++j)
        out[j] = ls_weight(offsets[j].norm(), re, weight) / re * (M_inv * (offsets[j] / re));
    return true;
}

extern template Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>
    wmls_design_matrix<2>(std::span<const Vec<2>>, Real, LsWeight);
extern template Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>
    wmls_design_matrix<3>(std::span<const Vec<3>>, Real, LsWeight);
extern template WmlsFit wmls_stencil_into<2>(std::span<const Vec<2>>, Real, LsWeight,
                                             WmlsWorkspace<2>&);
extern template WmlsFit wmls_stencil_into<3>(std::span<const Vec<3>>, Real, LsWeight,
                                             WmlsWorkspace<3>&);
extern template WmlsStencil<2> wmls_stencil<2>(std::span<const Vec<2>>, Real, LsWeight);
extern template WmlsStencil<3> wmls_stencil<3>(std::span<const Vec<3>>, Real, LsWeight);
extern template DiffResult<2> apply_stencil<2>(const WmlsStencil<2>&, std::span<const Real>);
extern template DiffResult<3> apply_stencil<3>(const WmlsStencil<3>&, std::span<const Real>);
extern template DiffResult<2> wmls_derivatives<2>(std::span<const Vec<2>>, std::span<const Real>,
                                                  Real, LsWeight);
extern template DiffResult<3> wmls_derivatives<3>(std::span<const Vec<3>>, std::span<const Real>,
                                                  Real, LsWeight);

} // namespace sluice
