// Arc (2-D) and cap-boundary (3-D) coverage tests of free_surface.hpp.
#include "sluice/physics/free_surface.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace sluice {

namespace {

constexpr Real two_pi = 2 * std::numbers::pi_v<Real>;
constexpr Real gap_tolerance = Real(1e-9); // rad

using Arc = SurfaceArc;
using Cap = SurfaceCap;
using Intervals = std::vector<std::pair<Real, Real>>;

// True when the arcs cover the whole circle (up to gap_tolerance).
// iv: reused buffer of the intervals inside [0, 2 pi).
bool arcs_cover_circle(const std::vector<Arc>& arcs, Intervals& iv) {
    iv.clear();
    for (const Arc& a : arcs) {
        if (a.half >= std::numbers::pi_v<Real>)
            return true;
        Real lo = std::fmod(a.centre - a.half, two_pi);
        if (lo < 0)
            lo += two_pi;
        const Real hi = lo + 2 * a.half;
        if (hi <= two_pi) {
            iv.emplace_back(lo, hi);
        } else {
            iv.emplace_back(lo, two_pi);
            iv.emplace_back(0, hi - two_pi);
        }
    }
    std::sort(iv.begin(), iv.end());
    Real reach = 0;
    for (const auto& [lo, hi] : iv) {
        if (lo > reach + gap_tolerance)
            return false;
        reach = std::max(reach, hi);
    }
    return reach >= two_pi - gap_tolerance;
}

// The part of cap j's boundary circle inside the open cap k, as an arc in the angle t of
// n(t) = cos_j axis_j + sin_j (cos t e1 + sin t e2). Returns false when it is empty.
// n(t) . axis_k = A + B cos(t - t0) > cos_k.
bool boundary_arc(const Cap& j, const Vec<3>& e1, const Vec<3>& e2, const Cap& k, Arc& arc) {
    const Real A = j.cos_half * j.axis.dot(k.axis);
    const Real p = e1.dot(k.axis), q = e2.dot(k.axis);
    const Real B = j.sin_half * std::hypot(p, q);
    if (B <= 1e-14) { // parallel axes: all or nothing
        arc = {0, std::numbers::pi_v<Real>};
        return A > k.cos_half;
    }
    const Real c = (k.cos_half - A) / B;
    if (c >= 1)
        return false;
    arc = {std::atan2(q, p), c <= -1 ? std::numbers::pi_v<Real> : std::acos(c)};
    return true;
}

bool sphere_uncovered(std::span<const Vec<3>> offsets, Real diameter,
                      FreeSurfaceScratch<3>& scratch) {
    std::vector<Cap>& caps = scratch.caps;
    caps.clear();
    for (const Vec<3>& d : offsets) {
        const Real r = d.norm();
        if (r <= 0 || r >= diameter)
            continue;
        const Real c = r / diameter;
        caps.push_back({d / r, c, std::sqrt(1 - c * c)});
    }
    if (caps.empty())
        return true;
    std::vector<Arc>& arcs = scratch.arcs;
    for (std::size_t j = 0; j < caps.size(); ++j) {
        // Orthonormal frame of the plane normal to axis_j.
        const Vec<3>& u = caps[j].axis;
        const Vec<3> helper = std::abs(u[0]) < 0.9 ? Vec<3>::UnitX() : Vec<3>::UnitY();
        const Vec<3> e1 = u.cross(helper).normalized();
        const Vec<3> e2 = u.cross(e1);
        arcs.clear();
        for (std::size_t k = 0; k < caps.size(); ++k) {
            Arc a{};
            if (k != j && boundary_arc(caps[j], e1, e2, caps[k], a))
                arcs.push_back(a);
        }
        if (!arcs_cover_circle(arcs, scratch.intervals))
            return true;
    }
    return false;
}

bool circle_uncovered(std::span<const Vec<2>> offsets, Real diameter,
                      FreeSurfaceScratch<2>& scratch) {
    std::vector<Arc>& arcs = scratch.arcs;
    arcs.clear();
    for (const Vec<2>& d : offsets) {
        const Real r = d.norm();
        if (r <= 0 || r >= diameter)
            continue;
        arcs.push_back({std::atan2(d[1], d[0]), std::acos(r / diameter)});
    }
    return !arcs_cover_circle(arcs, scratch.intervals);
}

} // namespace

template <int D>
bool is_free_surface(std::span<const Vec<D>> offsets, Real diameter,
                     FreeSurfaceScratch<D>& scratch) {
    if constexpr (D == 2)
        return circle_uncovered(offsets, diameter, scratch);
    else
        return sphere_uncovered(offsets, diameter, scratch);
}

template bool is_free_surface<2>(std::span<const Vec<2>>, Real, FreeSurfaceScratch<2>&);
template bool is_free_surface<3>(std::span<const Vec<3>>, Real, FreeSurfaceScratch<3>&);

} // namespace sluice
