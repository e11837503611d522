// Inverse-square images of candidate neighbours and their convex hull; see mapped_hull.hpp.
#include "sluice/physics/mapped_hull.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace sluice {

namespace {

// Relative margins of the prefilter: an edge/triangle counts as seen from the origin with the
// right orientation when its orientation determinant exceeds this fraction of the product of
// its corners' lengths; an image is dropped when |r'| < (1 - kDropMargin) rho.
constexpr Real kOrientationMargin = Real(1e-6);
constexpr Real kDropMargin = Real(1e-2);

// The extreme images along the 2 D coordinate half-axes: e[2 a] is the index of the image
// farthest along +axis a, e[2 a + 1] along -axis a (the first of equals; -1 if no image lies
// strictly on that side), and the largest squared norm; fed one image at a time, in order.
template <int D>
struct Extremes {
    std::array<int, 2 * D> e;
    std::array<Real, 2 * D> far{};
    Real size2 = 0;
    Extremes() { e.fill(-1); }
    void add(const Vec<D>& q, int i) {
        size2 = std::max(size2, q.squaredNorm());
        add_directions(q, i);
    }
    // Selects, not branches: which image is a new extreme is random, and a mispredicted
    // branch costs more than the selects.
    void add_directions(const Vec<D>& q, int i) {
        for (int a = 0; a < D; ++a) {
            const auto up = static_cast<std::size_t>(2 * a);
            const Real plus = q[a];
            const Real minus = -q[a];
            const bool more = plus > far[up];
            const bool less = minus > far[up + 1];
            far[up] = more ? plus : far[up];
            e[up] = more ? i : e[up];
            far[up + 1] = less ? minus : far[up + 1];
            e[up + 1] = less ? i : e[up + 1];
        }
    }
};

template <int D>
Extremes<D> extreme_images(std::span<const Vec<D>> p) {
    Extremes<D> x;
    for (std::size_t i = 0; i < p.size(); ++i)
        x.add(p[i], static_cast<int>(i));
    return x;
}

// The star-shaped surface of the prefilter (mapped_hull.hpp): its facets' planes, n.r' <= h
// inside with unit outward n, and its inradius rho about the origin (0: not star-shaped, or a
// half-axis without an image). 2-D: 4 edges; 3-D: 8 triangles, one per octant.
//
// One image can be the extreme of two half-axes (a particle at a surface: its in-plane
// neighbour with the lowest image z is also the one farthest along x). The facets with a
// repeated corner are then segments or points: the surface is the octahedron (diamond) with
// that edge contracted, still closed, and the argument holds for the rest of its facets.
// Such a facet has n = 0 and h = +max: no test ever fails on it.
template <int D>
struct StarSurface {
    static constexpr int kFacets = D == 2 ? 4 : 8;
    std::array<Vec<D>, kFacets> n;
    std::array<Eigen::Array<Real, kFacets, 1>, D> n_by_axis; // n by component (deep_inside)
    Eigen::Array<Real, kFacets, 1> h = Eigen::Array<Real, kFacets, 1>::Zero();
    Real rho = 0;
    bool convex = false; // every extreme not on a facet lies below its plane by the drop margin
};

// About `centre` (the images shifted by -centre; the origin for inscribed_ball_radius).
template <int D>
StarSurface<D> star_surface(std::span<const Vec<D>> images, const std::array<int, 2 * D>& ext,
                            const Vec<D>& centre) {
    StarSurface<D> s;
    std::array<Vec<D>, 2 * D> e;
    std::array<Real, 2 * D> len; // |e[k]|, once: every facet's orientation margin uses them
    for (std::size_t k = 0; k < e.size(); ++k) {
        if (ext[k] < 0)
            return s;
        e[k] = images[static_cast<std::size_t>(ext[k])] - centre;
        len[k] = e[k].norm();
    }
    // Corners of each facet, as indices into e.
    std::array<std::array<int, D>, StarSurface<D>::kFacets> corners;
    const auto same = [&](int j, int k) {
        return ext[static_cast<std::size_t>(j)] == ext[static_cast<std::size_t>(k)];
    };
    const auto degenerate = [&](const std::array<int, D>& c) {
        if constexpr (D == 2)
            return same(c[0], c[1]);
        else
            return same(c[0], c[1]) || same(c[0], c[2]) || same(c[1], c[2]);
    };
    Real rho = std::numeric_limits<Real>::max();
    if constexpr (D == 2) {
        // Edges (+x, +y), (+y, -x), (-x, -y), (-y, +x): counter-clockwise about the origin.
        corners = {{{0, 2}, {2, 1}, {1, 3}, {3, 0}}};
        for (std::size_t t = 0; t < 4; ++t) {
            if (degenerate(corners[t])) {
                s.n[t] = Vec<2>::Zero();
                s.h[static_cast<Eigen::Index>(t)] = std::numeric_limits<Real>::max();
                continue;
            }
            const Vec<2>& a = e[static_cast<std::size_t>(corners[t][0])];
            const Vec<2>& b = e[static_cast<std::size_t>(corners[t][1])];
            const Real cross = a.x() * b.y() - a.y() * b.x();
            if (!(cross > kOrientationMargin * len[static_cast<std::size_t>(corners[t][0])] *
                              len[static_cast<std::size_t>(corners[t][1])]))
                return s;
            const Vec<2> edge = b - a;
            const Real length = edge.norm();
            s.h[static_cast<Eigen::Index>(t)] = cross / length;
            s.n[t] = Vec<2>(edge.y(), -edge.x()) / length; // right of a -> b: outward
            rho = std::min(rho, s.h[static_cast<Eigen::Index>(t)]);
        }
    } else {
        // Octant (sx, sy, sz): the triangle of the extremes along sx x, sy y, sz z, whose
        // determinant has the sign sx sy sz on the regular octahedron.
        for (int o = 0; o < 8; ++o) {
            const int sx = o & 1, sy = (o >> 1) & 1, sz = (o >> 2) & 1;
            const auto t = static_cast<std::size_t>(o);
            corners[t] = {sx, 2 + sy, 4 + sz};
            if (degenerate(corners[t])) {
                s.n[t] = Vec<3>::Zero();
                s.h[static_cast<Eigen::Index>(t)] = std::numeric_limits<Real>::max();
                continue;
            }
            const Vec<3>& a = e[static_cast<std::size_t>(sx)];
            const Vec<3>& b = e[static_cast<std::size_t>(2 + sy)];
            const Vec<3>& c = e[static_cast<std::size_t>(4 + sz)];
            const Real sign = ((sx + sy + sz) & 1) != 0 ? Real(-1) : Real(1);
            const Real det = sign * a.dot(b.cross(c));
            if (!(det > kOrientationMargin * len[static_cast<std::size_t>(sx)] *
                            len[static_cast<std::size_t>(2 + sy)] *
                            len[static_cast<std::size_t>(4 + sz)]))
                return s;
            const Vec<3> m = (b - a).cross(c - a);
            const Real area2 = m.norm();
            s.h[static_cast<Eigen::Index>(t)] = det / area2;
            s.n[t] = sign * m / area2;
            rho = std::min(rho, s.h[static_cast<Eigen::Index>(t)]);
        }
    }
    if (rho == std::numeric_limits<Real>::max())
        return s; // every facet degenerate (cannot happen with distinct half-axes; guard)
    s.rho = rho;
    // Convex when every extreme off a facet (not the image of one of its corners) lies
    // clearly below its plane (each edge's other triangle turns down): the surface then
    // bounds conv(e), which lies inside the hull.
    // A facet's corners are one extreme per axis; the others are their opposites (c ^ 1).
    s.convex = true;
    for (std::size_t t = 0; t < s.n.size() && s.convex; ++t) {
        if (degenerate(corners[t]))
            continue;
        for (const int c : corners[t]) {
            const int k = c ^ 1;
            if (std::none_of(corners[t].begin(), corners[t].end(),
                             [&](int o) { return same(o, k); }) &&
                !(s.n[t].dot(e[static_cast<std::size_t>(k)]) - s.h[static_cast<Eigen::Index>(t)] <
                  -kDropMargin * rho))
                s.convex = false;
        }
    }
    for (std::size_t t = 0; t < s.n.size(); ++t)
        for (int a = 0; a < D; ++a)
            s.n_by_axis[static_cast<std::size_t>(a)][static_cast<Eigen::Index>(t)] = s.n[t][a];
    return s;
}

} // namespace

template <int D>
Real inscribed_ball_radius(std::span<const Vec<D>> images) {
    return star_surface<D>(images, extreme_images<D>(images).e, Vec<D>::Zero()).rho;
}

namespace {

// The hull of h.images (already mapped), see mapped_hull_into.
template <int D>
void hull_of_images(Extremes<D> extremes, HullPrefilter prefilter, bool with_boundary,
                    MappedHullWork<D>& work, MappedHull<D>& h) {
    h.vertices.clear();
    h.boundary.clear();
    h.facets.clear();
    const std::array<int, 2 * D>& ext = extremes.e;
    // sqrt is monotone: the largest norm is the root of the largest square
    h.size = std::sqrt(extremes.size2);
    const Real tol = kMappedHullTolerance * h.size;
    // The images the hull is computed on (all, or those the prefilter keeps) and their
    // indices; `dropped` marks the others, which are neither corners nor boundary points.
    std::vector<Vec<D>>& kept_images = work.kept_images;
    std::vector<int>& kept = work.kept;
    std::vector<char>& dropped = work.dropped;
    kept_images.clear();
    kept.clear();
    dropped.assign(h.images.size(), 0);
    std::vector<int>& position = work.position; // 3-D only
    if constexpr (D == 3)
        position.resize(h.images.size());
    std::span<const Vec<D>> hull_input(h.images);
    // 3-D: the extremes' octahedron as quickhull's first hull, as indices into hull_input,
    // when the prefilter proved it convex (quickhull_3d.hpp).
    std::array<int, 2 * D> octahedron{};
    bool have_octahedron = false;
    if (prefilter == HullPrefilter::inscribed_ball) {
        StarSurface<D> star = star_surface<D>(h.images, ext, Vec<D>::Zero());
        // A particle at a free surface or wall has its images on one side of the origin: the
        // surface is not star-shaped about it, or barely (rho tiny), and nothing was dropped
        // (quickhull then got ~67 images, not ~21: a quarter of the bench's 3-D particles).
        // The argument holds about any point, so try the extremes' centroid (inside their
        // hull) instead. Interior particles keep the origin: q - 0 is
        // q exactly, so their drop decisions are unchanged.
        Vec<D> centre = Vec<D>::Zero();
        if (!(star.rho > 0 && kDropMargin * star.rho > 1e3 * tol) &&
            std::all_of(ext.begin(), ext.end(), [](int k) { return k >= 0; })) {
            for (const int k : ext)
                centre += h.images[static_cast<std::size_t>(k)];
            centre /= Real(2 * D);
            star = star_surface<D>(h.images, ext, centre);
        }
        const Real rho = star.rho;
        const Real margin = kDropMargin * rho;
        const Real drop = (1 - kDropMargin) * rho;
        // Inside conv(e) by more than the margin (convex surface only): below every facet
        // plane by the margin. All 8 (4) planes at once as vector lanes, the same sums as
        // n.dot(q) - h; the largest excess decides (no early exit, whose branch would
        // mispredict).
        const auto deep_inside = [&](const Vec<D>& q) {
            if (!star.convex)
                return false;
            if constexpr (D == 2)
                return ((star.n_by_axis[0] * q[0] + star.n_by_axis[1] * q[1]) - star.h).maxCoeff() <
                       -margin;
            else
                return ((star.n_by_axis[0] * q[0] + star.n_by_axis[1] * q[1] +
                         star.n_by_axis[2] * q[2]) -
                        star.h)
                           .maxCoeff() < -margin;
        };
        // The margin left inside every facet must dwarf the boundary tolerance.
        if (rho > 0 && margin > 1e3 * tol) {
            // Without a branch on the outcome (random: about half the images go either way):
            // both tests always, the kept index and image always written at the end of the
            // kept list, which only grows when the image is kept.
            const std::size_t count = h.images.size();
            kept.resize(count);
            kept_images.resize(count);
            std::size_t n = 0;
            for (std::size_t i = 0; i < count; ++i) {
                const Vec<D> q = h.images[i] - centre;
                const bool drop_it = (q.squaredNorm() < drop * drop) | deep_inside(q);
                dropped[i] = static_cast<char>(drop_it);
                if constexpr (D == 3)
                    position[i] = static_cast<int>(n);
                kept[n] = static_cast<int>(i);
                kept_images[n] = h.images[i];
                n += drop_it ? 0 : 1;
            }
            kept.resize(n);
            kept_images.resize(n);
            hull_input = kept_images;
            // Convex with six distinct corners (a repeated one leaves a contracted surface).
            // (Extremes are never dropped: each lies on a facet of the surface, outside the
            // ball; `position` is checked all the same.)
            if constexpr (D == 3) {
                have_octahedron = star.convex;
                for (std::size_t k = 0; k < ext.size(); ++k) {
                    const auto i = static_cast<std::size_t>(ext[k]);
                    octahedron[k] = position[i];
                    have_octahedron = have_octahedron && dropped[i] == 0;
                    for (std::size_t j = 0; j < k; ++j)
                        have_octahedron = have_octahedron && ext[j] != ext[k];
                }
            }
        }
    }
    const bool filtered = hull_input.data() != h.images.data();
    const auto original = [&](std::vector<int>& idx) {
        if (filtered)
            for (int& k : idx)
                k = kept[static_cast<std::size_t>(k)];
    };
    // Each corner's image lies on a facet the hull knows (an edge it starts; a live facet
    // quickhull recorded for it): the boundary test tries that facet first.
    std::vector<int>& on_facet = work.on_facet;
    on_facet.resize(h.images.size());
    const auto mark_corner = [&](int i, int facet) {
        dropped[static_cast<std::size_t>(i)] = 2;
        on_facet[static_cast<std::size_t>(i)] = facet;
    };
    if constexpr (D == 2) {
        std::vector<int>& corners = work.corners;
        quadrant_hull_2d_into(hull_input, HullPoints::vertices, work.quadrant, corners);
        hull_edges_2d_into(hull_input, corners, h.facets);
        original(corners);
        if (with_boundary && !h.facets.empty()) // edge k runs from corner k to k + 1
            for (std::size_t k = 0; k < corners.size(); ++k)
                mark_corner(corners[k], static_cast<int>(k));
        h.vertices.assign(corners.begin(), corners.end());
        std::sort(h.vertices.begin(), h.vertices.end());
        if (h.facets.empty()) {
            // Fewer than 3 corners: a point or a segment; its edge points come exactly.
            if (with_boundary) {
                quadrant_hull_2d_into(hull_input, HullPoints::boundary, work.quadrant, h.boundary);
                original(h.boundary);
                std::sort(h.boundary.begin(), h.boundary.end());
            }
            return;
        }
    } else {
        ConvexHull3d& v = work.hull_3d;
        convex_hull_3d_into(hull_input, HullPoints::vertices, work.quickhull, v,
                            have_octahedron ? &octahedron : nullptr);
        if (with_boundary && !v.facets.empty()) // the last quickhull run made them
            for (const int c : v.points) {
                const int f = work.quickhull.incident[static_cast<std::size_t>(c)];
                mark_corner(filtered ? kept[static_cast<std::size_t>(c)] : c,
                            f < 0 ? -1 : work.quickhull.output[static_cast<std::size_t>(f)]);
            }
        original(v.points);
        h.vertices.assign(v.points.begin(), v.points.end());
        h.facets.assign(v.facets.begin(), v.facets.end());
        if (h.facets.empty()) {
            if (with_boundary) {
                convex_hull_3d_into(hull_input, HullPoints::boundary, work.quickhull, v);
                original(v.points);
                h.boundary.assign(v.points.begin(), v.points.end());
            }
            return;
        }
    }
    if (!with_boundary)
        return;
    // Points within the tolerance of a facet join the corners. Duplicates of a corner (same
    // image) are on the boundary too. An image nearer the origin than every facet's plane by
    // more than the tolerance (|r'| < min(-d) - 2 tol: n.r' + d <= |r'| + d < -tol, with a
    // tolerance's margin for rounding) is on none; the test skips it.
    Real inner = std::numeric_limits<Real>::max();
    for (const auto& f : h.facets)
        inner = std::min(inner, -f[D]);
    const Real skip = inner - 2 * tol;
    const Real skip2 = skip > 0 ? skip * skip : Real(-1);
    // Whether some facet holds the image: the same answer whichever facet is tried first, so
    // all are tried at once, as vector lanes over the facets by component (an
    // image inside the hull scans every facet), with the sums of
    // f.head(D).dot(q) + f[D]; the largest of them decides.
    std::array<Eigen::Array<Real, Eigen::Dynamic, 1>, D + 1>& by_axis = work.facet_components;
    const auto facet_count = static_cast<Eigen::Index>(h.facets.size());
    for (int a = 0; a <= D; ++a) {
        auto& c = by_axis[static_cast<std::size_t>(a)];
        c.resize(facet_count);
        for (Eigen::Index k = 0; k < facet_count; ++k)
            c[k] = h.facets[static_cast<std::size_t>(k)][a];
    }
    const auto on_a_facet = [&](const Vec<D>& q) {
        if constexpr (D == 2)
            return ((by_axis[0] * q[0] + by_axis[1] * q[1]) + by_axis[2]).maxCoeff() > -tol;
        else
            return ((by_axis[0] * q[0] + by_axis[1] * q[1] + by_axis[2] * q[2]) + by_axis[3])
                       .maxCoeff() > -tol;
    };
    const auto test = [&](std::size_t i) {
        if (h.images[i].squaredNorm() < skip2)
            return;
        const Vec<D>& q = h.images[i];
        bool on = false;
        if (dropped[i] == 2 && on_facet[i] >= 0) {
            const auto& f = h.facets[static_cast<std::size_t>(on_facet[i])];
            on = f.template head<D>().dot(q) + f[D] > -tol;
        }
        if (on || on_a_facet(q))
            h.boundary.push_back(static_cast<int>(i));
    };
    // Only the images the prefilter kept can be on a facet (`kept` ascending, as the output);
    // without the prefilter, every image.
    if (filtered) {
        for (const int i : kept)
            test(static_cast<std::size_t>(i));
    } else {
        for (std::size_t i = 0; i < h.images.size(); ++i)
            test(i);
    }
}

} // namespace

template <int D>
void mapped_hull_into(std::span<const Vec<D>> offsets, HullPrefilter prefilter,
                      MappedHullWork<D>& work, MappedHull<D>& h, bool with_boundary) {
    h.images.clear();
    for (const auto& r : offsets)
        h.images.push_back(inverse_square_map<D>(r));
    hull_of_images<D>(extreme_images<D>(h.images), prefilter, with_boundary, work, h);
}

template <int D>
void mapped_hull_within_into(std::span<const Vec<D>> offsets, Real radius2, HullPrefilter prefilter,
                             MappedHullWork<D>& work, MappedHull<D>& h, std::vector<int>& candidate,
                             bool with_boundary) {
    // One pass: the candidates, their images and the images' extremes.
    // Written through pointers into buffers sized for every offset, then cut to the count
    // (no capacity check per candidate).
    candidate.resize(offsets.size());
    h.images.resize(offsets.size());
    int* const cand = candidate.data();
    Vec<D>* const image = h.images.data();
    int n = 0;
    Extremes<D> found;
    Real size2 = 0; // a scalar of its own: the one chain from image to image
    for (std::size_t j = 0; j < offsets.size(); ++j) {
        const Real r2 = offsets[j].squaredNorm();
        if (r2 > 0 && r2 <= radius2) {
            const Vec<D> q = inverse_square_map<D>(offsets[j]);
            size2 = std::max(size2, q.squaredNorm());
            found.add_directions(q, n);
            image[n] = q;
            cand[n] = static_cast<int>(j);
            ++n;
        }
    }
    candidate.resize(static_cast<std::size_t>(n));
    h.images.resize(static_cast<std::size_t>(n));
    found.size2 = size2;
    hull_of_images<D>(found, prefilter, with_boundary, work, h);
}

template <int D>
MappedHull<D> mapped_hull(std::span<const Vec<D>> offsets, HullPrefilter prefilter) {
    MappedHull<D> h;
    MappedHullWork<D> work;
    mapped_hull_into<D>(offsets, prefilter, work, h);
    return h;
}

template <int D>
bool hull_surrounds_origin(const MappedHull<D>& hull) {
    if (hull.facets.empty())
        return false;
    const Real tol = kMappedHullTolerance * hull.size;
    return std::all_of(hull.facets.begin(), hull.facets.end(),
                       [&](const auto& f) { return f[D] < -tol; });
}

template MappedHull<2> mapped_hull<2>(std::span<const Vec<2>>, HullPrefilter);
template MappedHull<3> mapped_hull<3>(std::span<const Vec<3>>, HullPrefilter);
template void mapped_hull_into<2>(std::span<const Vec<2>>, HullPrefilter, MappedHullWork<2>&,
                                  MappedHull<2>&, bool);
template void mapped_hull_into<3>(std::span<const Vec<3>>, HullPrefilter, MappedHullWork<3>&,
                                  MappedHull<3>&, bool);
template void mapped_hull_within_into<2>(std::span<const Vec<2>>, Real, HullPrefilter,
                                         MappedHullWork<2>&, MappedHull<2>&, std::vector<int>&,
                                         bool);
template void mapped_hull_within_into<3>(std::span<const Vec<3>>, Real, HullPrefilter,
                                         MappedHullWork<3>&, MappedHull<3>&, std::vector<int>&,
                                         bool);
template Real inscribed_ball_radius<2>(std::span<const Vec<2>>);
template Real inscribed_ball_radius<3>(std::span<const Vec<3>>);
template bool hull_surrounds_origin<2>(const MappedHull<2>&);
template bool hull_surrounds_origin<3>(const MappedHull<3>&);

} // namespace sluice
