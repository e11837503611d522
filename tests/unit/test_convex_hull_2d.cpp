// Lee & Lee's (2011) quadrant + Sklansky hull against Andrew's monotone chain on many random
// and adversarial sets, and both against an independent check of the hull property with the
// exact predicate: every point inside or on the polygon, every corner a strict turn.
#include "sluice/physics/convex_hull_2d.hpp"
#include "sluice/physics/exact_orientation.hpp"
#include "sluice/physics/mapped_hull.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <string>

using namespace sluice;

namespace {

using Points = std::vector<Vec<2>>;

std::vector<int> sorted(std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
}

// Independent check that `hull` (cyclic, turning the way `turn` says: -1 clockwise, +1
// counter-clockwise) is the hull of `p` with the points `which` asks for.
void check_is_hull(const Points& p, const std::vector<int>& hull, int turn, HullPoints which,
                   const std::string& what) {
    INFO(what);
    const std::set<int> unique(hull.begin(), hull.end());
    REQUIRE(unique.size() == hull.size());
    for (int i : hull)
        REQUIRE((i >= 0 && i < static_cast<int>(p.size())));
    // Distinct coordinates in the hull; every point of p equal to a hull point has an index
    // no lower (the lowest index represents the duplicates).
    for (int i : hull)
        for (std::size_t j = 0; j < p.size(); ++j)
            if (p[j] == p[static_cast<std::size_t>(i)])
                REQUIRE(static_cast<int>(j) >= i);
    const std::size_t n = hull.size();
    const auto at = [&](std::size_t k) { return p[static_cast<std::size_t>(hull[k % n])]; };
    if (n >= 3) {
        bool any_turn = false;
        for (std::size_t k = 0; k < n; ++k) {
            const int s = orientation_sign(at(k), at(k + 1), at(k + 2));
            if (which == HullPoints::vertices)
                REQUIRE(s == turn); // a strict corner everywhere
            else
                REQUIRE((s == turn || s == 0));
            any_turn = any_turn || s != 0;
        }
        if (any_turn) { // all points inside or on every edge
            for (const auto& q : p)
                for (std::size_t k = 0; k < n; ++k)
                    REQUIRE(orientation_sign(at(k), at(k + 1), q) != -turn);
        } else { // a collinear set with its edge points: all on that line
            for (const auto& q : p)
                REQUIRE(orientation_sign(at(0), at(1), q) == 0);
        }
    } else if (n == 1) {
        for (const auto& q : p)
            REQUIRE(q == at(0));
    } else {
        // No turn: every point lies on the segment between the (at most two) hull points.
        for (const auto& q : p)
            REQUIRE(orientation_sign(at(0), at(n - 1), q) == 0);
    }
    if (which == HullPoints::boundary && n >= 2) {
        // Every point lying on the boundary is in the hull (by coordinates).
        for (const auto& q : p) {
            bool on_boundary = false;
            const std::size_t edges = n == 2 ? 1 : n;
            for (std::size_t k = 0; k < edges; ++k) {
                const auto a = at(k), b = at(k + 1);
                on_boundary = on_boundary ||
                              (orientation_sign(a, b, q) == 0 && std::min(a.x(), b.x()) <= q.x() &&
                               q.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= q.y() &&
                               q.y() <= std::max(a.y(), b.y()));
            }
            if (on_boundary)
                REQUIRE(std::any_of(hull.begin(), hull.end(),
                                    [&](int i) { return p[static_cast<std::size_t>(i)] == q; }));
        }
    }
}

// Both algorithms, both modes: same sets, and each passes the independent check.
void check_agree(const Points& p, const std::string& what) {
    for (HullPoints which : {HullPoints::vertices, HullPoints::boundary}) {
        const std::string w =
            what + (which == HullPoints::vertices ? " [vertices]" : " [boundary]");
        const auto seed = quadrant_hull_2d(p, which);
        const auto ref = monotone_chain_hull_2d(p, which);
        INFO(w);
        REQUIRE(sorted(seed) == sorted(ref));
        check_is_hull(p, seed, -1, which, w + " quadrant");
        check_is_hull(p, ref, +1, which, w + " monotone chain");
    }
}

} // namespace

TEST_CASE("a literal one-pass Sklansky scan fails; the scan with a step back does not") {
    // (1, 9.5) looks convex until (2, 8.5) is deleted; it lies inside the triangle
    // (0, 10), (10, 8), (11, 0). The same set has coincident extreme points: (11, 0) is both
    // Xmax and Ymin, (0, 10) both Ymax and Xmin (Lee & Lee's repair).
    const Points p = {{0, 10}, {1, 9.5}, {2, 8.5}, {10, 8}, {11, 0}};
    CHECK(quadrant_hull_2d(p) == std::vector<int>{0, 3, 4}); // clockwise from P1
    CHECK(sorted(monotone_chain_hull_2d(p)) == std::vector<int>{0, 3, 4});
    check_agree(p, "step-back example");
}

TEST_CASE("overlapping regions: a point beyond one chord but inside the other") {
    // Lee & Lee's boxes for A and C overlap here (X1 <= X3, Y2 < Y4): (8.9, 8.9) is in both.
    // It is a hull vertex on A's side only.
    const Points p = {{0, 10}, {10, 1}, {9, 0}, {-1, 9}, {8.9, 8.9}, {5, 5}};
    CHECK(quadrant_hull_2d(p) == std::vector<int>{0, 4, 1, 2, 3});
    check_agree(p, "A and C overlap");
    // P1 = P2 and P3 = P4: the boxes of B and D are the same; (1, 0) belongs to B only.
    const Points q = {{2, 2}, {-2, -1}, {1, 0}};
    CHECK(quadrant_hull_2d(q) == std::vector<int>{0, 2, 1});
    check_agree(q, "B and D overlap");
}

TEST_CASE("coincident extreme points (Lee & Lee's repair)") {
    // P1 == P2: the top-right point is both the highest and the rightmost.
    const Points a = {{2, 2}, {0, 1}, {1, 0}, {0.5, 0.5}, {-1, -1}};
    CHECK(quadrant_hull_2d(a) == std::vector<int>{0, 2, 4, 1}); // P1 = P2 = (2, 2), P3 = P4
    // All four extreme points distinct except P2 == P3 (bottom-right corner).
    const Points b = {{0, 3}, {3, -3}, {-3, 0}, {0, 0}, {1, -1}};
    CHECK(sorted(quadrant_hull_2d(b)) == std::vector<int>{0, 1, 2});
    check_agree(a, "P1 == P2");
    check_agree(b, "P2 == P3");
    // One point, two points, a point repeated: all extreme points coincide.
    check_agree({{1, 2}}, "one point");
    check_agree({{1, 2}, {1, 2}, {1, 2}}, "one point thrice");
    CHECK(quadrant_hull_2d(Points{{1, 2}, {1, 2}}) == std::vector<int>{0});
    check_agree({{0, 0}, {1, 1}}, "two points");
    CHECK(quadrant_hull_2d(Points{{0, 0}, {1, 1}}) == std::vector<int>{1, 0});
}

TEST_CASE("collinear sets: end points as vertices, every point as boundary") {
    const Points line = {{3, 3}, {0, 0}, {1, 1}, {2, 2}, {1, 1}};
    CHECK(sorted(quadrant_hull_2d(line)) == std::vector<int>{0, 1});
    CHECK(sorted(quadrant_hull_2d(line, HullPoints::boundary)) == std::vector<int>{0, 1, 2, 3});
    check_agree(line, "diagonal line");
    check_agree({{0, 5}, {0, 1}, {0, 3}}, "vertical line");
    check_agree({{4, 1}, {-2, 1}, {1, 1}, {0, 1}}, "horizontal line");
    // A square with points on every edge.
    const Points square = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {1, 1}};
    CHECK(sorted(quadrant_hull_2d(square)) == std::vector<int>{0, 2, 4, 6});
    CHECK(sorted(quadrant_hull_2d(square, HullPoints::boundary)) ==
          std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7});
    check_agree(square, "square with edge points");
}

TEST_CASE("three points in every arrangement") {
    std::mt19937 rng(7);
    std::uniform_int_distribution<int> c(-2, 2);
    for (int t = 0; t < 3000; ++t) {
        Points p(3);
        for (auto& q : p)
            q = Vec<2>(c(rng), c(rng)); // small integers: many collinear and equal triples
        check_agree(p, "3 small-integer points #" + std::to_string(t));
    }
}

TEST_CASE("random and adversarial sets agree") {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> size(3, 60);
    std::uniform_int_distribution<int> grid(-4, 4);
    int sets = 0;
    for (int t = 0; t < 400; ++t) {
        const int n = size(rng);
        Points uniform, lattice, dup, circle, near_line, corner, images;
        for (int i = 0; i < n; ++i) {
            uniform.emplace_back(u(rng), u(rng));
            lattice.emplace_back(grid(rng), grid(rng)); // collinear runs and duplicates
            const double a = 2 * std::numbers::pi * i / n;
            circle.emplace_back(std::cos(a), std::sin(a)); // rounding makes near-collinear triples
            // On y = 0.3 x + 0.1 up to one or two units in the last place.
            const double x = u(rng);
            near_line.emplace_back(x, std::nextafter(0.3 * x + 0.1, u(rng) > 0 ? 2.0 : -2.0));
            // The inverse-square images of a jittered lattice neighbourhood (the real use).
            const Vec<2> r(grid(rng) + 0.01 * u(rng), grid(rng) + 0.01 * u(rng));
            if (r.squaredNorm() > 0)
                images.push_back(inverse_square_map<2>(r));
        }
        dup = uniform;
        for (int i = 0; i < n / 2; ++i)
            dup.push_back(uniform[static_cast<std::size_t>(i * 7 % n)]);
        std::shuffle(dup.begin(), dup.end(), rng);
        // A corner point that is two extreme points at once, in each of the four corners.
        corner = uniform;
        corner.emplace_back(t % 4 < 2 ? 2 : -2, t % 2 == 0 ? 2 : -2);
        check_agree(uniform, "uniform #" + std::to_string(t));
        check_agree(lattice, "lattice #" + std::to_string(t));
        check_agree(dup, "duplicates #" + std::to_string(t));
        check_agree(circle, "circle #" + std::to_string(t));
        check_agree(near_line, "near a line #" + std::to_string(t));
        check_agree(corner, "corner #" + std::to_string(t));
        check_agree(images, "mapped lattice #" + std::to_string(t));
        sets += 7;
    }
    MESSAGE(sets << " sets checked in both modes");
}

TEST_CASE("hull_edges_2d gives outward unit normals") {
    const Points sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const auto corners = quadrant_hull_2d(sq);
    const auto edges = hull_edges_2d(sq, corners);
    REQUIRE(edges.size() == 4);
    const Vec<2> centre(0.5, 0.5);
    for (const auto& e : edges) {
        CHECK(e.head<2>().norm() == doctest::Approx(1));
        CHECK(e.head<2>().dot(centre) + e[2] == doctest::Approx(-0.5)); // inside, 0.5 away
    }
    // Edge k runs from corner k to corner k + 1: both lie on it.
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t m : {k, (k + 1) % 4})
            CHECK(std::abs(edges[k].head<2>().dot(sq[static_cast<std::size_t>(corners[m])]) +
                           edges[k][2]) < 1e-15);
}
