// Free-surface detection through the mapped convex hull on shapes whose surface is known:
// a square lattice block (its outer ring), a block with a square hole (outer ring plus the
// particles facing the hole), a cubic block in 3-D (its outer shell). Neighbours are those
// within 2.1 dx (second shell), the usual candidate set.
#include "sluice/physics/free_surface.hpp"
#include "sluice/physics/hull_free_surface.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <utility>

using namespace sluice;

namespace {

using Site = std::pair<int, int>;

// Surface particles by the hull test, or (arc = true) by Dilts' arc method with circles of
// diameter radius_over_dx * dx (Park et al. 2014: 2.1 l0), on the same neighbours.
std::set<Site> surface_2d(const std::set<Site>& sites, double dx, double radius_over_dx,
                          bool arc = false) {
    std::set<Site> surface;
    for (const auto& [i, j] : sites) {
        std::vector<Vec<2>> r;
        for (const auto& [k, l] : sites) {
            const Vec<2> o((k - i) * dx, (l - j) * dx);
            if ((k != i || l != j) && o.norm() <= radius_over_dx * dx)
                r.push_back(o);
        }
        if (arc ? is_free_surface<2>(r, radius_over_dx * dx) : is_surface_particle_by_hull<2>(r))
            surface.insert({i, j});
    }
    return surface;
}

// Independent criterion: the largest angle between consecutive neighbour directions is at
// least pi (a half-plane without neighbours).
bool largest_gap_at_least_pi(const std::vector<Vec<2>>& r) {
    std::vector<double> a;
    for (const auto& o : r)
        a.push_back(std::atan2(o.y(), o.x()));
    if (a.empty())
        return true;
    std::sort(a.begin(), a.end());
    double gap = a.front() + 2 * std::numbers::pi - a.back();
    for (std::size_t k = 1; k < a.size(); ++k)
        gap = std::max(gap, a[k] - a[k - 1]);
    return gap >= std::numbers::pi - 1e-9;
}

} // namespace

TEST_CASE("square lattice block: the surface is the outer ring") {
    const int n = 20;
    const double dx = 0.013; // not a power of two: offsets carry round-off
    std::set<Site> sites;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            sites.insert({i + 7, j - 3});
    std::set<Site> ring;
    for (const auto& [i, j] : sites)
        if (i == 7 || i == n + 6 || j == -3 || j == n - 4)
            ring.insert({i, j});
    CHECK(ring.size() == 4 * n - 4);
    CHECK(surface_2d(sites, dx, 2.1) == ring);
    CHECK(surface_2d(sites, dx, 1.5) == ring);       // first shell only: same answer
    CHECK(surface_2d(sites, dx, 2.1, true) == ring); // the arc method agrees
}

TEST_CASE("lattice with a square hole: outer ring and the particles facing the hole") {
    const int n = 21, h0 = 8, hole = 5; // hole: h0 <= i, j < h0 + hole
    const double dx = 0.1;
    std::set<Site> sites;
    const auto in_hole = [&](int i, int j) {
        return i >= h0 && i < h0 + hole && j >= h0 && j < h0 + hole;
    };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            if (!in_hole(i, j))
                sites.insert({i, j});
    std::set<Site> expected;
    for (const auto& [i, j] : sites)
        if (i == 0 || i == n - 1 || j == 0 || j == n - 1)
            expected.insert({i, j});
    // Beside each side of the hole, the middle three particles have no neighbour on the hole's
    // side within 2.1 dx. The two at the ends of a side still see a particle diagonally across
    // the hole's corner, which closes their hull: they are surrounded.
    for (int k = h0 + 1; k < h0 + hole - 1; ++k) {
        expected.insert({h0 - 1, k});
        expected.insert({h0 + hole, k});
        expected.insert({k, h0 - 1});
        expected.insert({k, h0 + hole});
    }
    CHECK(expected.size() == 4 * n - 4 + 12);
    const auto found = surface_2d(sites, dx, 2.1);
    CHECK(found == expected);
    // Dilts' arc method (circle diameter 2.1 dx) also flags the 8 particles at the ends of the
    // hole's sides: their one diagonal neighbour across the corner does not cover the arc
    // facing the hole. Everything the hull calls surface, the arc method does too.
    const auto arc = surface_2d(sites, dx, 2.1, true);
    for (const auto& s : found)
        CHECK(arc.count(s) == 1);
    CHECK(arc.size() == found.size() + 8);
    MESSAGE("hole: hull " << found.size() << " surface particles, arc method " << arc.size());
    // The angular-gap criterion (no hull involved) agrees particle by particle.
    for (const auto& [i, j] : sites) {
        std::vector<Vec<2>> r;
        for (const auto& [k, l] : sites) {
            const Vec<2> o((k - i) * dx, (l - j) * dx);
            if ((k != i || l != j) && o.norm() <= 2.1 * dx)
                r.push_back(o);
        }
        CHECK(largest_gap_at_least_pi(r) == (found.count({i, j}) == 1));
    }
}

TEST_CASE("cubic lattice block in 3-D: the surface is the outer shell") {
    const int n = 7;
    const double dx = 0.02;
    int surface = 0, wrong = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                std::vector<Vec<3>> r;
                for (int a = 0; a < n; ++a)
                    for (int b = 0; b < n; ++b)
                        for (int c = 0; c < n; ++c) {
                            const Vec<3> o((a - i) * dx, (b - j) * dx, (c - k) * dx);
                            if (o.squaredNorm() > 0 && o.norm() <= 2.1 * dx)
                                r.push_back(o);
                        }
                const bool on_shell =
                    i == 0 || j == 0 || k == 0 || i == n - 1 || j == n - 1 || k == n - 1;
                const bool found = is_surface_particle_by_hull<3>(r);
                surface += found ? 1 : 0;
                wrong += found != on_shell ? 1 : 0;
            }
    CHECK(wrong == 0);
    CHECK(surface == n * n * n - (n - 2) * (n - 2) * (n - 2));
}

TEST_CASE("no neighbours, one neighbour, a line of neighbours: surface") {
    CHECK(is_surface_particle_by_hull<2>(std::vector<Vec<2>>{}));
    CHECK(is_surface_particle_by_hull<2>(std::vector<Vec<2>>{{1, 0}}));
    CHECK(is_surface_particle_by_hull<2>(std::vector<Vec<2>>{{1, 0}, {-1, 0}, {2, 0}}));
    CHECK_FALSE(is_surface_particle_by_hull<2>(std::vector<Vec<2>>{{1, 0}, {-1, 1}, {-1, -1}}));
    CHECK(is_surface_particle_by_hull<3>(std::vector<Vec<3>>{{1, 0, 0}, {0, 1, 0}, {-1, -1, 0}}));
    CHECK_FALSE(is_surface_particle_by_hull<3>(
        std::vector<Vec<3>>{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, -1, -1}}));
}
