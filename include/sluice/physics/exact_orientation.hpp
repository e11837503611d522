#pragma once
// Exact sign of the 2-D orientation determinant, the one predicate every hull decision rests on.
//
//   orient(a, b, c) = (b - a) x (c - a) = (bx - ax)(cy - ay) - (by - ay)(cx - ax)
//
// > 0: a, b, c turn counter-clockwise; < 0: clockwise; 0: collinear. This is the cross product
// P of Lee & Lee (2011, Sklansky's rule) with the sign convention of Shewchuk (1997).
//
// How exactness is obtained: the determinant expands into six products of input coordinates
// (ax by - ax cy - ay bx + ay cx + bx cy - by cx). Each product is split exactly into two
// doubles with a fused multiply-add (p = a*b, e = fma(a, b, -p), a*b = p + e exactly), and the
// twelve doubles are summed without any rounding into a non-overlapping expansion with
// Knuth's two-sum (Shewchuk's Grow-Expansion); the sign of an expansion is the sign of its
// largest component. A cheap floating-point evaluation with Shewchuk's forward error bound
// answers first and the exact path runs only when that bound cannot decide.
// The result is exact for all finite inputs unless a product of two coordinates overflows
// or underflows into the subnormal range (|product| below about 1e-292 but not 0), which
// cannot happen for particle offsets and their inverse-square images.
#include "sluice/core/types.hpp"

#include <cmath>
#include <limits>

namespace sluice {

// The same decided by the exact expansion alone (no floating-point filter); for tests, and the
// filters' fallback.
[[nodiscard]] int orientation_sign_expansion(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c);

// -1, 0 or +1: exact sign of orient(a, b, c). Inline (the hulls call it for every
// turn): Shewchuk's orient2d filter, the rounded determinant having the right sign when its
// magnitude exceeds (3 + 16 eps) eps (|detleft| + |detright|), eps = 2^-53; else the expansion.
[[nodiscard]] inline int orientation_sign(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c) {
    const double detleft = (a.x() - c.x()) * (b.y() - c.y());
    const double detright = (a.y() - c.y()) * (b.x() - c.x());
    const double det = detleft - detright;
    constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
    const double bound = (3 + 16 * eps) * eps * (std::abs(detleft) + std::abs(detright));
    if (det > bound || -det > bound)
        return (det > 0) - (det < 0);
    return orientation_sign_expansion(a, b, c);
}

// 3-D (the hull of convex_hull_3d.hpp): exact sign of
//
//   orient(a, b, c, d) = ((b - a) x (c - a)) . (d - a),
//
// > 0 when d lies on the side of the plane abc into which (b - a) x (c - a) points (abc turn
// counter-clockwise seen from d); 0: coplanar. The opposite sign of Shewchuk's orient3d. Same
// method as in 2-D: the determinant in input coordinates is 24 products of three coordinates,
// each split exactly into four doubles (two fused multiply-adds per factor), summed into an
// expansion; Shewchuk's orient3d error bound answers first.
[[nodiscard]] int orientation_sign_expansion(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c,
                                             const Vec<3>& d);
[[nodiscard]] inline int orientation_sign(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c,
                                          const Vec<3>& d) {
    // Shewchuk's orient3d filter on the differences from a: the rounded determinant has the
    // right sign when its magnitude exceeds (7 + 56 eps) eps times the permanent.
    const Vec<3> u = b - a;
    const Vec<3> v = c - a;
    const Vec<3> w = d - a;
    const double uv_z = u.x() * v.y();
    const double vu_z = u.y() * v.x();
    const double uv_y = u.z() * v.x();
    const double vu_y = u.x() * v.z();
    const double uv_x = u.y() * v.z();
    const double vu_x = u.z() * v.y();
    const double det = w.x() * (uv_x - vu_x) + w.y() * (uv_y - vu_y) + w.z() * (uv_z - vu_z);
    const double permanent = std::abs(w.x()) * (std::abs(uv_x) + std::abs(vu_x)) +
                             std::abs(w.y()) * (std::abs(uv_y) + std::abs(vu_y)) +
                             std::abs(w.z()) * (std::abs(uv_z) + std::abs(vu_z));
    constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
    const double bound = (7 + 56 * eps) * eps * permanent;
    if (det > bound || -det > bound)
        return (det > 0) - (det < 0);
    return orientation_sign_expansion(a, b, c, d);
}

} // namespace sluice
