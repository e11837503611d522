// 3-D convex hull through Qhull's reentrant C library; see convex_hull_3d.hpp.
#include "sluice/physics/convex_hull_3d.hpp"

#include <Eigen/SVD>

extern "C" {
#include <libqhull_r/libqhull_r.h>
}

#include <algorithm>
#include <array>
#include <cstdio>
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

// Qhull's messages on precision trouble go nowhere: the caller gets the exit code.
std::FILE* quiet_stream() {
    static std::FILE* f = std::fopen("/dev/null", "w");
    return f;
}

// One Qhull instance per thread, reused from call to call (issue 22): qh_freeqhull(!qh_ALL)
// keeps Qhull's short-memory pools, so a call after the first skips their set-up and most of
// its allocations. Calls in different threads never share it.
class QhullInstance {
public:
    QhullInstance() { qh_zero(&qh_, quiet_stream()); }
    ~QhullInstance() { release(); }
    // After a refused input Qhull's state is not trusted again: everything goes, a fresh one
    // starts.
    void reset() {
        release();
        qh_zero(&qh_, quiet_stream());
    }
    QhullInstance(const QhullInstance&) = delete;
    QhullInstance& operator=(const QhullInstance&) = delete;
    qhT* get() { return &qh_; }

private:
    void release() {
        qh_freeqhull(&qh_, qh_ALL);
        int still_long = 0;
        int total_long = 0;
        qh_memfreeshort(&qh_, &still_long, &total_long);
    }
    qhT qh_{};
};

// Runs Qhull on the distinct points; false when it refuses them.
bool run_qhull(std::span<const Vec<3>> p, const std::vector<int>& idx, const char* options,
               ConvexHull3d& out) {
    thread_local std::vector<coordT> coords;
    coords.clear();
    for (int i : idx)
        for (int a = 0; a < 3; ++a)
            coords.push_back(p[static_cast<std::size_t>(i)][a]);
    thread_local QhullInstance instance;
    qhT* qh = instance.get();
    std::array<char, 64> command{};
    std::snprintf(command.data(), command.size(), "qhull %s", options);
    const int exit_code = qh_new_qhull(qh, 3, static_cast<int>(idx.size()), coords.data(), False,
                                       command.data(), nullptr, quiet_stream());
    if (exit_code == 0) {
        vertexT* vertex = nullptr;
        FORALLvertices {
            out.points.push_back(idx[static_cast<std::size_t>(qh_pointid(qh, vertex->point))]);
        }
        facetT* facet = nullptr;
        FORALLfacets {
            out.facets.emplace_back(facet->normal[0], facet->normal[1], facet->normal[2],
                                    facet->offset);
        }
    }
    // The hull's memory goes back to the pools, which stay for the next call.
    qh_freeqhull(qh, !qh_ALL);
    if (exit_code != 0)
        instance.reset();
    return exit_code == 0;
}

} // namespace

ConvexHull3d convex_hull_3d(std::span<const Vec<3>> points, HullPoints which) {
    ConvexHull3d hull;
    const std::vector<int> idx = distinct_points(points);
    if (idx.empty())
        return hull;
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
        if (!run_qhull(points, idx, "", hull)) {
            // Nearly flat sets can still trouble Qhull's precision checks: joggle the input
            // (deterministic seed) rather than fail.
            hull.points.clear();
            hull.facets.clear();
            run_qhull(points, idx, "QJ", hull);
        }
        if (which == HullPoints::boundary) {
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
    }
    std::sort(hull.points.begin(), hull.points.end());
    return hull;
}

} // namespace sluice
