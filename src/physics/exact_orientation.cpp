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

int orientation_sign(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c) {
    // Shewchuk's orient2d filter: the rounded determinant has the right sign when its
    // magnitude exceeds (3 + 16 eps) eps (|detleft| + |detright|), eps = 2^-53.
    const double detleft = (a.x() - c.x()) * (b.y() - c.y());
    const double detright = (a.y() - c.y()) * (b.x() - c.x());
    const double det = detleft - detright;
    constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
    const double bound = (3 + 16 * eps) * eps * (std::abs(detleft) + std::abs(detright));
    if (det > bound || -det > bound)
        return sign_of(det);
    return orientation_sign_expansion(a, b, c);
}

} // namespace sluice
