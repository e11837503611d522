// WMLS stencil coefficients (docs/WMLS.md). Unknowns, in scaled form (a~ = S a):
//   2-D: re f_x, re f_y, re^2 f_xx, re^2 f_yy, re^2 f_xy
//   3-D: re f_x, re f_y, re f_z, re^2 f_xx, re^2 f_yy, re^2 f_zz, re^2 f_xy, re^2 f_xz, re^2 f_yz
// Row j of the scaled design matrix: sqrt(w_j) (s, s_a^2 / 2, s_a s_b), s = (x_j - x_i) / re.
#include "sluice/physics/wmls.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <cmath>
#include <limits>

namespace sluice::physics {

namespace {

using MatX = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
using VecX = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

// Columns: the D gradient components and the Laplacian, as functionals on the scaled
// unknowns a~ (the 1/re and 1/re^2 of the unscaling are applied to the coefficients later).
template <int D>
MatX target_functionals() {
    MatX G = MatX::Zero(wmls_unknowns<D>, D + 1);
    for (int a = 0; a < D; ++a) {
        G(a, a) = 1;
        G(D + a, D) = 1;
    }
    return G;
}

// Coefficients (N x k) of the least-squares estimates of G^T a~ from the truncated SVD of B:
// B^+ = V_r S_r^-1 U_r^T (minimum-norm solution among the numerically equivalent fits).
MatX svd_coefficients(const Eigen::JacobiSVD<MatX>& svd, const MatX& G, Eigen::Index r) {
    const MatX Vr = svd.matrixV().leftCols(r);
    const VecX inv_s = svd.singularValues().head(r).cwiseInverse();
    return svd.matrixU().leftCols(r) * (inv_s.asDiagonal() * (Vr.transpose() * G));
}

// True when the functional g lies in the row space of B (numerically): then its estimate is
// the same for every least-squares solution, hence exact for every quadratic polynomial.
bool estimable(const Eigen::JacobiSVD<MatX>& svd, Eigen::Index r, const VecX& g) {
    const MatX Vr = svd.matrixV().leftCols(r);
    const VecX residual = g - Vr * (Vr.transpose() * g);
    return residual.norm() <= Real(1e3) * std::numeric_limits<Real>::epsilon() * g.norm() +
                                  wmls_rank_tolerance * g.norm();
}

} // namespace

template <int D>
MatX wmls_design_matrix(std::span<const Vec<D>> offsets, Real re, LsWeight weight) {
    const auto N = static_cast<Eigen::Index>(offsets.size());
    MatX B(N, wmls_unknowns<D>);
    for (Eigen::Index j = 0; j < N; ++j) {
        const Vec<D>& d = offsets[static_cast<std::size_t>(j)];
        const Real sqrt_w = std::sqrt(ls_weight(d.norm(), re, weight));
        const Vec<D> s = d / re;
        int c = 0;
        for (int a = 0; a < D; ++a)
            B(j, c++) = sqrt_w * s[a];
        for (int a = 0; a < D; ++a)
            B(j, c++) = sqrt_w * Real(0.5) * s[a] * s[a];
        for (int a = 0; a < D; ++a)
            for (int b = a + 1; b < D; ++b)
                B(j, c++) = sqrt_w * s[a] * s[b];
    }
    return B;
}

template <int D>
WmlsStencil<D> wmls_stencil(std::span<const Vec<D>> offsets, Real re, LsWeight weight) {
    constexpr int M = wmls_unknowns<D>;
    const auto N = static_cast<Eigen::Index>(offsets.size());
    WmlsStencil<D> out;
    out.gradient.setZero(D, N);
    out.laplacian.setZero(1, N);
    if (N == 0 || !(re > 0))
        return out;

    const Real inv_re = 1 / re;
    VecX sqrt_w(N);
    for (Eigen::Index j = 0; j < N; ++j)
        sqrt_w[j] = std::sqrt(ls_weight(offsets[static_cast<std::size_t>(j)].norm(), re, weight));
    const MatX B = wmls_design_matrix<D>(offsets, re, weight);
    const MatX G = target_functionals<D>();
    MatX C(N, D + 1); // coefficients of the scaled functionals, before sqrt(w) and unscaling

    // Regular path: a~ = P R^-1 Q^T (W^1/2 df), so g^T a~ = (Q [R^-T P^T g; 0])^T (W^1/2 df).
    Eigen::ColPivHouseholderQR<MatX> qr(B);
    qr.setThreshold(wmls_rank_tolerance);
    out.rank = static_cast<int>(qr.rank());
    if (out.rank == M) {
        MatX Y = qr.colsPermutation().transpose() * G;
        qr.matrixR()
            .topLeftCorner(M, M)
            .template triangularView<Eigen::Upper>()
            .transpose()
            .solveInPlace(Y);
        C.setZero();
        C.topRows(M) = Y;
        C.applyOnTheLeft(qr.householderQ());
        out.ok = true;
    } else {
        // Degenerate stencil (too few neighbours, collinear/coplanar or coincident). Truncated SVD
        // of the second-order fit; a target not determined by it (not in the row space) is
        // taken from the first-order fit (gradient) or set to 0 (Laplacian).
        Eigen::JacobiSVD<MatX> svd(B, Eigen::ComputeThinU | Eigen::ComputeThinV);
        svd.setThreshold(wmls_rank_tolerance);
        const Eigen::Index r = svd.rank();
        out.rank = static_cast<int>(r);
        C = svd_coefficients(svd, G, r);
        bool grad_ok = true;
        MatX C_linear; // first-order fit, computed only when a gradient component needs it
        for (int a = 0; a < D; ++a) {
            if (estimable(svd, r, G.col(a)))
                continue;
            grad_ok = false;
            if (C_linear.size() == 0) {
                Eigen::JacobiSVD<MatX> svd_lin(MatX(B.leftCols(D)),
                                               Eigen::ComputeThinU | Eigen::ComputeThinV);
                svd_lin.setThreshold(wmls_rank_tolerance);
                C_linear = svd_coefficients(svd_lin, MatX::Identity(D, D), svd_lin.rank());
            }
            C.col(a) = C_linear.col(a);
        }
        const bool lap_ok = estimable(svd, r, G.col(D));
        if (!lap_ok)
            C.col(D).setZero();
        out.ok = grad_ok && lap_ok;
    }

    for (Eigen::Index j = 0; j < N; ++j) {
        out.gradient.col(j) = (sqrt_w[j] * inv_re) * C.row(j).head(D).transpose();
        out.laplacian(0, j) = sqrt_w[j] * inv_re * inv_re * C(j, D);
    }
    return out;
}

template <int D>
DiffResult<D> apply_stencil(const WmlsStencil<D>& stencil, std::span<const Real> differences) {
    const Eigen::Map<const VecX> df(differences.data(),
                                    static_cast<Eigen::Index>(differences.size()));
    DiffResult<D> r;
    r.gradient = stencil.gradient * df;
    r.laplacian = stencil.laplacian.dot(df);
    r.ok = stencil.ok;
    r.rank = stencil.rank;
    return r;
}

template <int D>
DiffResult<D> wmls_derivatives(std::span<const Vec<D>> offsets, std::span<const Real> differences,
                               Real re, LsWeight weight) {
    return apply_stencil<D>(wmls_stencil<D>(offsets, re, weight), differences);
}

template MatX wmls_design_matrix<2>(std::span<const Vec<2>>, Real, LsWeight);
template MatX wmls_design_matrix<3>(std::span<const Vec<3>>, Real, LsWeight);
template WmlsStencil<2> wmls_stencil<2>(std::span<const Vec<2>>, Real, LsWeight);
template WmlsStencil<3> wmls_stencil<3>(std::span<const Vec<3>>, Real, LsWeight);
template DiffResult<2> apply_stencil<2>(const WmlsStencil<2>&, std::span<const Real>);
template DiffResult<3> apply_stencil<3>(const WmlsStencil<3>&, std::span<const Real>);
template DiffResult<2> wmls_derivatives<2>(std::span<const Vec<2>>, std::span<const Real>, Real,
                                           LsWeight);
template DiffResult<3> wmls_derivatives<3>(std::span<const Vec<3>>, std::span<const Real>, Real,
                                           LsWeight);

} // namespace sluice::physics
