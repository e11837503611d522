// WMLS operators (docs/WMLS.md): exact for every quadratic polynomial on random non-degenerate
// stencils in 2-D and 3-D, for both weights and for one-sided (free-surface) stencils; the
// stencil coefficients give the same result as a direct fit; degenerate stencils return
// finite values, the documented fallback and ok = false.
#include "sluice/physics/wmls.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace sluice;

namespace {

// f(x) = c + g.x + x^T H x / 2 with random g and symmetric H.
template <int D>
struct Quadratic {
    Real c;
    Vec<D> g;
    Mat<D> H;
    Real operator()(const Vec<D>& x) const { return c + g.dot(x) + Real(0.5) * x.dot(H * x); }
    Vec<D> gradient(const Vec<D>& x) const { return g + H * x; }
    Real laplacian() const { return H.trace(); }
};

template <int D>
Quadratic<D> random_quadratic(std::mt19937_64& rng) {
    std::uniform_real_distribution<Real> u(-3, 3);
    Quadratic<D> q;
    q.c = u(rng);
    for (int a = 0; a < D; ++a)
        q.g[a] = u(rng);
    for (int a = 0; a < D; ++a)
        for (int b = a; b < D; ++b)
            q.H(a, b) = q.H(b, a) = u(rng);
    return q;
}

// n points uniformly in the ball of radius `radius` (optionally only the half x_0 < 0).
template <int D>
std::vector<Vec<D>> random_offsets(std::mt19937_64& rng, int n, Real radius, bool half = false) {
    std::uniform_real_distribution<Real> u(-1, 1);
    std::vector<Vec<D>> out;
    while (static_cast<int>(out.size()) < n) {
        Vec<D> p;
        for (int a = 0; a < D; ++a)
            p[a] = u(rng);
        if (p.squaredNorm() >= 1 || p.squaredNorm() < 1e-4 || (half && p[0] >= 0))
            continue;
        out.push_back(radius * p);
    }
    return out;
}

template <int D>
std::vector<Real> differences(const Quadratic<D>& f, const Vec<D>& xi,
                              const std::vector<Vec<D>>& offsets) {
    std::vector<Real> df;
    for (const auto& d : offsets)
        df.push_back(f(xi + d) - f(xi));
    return df;
}

template <int D>
bool finite(const DiffResult<D>& r) {
    return r.gradient.allFinite() && std::isfinite(r.laplacian);
}

template <int D>
void check_exact_on_random_stencils(LsWeight weight, bool half, int n_min, int n_max) {
    std::mt19937_64 rng(20140415 + D + 10 * static_cast<int>(weight) + (half ? 100 : 0));
    const Real re = 0.31;
    Real worst_grad = 0, worst_lap = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int n = std::uniform_int_distribution<int>(n_min, n_max)(rng);
        const auto offsets = random_offsets<D>(rng, n, Real(0.999) * re, half);
        const Quadratic<D> f = random_quadratic<D>(rng);
        Vec<D> xi;
        for (int a = 0; a < D; ++a)
            xi[a] = std::uniform_real_distribution<Real>(-2, 2)(rng);
        const auto df = differences<D>(f, xi, offsets);
        const auto r = wmls_derivatives<D>(offsets, df, re, weight);
        REQUIRE(r.ok);
        REQUIRE(r.rank == wmls_unknowns<D>);
        const Vec<D> g = f.gradient(xi);
        // Relative to the size of the data: |f| ~ 3 (1 + |x| + |x|^2), round-off ~ 1e-16 of it.
        worst_grad = std::max(worst_grad, (r.gradient - g).norm() / (1 + g.norm()));
        worst_lap = std::max(worst_lap,
                             std::abs(r.laplacian - f.laplacian()) / (1 + std::abs(f.laplacian())));
    }
    MESSAGE("D=", D, " weight=", static_cast<int>(weight), " half=", half,
            ": worst relative error, gradient ", worst_grad, ", Laplacian ", worst_lap);
    CHECK(worst_grad < 1e-11);
    CHECK(worst_lap < 1e-9);
}

} // namespace

TEST_CASE("WMLS is exact for quadratic polynomials on random 2-D stencils") {
    check_exact_on_random_stencils<2>(LsWeight::pnu_mps, false, 8, 40);
    check_exact_on_random_stencils<2>(LsWeight::smooth, false, 8, 40);
}

TEST_CASE("WMLS is exact for quadratic polynomials on random 3-D stencils") {
    check_exact_on_random_stencils<3>(LsWeight::pnu_mps, false, 20, 120);
    check_exact_on_random_stencils<3>(LsWeight::smooth, false, 20, 120);
}

TEST_CASE("WMLS is exact on one-sided (free-surface) stencils") {
    check_exact_on_random_stencils<2>(LsWeight::pnu_mps, true, 12, 20);
    check_exact_on_random_stencils<3>(LsWeight::pnu_mps, true, 30, 60);
}

TEST_CASE("Stencil coefficients reproduce the direct fit and sum to zero") {
    std::mt19937_64 rng(7);
    const auto offsets = random_offsets<2>(rng, 25, 0.3);
    const WmlsStencil<2> s = wmls_stencil<2>(offsets, 0.31, LsWeight::pnu_mps);
    REQUIRE(s.gradient.cols() == 25);
    // A constant field has zero differences; a linear one g.x has zero Laplacian and
    // gradient g: sum_j c_j (x_j - x_i)^T = I and sum_j c^lap_j (x_j - x_i) = 0.
    Mat<2> M = Mat<2>::Zero();
    Vec<2> lap_first = Vec<2>::Zero();
    Real lap_second = 0;
    for (std::size_t j = 0; j < offsets.size(); ++j) {
        M += s.gradient.col(static_cast<Eigen::Index>(j)) * offsets[j].transpose();
        lap_first += s.laplacian(static_cast<Eigen::Index>(j)) * offsets[j];
        lap_second +=
            s.laplacian(static_cast<Eigen::Index>(j)) * Real(0.5) * offsets[j].squaredNorm();
    }
    CHECK((M - Mat<2>::Identity()).norm() < 1e-12);
    CHECK(lap_first.norm() < 1e-10);
    CHECK(lap_second == doctest::Approx(2.0).epsilon(1e-12)); // lap(|x|^2 / 2) = D = 2
}

TEST_CASE("Neighbours at or beyond re do not change the result") {
    std::mt19937_64 rng(11);
    auto offsets = random_offsets<2>(rng, 20, 0.3);
    const Quadratic<2> f = random_quadratic<2>(rng);
    const auto df = differences<2>(f, Vec<2>::Zero(), offsets);
    const auto inside = wmls_derivatives<2>(offsets, df, 0.31, LsWeight::smooth);
    auto far = offsets;
    auto df_far = df;
    far.push_back(Vec<2>(0.5, 0.1));
    df_far.push_back(1e6); // would spoil the fit if it were used
    const auto with_far = wmls_derivatives<2>(far, df_far, 0.31, LsWeight::smooth);
    CHECK((with_far.gradient - inside.gradient).norm() < 1e-12);
    CHECK(with_far.laplacian == doctest::Approx(inside.laplacian).epsilon(1e-12));
}

TEST_CASE("Degenerate stencils: finite values, documented fallback, ok = false") {
    const Real re = 0.31;
    // f = 1 + 3x + 2y + x^2 + 5xy - y^2 (gradient at 0: (3, 2), Laplacian 0)
    const auto f = [](const Vec<2>& x) {
        return 1 + 3 * x[0] + 2 * x[1] + x[0] * x[0] + 5 * x[0] * x[1] - x[1] * x[1];
    };
    const auto diffs = [&](const std::vector<Vec<2>>& o) {
        std::vector<Real> d;
        for (const auto& p : o)
            d.push_back(f(p) - f(Vec<2>::Zero()));
        return d;
    };

    SUBCASE("no neighbours") {
        const auto r = wmls_derivatives<2>({}, {}, re, LsWeight::pnu_mps);
        CHECK(finite(r));
        CHECK_FALSE(r.ok);
        CHECK(r.rank == 0);
        CHECK(r.gradient.norm() == 0);
        CHECK(r.laplacian == 0);
    }
    SUBCASE("only coincident neighbours") {
        const std::vector<Vec<2>> o(4, Vec<2>::Zero());
        const auto r = wmls_derivatives<2>(o, std::vector<Real>(4, 1.0), re, LsWeight::pnu_mps);
        CHECK(finite(r));
        CHECK_FALSE(r.ok);
        CHECK(r.rank == 0);
    }
    SUBCASE("three neighbours: first-order gradient, Laplacian 0") {
        const std::vector<Vec<2>> o{{0.1, 0}, {0, 0.1}, {-0.1, -0.1}};
        const auto lin = [](const Vec<2>& x) { return 3 * x[0] + 2 * x[1]; };
        std::vector<Real> d;
        for (const auto& p : o)
            d.push_back(lin(p));
        const auto r = wmls_derivatives<2>(o, d, re, LsWeight::pnu_mps);
        CHECK(finite(r));
        CHECK_FALSE(r.ok);
        CHECK(r.rank == 3);
        CHECK(r.gradient[0] == doctest::Approx(3).epsilon(1e-12)); // exact for linear fields
        CHECK(r.gradient[1] == doctest::Approx(2).epsilon(1e-12));
        CHECK(r.laplacian == 0);
    }
    SUBCASE("collinear neighbours: the derivative along the line is still exact") {
        std::vector<Vec<2>> o;
        for (int k = -3; k <= 3; ++k)
            if (k != 0)
                o.emplace_back(0.09 * k, 0);
        const auto r = wmls_derivatives<2>(o, diffs(o), re, LsWeight::pnu_mps);
        CHECK(finite(r));
        CHECK_FALSE(r.ok);
        CHECK(r.rank == 2);
        CHECK(r.gradient[0] == doctest::Approx(3).epsilon(1e-12)); // quadratic fit on the line
        CHECK(r.gradient[1] == 0);                                 // not seen: minimum norm
        CHECK(r.laplacian == 0);                                   // f_yy not seen
    }
    SUBCASE("nearly collinear neighbours are caught by the rank tolerance") {
        std::vector<Vec<2>> o;
        for (int k = -3; k <= 3; ++k)
            if (k != 0)
                o.emplace_back(0.09 * k, 1e-7 * k * k * k);
        const auto r = wmls_derivatives<2>(o, diffs(o), re, LsWeight::pnu_mps);
        CHECK(finite(r));
        CHECK_FALSE(r.ok);
        CHECK(r.rank < 5);
        CHECK(std::abs(r.laplacian) < 1e-6);
    }
    SUBCASE("plus-shaped stencil: f_xy unseen but gradient and Laplacian exact") {
        std::vector<Vec<2>> o;
        for (int k = -3; k <= 3; ++k)
            if (k != 0) {
                o.emplace_back(0.09 * k, 0);
                o.emplace_back(0, 0.09 * k);
            }
        const auto r = wmls_derivatives<2>(o, diffs(o), re, LsWeight::pnu_mps);
        CHECK(finite(r));
        CHECK(r.ok);
        CHECK(r.rank == 4);
        CHECK(r.gradient[0] == doctest::Approx(3).epsilon(1e-12));
        CHECK(r.gradient[1] == doctest::Approx(2).epsilon(1e-12));
        CHECK(std::abs(r.laplacian) < 1e-10);
    }
    SUBCASE("coplanar neighbours in 3-D") {
        std::mt19937_64 rng(3);
        std::vector<Vec<3>> o;
        for (const auto& p : random_offsets<2>(rng, 30, 0.3))
            o.emplace_back(p[0], p[1], 0);
        // f = 2x - y + 4z + x^2 + y^2 + 3 z^2 + xz: in-plane derivatives exact, f_z unseen.
        std::vector<Real> d;
        for (const auto& p : o)
            d.push_back(2 * p[0] - p[1] + 4 * p[2] + p[0] * p[0] + p[1] * p[1] + 3 * p[2] * p[2] +
                        p[0] * p[2]);
        const auto r = wmls_derivatives<3>(o, d, re, LsWeight::smooth);
        CHECK(finite(r));
        CHECK_FALSE(r.ok);
        CHECK(r.rank == 5);
        CHECK(r.gradient[0] == doctest::Approx(2).epsilon(1e-11));
        CHECK(r.gradient[1] == doctest::Approx(-1).epsilon(1e-11));
        CHECK(r.gradient[2] == 0);
        CHECK(r.laplacian == 0);
    }
    SUBCASE("random small or flat sets never give a NaN") {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<Real> u(-0.3, 0.3);
        for (int trial = 0; trial < 2000; ++trial) {
            const int n = trial % 8;
            std::vector<Vec<2>> o;
            std::vector<Real> d;
            const bool flat = trial % 3 == 0;
            for (int k = 0; k < n; ++k) {
                const Real x = u(rng);
                o.emplace_back(x, flat ? 0.5 * x : u(rng));
                d.push_back(u(rng));
            }
            const auto r = wmls_derivatives<2>(o, d, re, LsWeight::pnu_mps);
            REQUIRE(finite(r));
            if (n < 5 || flat)
                CHECK_FALSE(r.ok);
        }
    }
}

TEST_CASE("First-order gradient: hand-computed stencils, linear exactness, singular stencils") {
    const Real re = 3;
    // Two orthogonal unit offsets: M = w diag(1, 1)/9 in the scaled variable, so c_j = r_j:
    // one-sided finite differences, whatever the weight.
    {
        const std::vector<Vec<2>> offsets{Vec<2>(1, 0), Vec<2>(0, 1)};
        std::vector<Vec<2>> c(2);
        REQUIRE(wmls_linear_gradient<2>(offsets, re, LsWeight::pnu_mps, c));
        CHECK(c[0][0] == doctest::Approx(1));
        CHECK(c[0][1] == doctest::Approx(0).epsilon(1e-15));
        CHECK(c[1][0] == doctest::Approx(0).epsilon(1e-15));
        CHECK(c[1][1] == doctest::Approx(1));
    }
    // The symmetric cross (+-1, 0), (0, +-1): central differences, c_j = r_j / 2.
    {
        const std::vector<Vec<2>> offsets{Vec<2>(1, 0), Vec<2>(-1, 0), Vec<2>(0, 1), Vec<2>(0, -1)};
        std::vector<Vec<2>> c(4);
        REQUIRE(wmls_linear_gradient<2>(offsets, re, LsWeight::smooth, c));
        for (std::size_t j = 0; j < 4; ++j)
            CHECK((c[j] - offsets[j] / 2).norm() < 1e-14);
    }
    // Exact for linear fields on random one-sided 3-D stencils: sum_j c_j r_j^T = I.
    {
        std::mt19937_64 rng(2012);
        const auto offsets = random_offsets<3>(rng, 12, 0.3, true);
        std::vector<Vec<3>> c(offsets.size());
        REQUIRE(wmls_linear_gradient<3>(offsets, 0.31, LsWeight::pnu_mps, c));
        Mat<3> sum = Mat<3>::Zero();
        for (std::size_t j = 0; j < offsets.size(); ++j)
            sum += c[j] * offsets[j].transpose();
        CHECK((sum - Mat<3>::Identity()).norm() < 1e-12);
    }
    // Collinear offsets: M is singular, the output is left untouched.
    {
        const std::vector<Vec<2>> offsets{Vec<2>(1, 0), Vec<2>(2, 0), Vec<2>(-1, 0)};
        std::vector<Vec<2>> c(3, Vec<2>(7, 7));
        CHECK_FALSE(wmls_linear_gradient<2>(offsets, re, LsWeight::pnu_mps, c));
        CHECK(c[1] == Vec<2>(7, 7));
    }
}

namespace {

// One workspace through stencils of changing size, full and degenerate (truncated SVD), in
// turn: each result must be bitwise a fresh fit's (nothing of the last stencil leaks into the
// next: stale rows, targets or Householder scratch) and exact on a quadratic.
template <int D>
void check_reused_workspace() {
    std::mt19937_64 rng(2026 + D);
    const Real re = 0.31;
    WmlsWorkspace<D> ws;
    for (const int n : {40, 12, 60, 3, 25, 2, 41, 40}) {
        CAPTURE(n);
        const auto offsets = random_offsets<D>(rng, n, Real(0.95) * re);
        const WmlsFit fit = wmls_stencil_into<D>(offsets, re, LsWeight::pnu_mps, ws);
        const WmlsStencil<D> fresh = wmls_stencil<D>(offsets, re, LsWeight::pnu_mps);
        CHECK(fit.ok == fresh.ok);
        CHECK(fit.rank == fresh.rank);
        REQUIRE(ws.gradient.size() == offsets.size());
        int same = 0;
        for (std::size_t j = 0; j < offsets.size(); ++j) {
            const auto k = static_cast<Eigen::Index>(j);
            same +=
                ws.gradient[j] == fresh.gradient.col(k) && ws.laplacian[j] == fresh.laplacian(0, k)
                    ? 1
                    : 0;
        }
        CHECK(same == n);
        if (n < wmls_unknowns<D>) {
            CHECK_FALSE(fit.ok); // fewer neighbours than unknowns: the SVD path
            continue;
        }
        REQUIRE(fit.ok);
        const Quadratic<D> q = random_quadratic<D>(rng);
        Vec<D> grad = Vec<D>::Zero();
        Real lap = 0;
        for (std::size_t j = 0; j < offsets.size(); ++j) {
            const Real df = q(offsets[j]) - q(Vec<D>::Zero());
            grad += ws.gradient[j] * df;
            lap += ws.laplacian[j] * df;
        }
        CHECK((grad - q.gradient(Vec<D>::Zero())).norm() < 1e-9);
        CHECK(std::abs(lap - q.laplacian()) < 1e-8);
    }
}

} // namespace

TEST_CASE("A reused workspace gives bitwise the fresh fit's coefficients, 2-D and 3-D") {
    check_reused_workspace<2>();
    check_reused_workspace<3>();
}
