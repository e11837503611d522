// Wall layers and fluid sites of a shape (shape_particles.hpp).
#include "sluice/geometry/shape_particles.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace sluice {

namespace {

// Lattice index range [k0, k1) per axis whose sites cover [lo - margin, hi + margin].
struct IndexBox {
    std::array<std::int64_t, 3> k0{0, 0, 0}, k1{1, 1, 1};
};

IndexBox index_box(const Point3& lo, const Point3& hi, double margin, const LatticeSpec& l) {
    IndexBox b;
    for (std::size_t a = 0; a < static_cast<std::size_t>(l.dimension); ++a) {
        b.k0[a] =
            static_cast<std::int64_t>(std::floor((lo[a] - margin - l.origin[a]) / l.dx - 0.5));
        b.k1[a] =
            static_cast<std::int64_t>(std::ceil((hi[a] + margin - l.origin[a]) / l.dx - 0.5)) + 1;
    }
    return b;
}

constexpr std::int64_t kTile = 16;

// Calls f(site position) for every site of the index box, tile by tile, skipping tiles that
// `keep_tile(centre, half_diagonal)` rejects.
template <class Keep, class F>
void for_each_site_in_tiles(const IndexBox& b, const LatticeSpec& l, Keep&& keep_tile, F&& f) {
    const int D = l.dimension;
    std::array<std::int64_t, 3> tiles{1, 1, 1};
    for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a)
        tiles[a] = (b.k1[a] - b.k0[a] + kTile - 1) / kTile;
    const double half_diagonal = 0.5 * kTile * l.dx * std::sqrt(double(D));
    for (std::int64_t tz = 0; tz < tiles[2]; ++tz)
        for (std::int64_t ty = 0; ty < tiles[1]; ++ty)
            for (std::int64_t tx = 0; tx < tiles[0]; ++tx) {
                const std::array<std::int64_t, 3> t{tx, ty, tz};
                std::array<std::int64_t, 3> s0{}, s1{};
                Point3 centre{};
                for (std::size_t a = 0; a < 3; ++a) {
                    if (a >= static_cast<std::size_t>(D)) {
                        s0[a] = 0;
                        s1[a] = 1;
                        continue;
                    }
                    s0[a] = b.k0[a] + t[a] * kTile;
                    s1[a] = std::min(b.k1[a], s0[a] + kTile);
                    centre[a] = l.origin[a] + 0.5 * double(s0[a] + s1[a]) * l.dx;
                }
                if (!keep_tile(centre, half_diagonal))
                    continue;
                for (std::int64_t kz = s0[2]; kz < s1[2]; ++kz)
                    for (std::int64_t ky = s0[1]; ky < s1[1]; ++ky)
                        for (std::int64_t kx = s0[0]; kx < s1[0]; ++kx) {
                            const std::array<std::int64_t, 3> k{kx, ky, kz};
                            Point3 x{};
                            for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a)
                                x[a] = l.origin[a] + (double(k[a]) + 0.5) * l.dx;
                            f(x);
                        }
            }
}

} // namespace

void visit_wall_sites(const SurfaceIndex& shape, ShapeRole role, const LatticeSpec& l, int layers,
                      const std::function<void(const WallSite&)>& f) {
    if (role == ShapeRole::solid && !shape.closed())
        throw GeometryError("a solid needs a closed shape");
    const double depth_max = layers * l.dx;
    const double margin = role == ShapeRole::solid ? 0.0 : depth_max;
    const IndexBox box = index_box(shape.lo(), shape.hi(), margin, l);
    const double tol = 1e-9 * l.dx;
    for_each_site_in_tiles(
        box, l,
        [&](const Point3& c, double r) {
            const double reach = r + depth_max;
            return shape.squared_distance(c) < reach * reach;
        },
        [&](const Point3& x) {
            const ClosestPoint c = shape.closest(x);
            if (c.distance >= depth_max - tol)
                return;
            if (role == ShapeRole::solid) {
                if (!shape.inside(x))
                    return;
            } else if (!(c.side < -1e-6)) {
                return; // in front of the surface, on it, or beside an open edge
            }
            WallSite w;
            w.layer = std::min(layers - 1, static_cast<int>(std::floor((c.distance + tol) / l.dx)));
            w.depth = (w.layer + 0.5) * l.dx;
            w.normal = c.normal;
            if (std::abs(c.distance - w.depth) <= tol) {
                w.x = x;
            } else if (c.distance > tol) {
                const double s = w.depth / c.distance;
                for (std::size_t a = 0; a < 3; ++a)
                    w.x[a] = c.point[a] + (x[a] - c.point[a]) * s;
            } else { // on the surface: straight behind it
                for (std::size_t a = 0; a < 3; ++a)
                    w.x[a] = c.point[a] - c.normal[a] * w.depth;
            }
            // Moved deeper near a concave edge of the wall (a convex edge of a solid, seen
            // from inside), a site can come nearer another face than its layer's depth: that
            // face's own sites cover the place, and this one would crowd them.
            if (w.x != x && shape.squared_distance(w.x) < (w.depth - tol) * (w.depth - tol))
                return;
            f(w);
        });
}

} // namespace sluice
