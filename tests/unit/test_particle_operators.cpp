// MPS (Koshizuka & Oka 1996) and SPH operators behind particle_operators.hpp: on a regular
// lattice MPS is exact for quadratic fields by construction of n0 and lambda, SPH is close
// (its kernel sums approximate integrals), WMLS is exact; the lattice constants match their
// definitions.
#include "sluice/physics/particle_operators.hpp"

#include <doctest/doctest.h>

#include <vector>

using namespace sluice;

namespace {

constexpr Real l0 = 0.1, re = 3.1 * l0;

template <int D>
std::vector<Vec<D>> lattice_offsets() {
    std::vector<Vec<D>> o;
    const int m = 4;
    for (int i = -m; i <= m; ++i)
        for (int j = -m; j <= m; ++j)
            for (int k = (D == 3 ? -m : 0); k <= (D == 3 ? m : 0); ++k) {
                if (i == 0 && j == 0 && k == 0)
                    continue;
                Vec<D> p;
                p[0] = i * l0;
                p[1] = j * l0;
                if constexpr (D == 3)
                    p[2] = k * l0;
                o.push_back(p);
            }
    return o;
}

// f = g.x + x^T H x / 2 about the particle at the origin.
template <int D>
void check_lattice(Operator op, Real grad_tol, Real lap_tol) {
    Vec<D> g;
    Mat<D> H;
    for (int a = 0; a < D; ++a) {
        g[a] = 1.5 - a;
        for (int b = 0; b < D; ++b)
            H(a, b) = a == b ? 2.0 + a : 0.7;
    }
    const auto o = lattice_offsets<D>();
    std::vector<Real> df;
    for (const auto& p : o)
        df.push_back(g.dot(p) + 0.5 * p.dot(H * p));
    const auto s = operator_settings<D>(op, l0, re);
    const auto r = particle_derivatives<D>(s, o, df);
    INFO(operator_name(op), " D=", D, ": gradient ", r.gradient.transpose(), ", Laplacian ",
         r.laplacian, " (exact ", H.trace(), ")");
    CHECK(r.ok);
    CHECK((r.gradient - g).norm() <= grad_tol * g.norm());
    CHECK(std::abs(r.laplacian - H.trace()) <= lap_tol * H.trace());
}

} // namespace

TEST_CASE("MPS constants: n0 = sum w and lambda = sum w r^2 / sum w on the lattice") {
    const auto c = mps_lattice_constants<2>(l0, re, LsWeight::pnu_mps);
    Real sw = 0, swr2 = 0;
    for (const auto& p : lattice_offsets<2>()) {
        const Real w = ls_weight(p.norm(), re, LsWeight::pnu_mps);
        sw += w;
        swr2 += w * p.squaredNorm();
    }
    CHECK(c.n0 == doctest::Approx(sw).epsilon(1e-14));
    CHECK(c.lambda == doctest::Approx(swr2 / sw).epsilon(1e-14));
    // Weights vanish at re and beyond; PNU-MPS is finite at r = 0.
    CHECK(ls_weight(re, re, LsWeight::pnu_mps) == 0);
    CHECK(ls_weight(re, re, LsWeight::smooth) == 0);
    CHECK(ls_weight(0, re, LsWeight::pnu_mps) == doctest::Approx(17.0 / 3));
    CHECK(ls_weight(0.999999 * re, re, LsWeight::pnu_mps) < 1e-5);
    CHECK(ls_weight(0, re, LsWeight::smooth) == 1);
}

TEST_CASE("On a regular lattice MPS and WMLS are exact for quadratics, SPH close") {
    check_lattice<2>(Operator::wmls, 1e-12, 1e-12);
    check_lattice<3>(Operator::wmls, 1e-12, 1e-12);
    check_lattice<2>(Operator::mps, 1e-12, 1e-12);
    check_lattice<3>(Operator::mps, 1e-12, 1e-12);
    check_lattice<2>(Operator::sph, 1e-2, 3e-2);
    check_lattice<3>(Operator::sph, 1e-2, 3e-2);
}

TEST_CASE("A lone particle gets zero derivatives and ok = false from every operator") {
    for (const Operator op : {Operator::wmls, Operator::mps, Operator::sph}) {
        const auto r = particle_derivatives<2>(operator_settings<2>(op, l0, re), {}, {});
        CHECK_FALSE(r.ok);
        CHECK(r.gradient.norm() == 0);
        CHECK(r.laplacian == 0);
    }
}
