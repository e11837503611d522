// 3-D convex hull: the exact quickhull, degenerate sets by their dimension; see convex_hull_3d.hpp.
#include "sluice/physics/convex_hull_3d.hpp"

#include "sluice/physics/quickhull_3d.hpp"

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace sluice {
namespace {

constexpr Real kRankTolerance = Real(1e-10);    // singular value / largest one below this: flat
constexpr Real kBoundaryTolerance = Real(1e-9); // distance to a facet / set size: on the facet

std::vector<int> distinct_points(std::span<const Vec<3>> p) {
    std::vector<int> idx(p.size());
    std::iota(idx.begin(), idx.end(), 0);
    const auto key = [&](int i) {
        const auto& q = p[static_cast<std::size_t>(i)];
        return std::array<Real, 3>{q.x(), q.y(), q.z()};
    };
    std::sort(idx.begin(), idx.end(),
              [&](int a, int b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
    idx.erase(std::unique(idx.begin(), idx.end(), [&](int a, int b) { return key(a) == key(b); }),
              idx.end());
    return idx;
}

// Adds to the corners the distinct points within kBoundaryTolerance of the set's size (largest
// distance from the centroid) of a facet.
void add_facet_points(std::span<const Vec<3>> points, const std::vector<int>& idx,
                      ConvexHull3d& hull) {
    const auto at = [&](int i) -> const Vec<3>& { return points[static_cast<std::size_t>(i)]; };
    Vec<3> centre = Vec<3>::Zero();
    for (int i : idx)
        centre += at(i);
    centre /= static_cast<Real>(idx.size());
    Real size = 0;
    for (int i : idx)
        size = std::max(size, (at(i) - centre).norm());
    const Real tol = kBoundaryTolerance * size;
    std::vector<char> in(points.size(), 0);
    for (int i : hull.points)
        in[static_cast<std::size_t>(i)] = 1;
    for (int i : idx) {
        if (in[static_cast<std::size_t>(i)] != 0)
            continue;
        for (const auto& f : hull.facets)
            if (f.head<3>().dot(at(i)) + f[3] > -tol) {
                hull.points.push_back(i);
                break;
            }
    }
}

// A first tetrahedron with more than this volume proves what the singular values below would
// say, dimension 3: it is at least V / D^2 wide in every direction (D: the set's diameter,
// at most 2 max |p|), so sigma_3 >= V / (sqrt(2) D^2), while sigma_1 <= sqrt(n) D; the
// factor 100 covers the rounding of both.
Real clearly_3d_volume(std::span<const Vec<3>> points) {
    Real size2 = 0;
    for (const auto& q : points)
        size2 = std::max(size2, q.squaredNorm());
    const Real size = std::sqrt(size2);
    const Real diameter = 2 * size;
    return 100 * kRankTolerance * std::sqrt(static_cast<Real>(points.size())) * std::sqrt(Real(2)) *
           diameter * diameter * diameter;
}

} // namespace

void convex_hull_3d_into(std::span<const Vec<3>> points, HullPoints which, QuickhullWork& work,
                         ConvexHull3d& hull, const std::array<int, 6>* octahedron) {
    hull.points.clear();
    hull.facets.clear();
    hull.dimension = -1;
    // The usual case: a solid set, its hull without sorting or decomposing it.
    if (points.size() >= 4 && quickhull_3d(points, clearly_3d_volume(points), work, hull.points,
                                           hull.facets, octahedron)) {
        hull.dimension = 3;
        // quickhull_3d's corners ascend already; the facet points need a sort.
        if (which == HullPoints::boundary) {
            add_facet_points(points, distinct_points(points), hull);
            std::sort(hull.points.begin(), hull.points.end());
        }
        return;
    }
    const std::vector<int> idx = distinct_points(points);
    if (idx.empty())
        return;
    const auto at = [&](int i) -> const Vec<3>& { return points[static_cast<std::size_t>(i)]; };

    Vec<3> centre = Vec<3>::Zero();
    for (int i : idx)
        centre += at(i);
    centre /= static_cast<Real>(idx.size());
    // At least 3 rows (zero rows change nothing) so that there are 3 singular values.
    Eigen::Matrix<Real, Eigen::Dynamic, 3> centred =
        Eigen::Matrix<Real, Eigen::Dynamic, 3>::Zero(std::max<Eigen::Index>(3, std::ssize(idx)), 3);
    for (std::size_t k = 0; k < idx.size(); ++k)
        centred.row(static_cast<Eigen::Index>(k)) = (at(idx[k]) - centre).transpose();
    const Eigen::JacobiSVD<Eigen::Matrix<Real, Eigen::Dynamic, 3>> svd(centred,
                                                                       Eigen::ComputeFullV);
    const Vec<3> sigma = svd.singularValues();
    hull.dimension = 0;
    for (int a = 0; a < 3; ++a)
        if (sigma[a] > kRankTolerance * sigma[0])
            hull.dimension = a + 1;

    if (hull.dimension <= 1) {
        // A point or a segment: its end points along the principal direction, or all points.
        const Vec<3> u = svd.matrixV().col(0);
        const auto along = [&](int i) { return u.dot(at(i)); };
        if (which == HullPoints::boundary || hull.dimension == 0) {
            hull.points = idx;
        } else {
            const auto [lo, hi] = std::minmax_element(
                idx.begin(), idx.end(), [&](int a, int b) { return along(a) < along(b); });
            hull.points = {*lo, *hi};
        }
    } else if (hull.dimension == 2) {
        // A flat set has no interior: every point is on its boundary. Its corners: drop the
        // coordinate along which the plane's normal points most, an exact affine projection,
        // so the 2-D hull of the images is the hull of the plane's points.
        if (which == HullPoints::boundary) {
            hull.points = idx;
        } else {
            const Vec<3> normal = svd.matrixV().col(2);
            int drop = 0;
            normal.cwiseAbs().maxCoeff(&drop);
            const int u = (drop + 1) % 3;
            const int v = (drop + 2) % 3;
            std::vector<Vec<2>> flat;
            flat.reserve(idx.size());
            for (int i : idx)
                flat.emplace_back(at(i)[u], at(i)[v]);
            for (int k : monotone_chain_hull_2d(flat, HullPoints::vertices))
                hull.points.push_back(idx[static_cast<std::size_t>(k)]);
        }
    } else {
        // Thin but solid (the first tetrahedron was too flat to prove it): any positive volume.
        if (!quickhull_3d(points, 0, work, hull.points, hull.facets)) {
            hull.points = idx; // unreachable: sigma_3 > 0 means four points off one plane
        } else if (which == HullPoints::boundary) {
            add_facet_points(points, idx, hull);
        }
    }
    std::sort(hull.points.begin(), hull.points.end());
}

ConvexHull3d convex_hull_3d(std::span<const Vec<3>> points, HullPoints which) {
    ConvexHull3d hull;
    QuickhullWork work;
    convex_hull_3d_into(points, which, work, hull);
    return hull;
}

} // namespace sluice
