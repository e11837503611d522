// Exact orientation predicate: see include/sluice/physics/exact_orientation.hpp for the method.
#include "sluice/physics/exact_orientation.hpp"

#include <array>
#include <cmath>
#include <limits>

namespace sluice {
namespace {

// Knuth's two-sum: s + e == a + b exactly, |e| <= ulp(s)/2.
inline void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bv = s - a;
    const double av = s - bv;
    e = (a - av) + (b - bv);
}

// Adds b to the non-overlapping expansion e[0..n) (increasing magnitude) exactly, dropping
// zero components (Shewchuk 1997, Grow-Expansion with zero elimination). Returns the new size.
int grow_expansion(double* e, int n, double b) {
    double q = b;
    int m = 0;
    for (int i = 0; i < n; ++i) {
        double s = 0;
        double err = 0;
        two_sum(q, e[i], s, err);
        q = s;
        if (err != 0)
            e[m++] = err;
    }
    if (q != 0)
        e[m++] = q;
    return m;
}

int sign_of(double v) {
    return (v > 0) - (v < 0);
}

} // namespace

int orientation_sign_expansion(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c) {
    // The six signed products whose sum is the determinant.
    const std::array<std::array<double, 3>, 6> terms = {{{a.x(), b.y(), 1},
                                                         {a.x(), c.y(), -1},
                                                         {a.y(), b.x(), -1},
                                                         {a.y(), c.x(), 1},
                                                         {b.x(), c.y(), 1},
                                                         {b.y(), c.x(), -1}}};
    std::array<double, 12> e{};
    int n = 0;
    for (const auto& t : terms) {
        const double p = t[0] * t[1];
        const double err = std::fma(t[0], t[1], -p); // exact: t0*t1 == p + err
        n = grow_expansion(e.data(), n, t[2] * p);
        n = grow_expansion(e.data(), n, t[2] * err);
    }
    return n == 0 ? 0 : sign_of(e[static_cast<std::size_t>(n - 1)]);
}

namespace {

// Adds s * x * y * z exactly to the expansion e[0..n): x y = p + q (fma), then p z and q z
// split the same way; four doubles in all. Returns the new size.
int grow_triple_product(double* e, int n, double s, double x, double y, double z) {
    const double p = x * y;
    const double q = std::fma(x, y, -p);
    const double pz = p * z;
    const double pz_err = std::fma(p, z, -pz);
    const double qz = q * z;
    const double qz_err = std::fma(q, z, -qz);
    n = grow_expansion(e, n, s * pz);
    n = grow_expansion(e, n, s * pz_err);
    n = grow_expansion(e, n, s * qz);
    return grow_expansion(e, n, s * qz_err);
}

// Adds s * det[u; v; w] (rows: coordinates) exactly: six products of three coordinates.
int grow_det3(double* e, int n, double s, const Vec<3>& u, const Vec<3>& v, const Vec<3>& w) {
    n = grow_triple_product(e, n, s, u.x(), v.y(), w.z());
    n = grow_triple_product(e, n, -s, u.x(), v.z(), w.y());
    n = grow_triple_product(e, n, -s, u.y(), v.x(), w.z());
    n = grow_triple_product(e, n, s, u.y(), v.z(), w.x());
    n = grow_triple_product(e, n, s, u.z(), v.x(), w.y());
    return grow_triple_product(e, n, -s, u.z(), v.y(), w.x());
}

} // namespace

int orientation_sign_expansion(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c, const Vec<3>& d) {
    // ((b - a) x (c - a)) . (d - a) = -det[a 1; b 1; c 1; d 1]
    //                               = det[b; c; d] - det[a; c; d] + det[a; b; d] - det[a; b; c]
    // (cofactors along the column of ones), 24 products of three input coordinates.
    std::array<double, 96> e{};
    int n = grow_det3(e.data(), 0, 1, b, c, d);
    n = grow_det3(e.data(), n, -1, a, c, d);
    n = grow_det3(e.data(), n, 1, a, b, d);
    n = grow_det3(e.data(), n, -1, a, b, c);
    return n == 0 ? 0 : sign_of(e[static_cast<std::size_t>(n - 1)]);
}

} // namespace sluice
