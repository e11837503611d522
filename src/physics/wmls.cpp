// WMLS stencil coefficients (docs/WMLS.md). Unknowns, in scaled form (a~ = S a):
//   2-D: re f_x, re f_y, re^2 f_xx, re^2 f_yy, re^2 f_xy
//   3-D: re f_x, re f_y, re f_z, re^2 f_xx, re^2 f_yy, re^2 f_zz, re^2 f_xy, re^2 f_xz, re^2 f_yz
// Row j of the scaled design matrix: sqrt(w_j) (s, s_a^2 / 2, s_a s_b), s = (x_j - x_i) / re.
#include "sluice/physics/wmls.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <cmath>
#include <limits>

namespace sluice {

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

namespace {

// Row j of the scaled design matrix into B (N x M, column-major, leading dimension N).
template <int D>
void fill_design_row(Real* B, Eigen::Index N, Eigen::Index j, const Vec<D>& d, Real sqrt_w,
                     Real re) {
    const Vec<D> s = d / re;
    Eigen::Index c = 0;
    for (int a = 0; a < D; ++a)
        B[j + N * c++] = sqrt_w * s[a];
    for (int a = 0; a < D; ++a)
        B[j + N * c++] = sqrt_w * Real(0.5) * s[a] * s[a];
    for (int a = 0; a < D; ++a)
        for (int b = a + 1; b < D; ++b)
            B[j + N * c++] = sqrt_w * s[a] * s[b];
}

} // namespace

template <int D>
MatX wmls_design_matrix(std::span<const Vec<D>> offsets, Real re, LsWeight weight) {
    const auto N = static_cast<Eigen::Index>(offsets.size());
    MatX B(N, wmls_unknowns<D>);
    for (Eigen::Index j = 0; j < N; ++j) {
        const Vec<D>& d = offsets[static_cast<std::size_t>(j)];
        fill_design_row<D>(B.data(), N, j, d, std::sqrt(ls_weight(d.norm(), re, weight)), re);
    }
    return B;
}

template <int D>
WmlsFit wmls_stencil_into(std::span<const Vec<D>> offsets, Real re, LsWeight weight,
                          WmlsWorkspace<D>& ws) {
    constexpr int M = wmls_unknowns<D>;
    const auto N = static_cast<Eigen::Index>(offsets.size());
    const auto n = offsets.size();
    WmlsFit out;
    ws.gradient.assign(n, Vec<D>::Zero());
    ws.laplacian.assign(n, Real(0));
    if (N == 0 || !(re > 0))
        return out;

    const Real inv_re = 1 / re;
    ws.sqrt_w.resize(n);
    ws.design.resize(n * M);
    ws.coefficients.resize(n * (D + 1));
    for (Eigen::Index j = 0; j < N; ++j) {
        const Vec<D>& d = offsets[static_cast<std::size_t>(j)];
        ws.sqrt_w[static_cast<std::size_t>(j)] = std::sqrt(ls_weight(d.norm(), re, weight));
        fill_design_row<D>(ws.design.data(), N, j, d, ws.sqrt_w[static_cast<std::size_t>(j)], re);
    }
    const Eigen::Map<const MatX> B(ws.design.data(), N, M);
    if (ws.targets.size() == 0)
        ws.targets = target_functionals<D>();
    const MatX& G = ws.targets;
    // Coefficients of the scaled functionals, before sqrt(w) and unscaling.
    Eigen::Map<MatX> C(ws.coefficients.data(), N, D + 1);

    // Regular path: a~ = P R^-1 Q^T (W^1/2 df), so g^T a~ = (Q [R^-T P^T g; 0])^T (W^1/2 df).
    auto& qr = ws.qr;
    qr.compute(B);
    qr.setThreshold(wmls_rank_tolerance);
    out.rank = static_cast<int>(qr.rank());
    if (out.rank == M) {
        ws.y = qr.colsPermutation().transpose() * G;
        qr.matrixR()
            .topLeftCorner(M, M)
            .template triangularView<Eigen::Upper>()
            .transpose()
            .solveInPlace(ws.y);
        C.setZero();
        C.topRows(M) = ws.y;
        qr.householderQ().applyThisOnTheLeft(C, ws.householder);
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
        const auto u = static_cast<std::size_t>(j);
        ws.gradient[u] = (ws.sqrt_w[u] * inv_re) * C.row(j).head(D).transpose();
        ws.laplacian[u] = ws.sqrt_w[u] * inv_re * inv_re * C(j, D);
    }
    return out;
}

template <int D>
WmlsStencil<D> wmls_stencil(std::span<const Vec<D>> offsets, Real re, LsWeight weight) {
    WmlsWorkspace<D> ws;
    const WmlsFit fit = wmls_stencil_into<D>(offsets, re, weight, ws);
    const auto N = static_cast<Eigen::Index>(offsets.size());
    WmlsStencil<D> out;
    out.gradient.resize(D, N);
    out.laplacian.resize(1, N);
    for (Eigen::Index j = 0; j < N; ++j) {
        out.gradient.col(j) = ws.gradient[static_cast<std::size_t>(j)];
        out.laplacian(0, j) = ws.laplacian[static_cast<std::size_t>(j)];
    }
    out.ok = fit.ok;
    out.rank = fit.rank;
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
template WmlsFit wmls_stencil_into<2>(std::span<const Vec<2>>, Real, LsWeight, WmlsWorkspace<2>&);
template WmlsFit wmls_stencil_into<3>(std::span<const Vec<3>>, Real, LsWeight, WmlsWorkspace<3>&);
template WmlsStencil<2> wmls_stencil<2>(std::span<const Vec<2>>, Real, LsWeight);
template WmlsStencil<3> wmls_stencil<3>(std::span<const Vec<3>>, Real, LsWeight);
template DiffResult<2> apply_stencil<2>(const WmlsStencil<2>&, std::span<const Real>);
template DiffResult<3> apply_stencil<3>(const WmlsStencil<3>&, std::span<const Real>);
template DiffResult<2> wmls_derivatives<2>(std::span<const Vec<2>>, std::span<const Real>, Real,
                                           LsWeight);
template DiffResult<3> wmls_derivatives<3>(std::span<const Vec<3>>, std::span<const Real>, Real,
                                           LsWeight);

} // namespace sluice
