// Verlet lists (numerics.neighbour_skin): pairs selected from a list built within support +
// skin at earlier positions must be exactly the pairs a fresh search finds, as long as no
// particle has moved more than skin/2, in the order of the wider list, with the same factor.
#include "sluice/core/neighbourhood.hpp"
#include "sluice/core/rebin.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <span>
#include <utility>

using namespace sluice;

namespace {

template <int D>
struct Cloud {
    Particles<D> P;
    CellGrid<D> grid;
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    std::vector<CellIndex> cells; // occupied cells in storage order
    Real support, skin;

    // n^D jittered lattice particles in the unit box (periodic on axis 0 if asked).
    Cloud(int n, Real support_, Real skin_, bool periodic, std::mt19937& rng)
        : support(support_), skin(skin_) {
        std::uniform_real_distribution<Real> jitter(-0.3, 0.3);
        const Real dx = Real(1) / n;
        const int total = D == 2 ? n * n : n * n * n;
        for (int k = 0; k < total; ++k) {
            Vec<D> x;
            int r = k;
            for (int d = 0; d < D; ++d, r /= n)
                x[d] = ((r % n) + Real(0.5) + jitter(rng)) * dx;
            P.push_back(static_cast<ParticleId>(k), Kind::fluid, x, Vec<D>::Zero(), 1000, 1);
        }
        std::array<bool, D> per{};
        per[0] = periodic;
        grid = CellGrid<D>::make(Vec<D>::Zero(), Vec<D>::Ones(), support + skin, per);
        rebin(grid, P, ranges, occ);
        for (const auto& c : occ)
            cells.push_back(c.cell);
        P.x_ref = P.x;
    }
    Neighbourhood<D> nb(Real radius, const std::vector<Vec<D>>& x) const {
        return {&grid, &ranges, std::span<const Vec<D>>(x), radius};
    }
};

const auto none = [](std::uint32_t) { return false; };
const auto all = [](std::uint32_t) { return true; };
const auto square = [](Real r2) { return r2; };

template <int D>
std::set<std::pair<std::uint32_t, std::uint32_t>> pair_set(const NeighbourList<D>& L) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> s;
    for (std::size_t k = 0; k + 1 < L.offset.size(); ++k)
        for (std::uint32_t p = L.offset[k]; p < L.offset[k + 1]; ++p)
            s.emplace(L.first + static_cast<std::uint32_t>(k), L.j[p]);
    return s;
}

template <int D>
void check_selection(bool periodic, unsigned seed) {
    std::mt19937 rng(seed);
    const int n = D == 2 ? 24 : 10;
    const Real dx = Real(1) / n, support = Real(2.4) * dx, skin = Real(0.5) * dx;
    Cloud<D> C(n, support, skin, periodic, rng);
    NeighbourList<D> wide, selected, fresh;
    C.nb(support + skin, C.P.x_ref).build_list(C.cells, wide, square, none, all);

    // Every particle moves by just under skin/2 in a random direction (wrapped on the
    // periodic axis only by the image shift the lists carry, so positions stay in the box).
    std::normal_distribution<Real> dir(0, 1);
    for (auto& x : C.P.x) {
        Vec<D> u;
        for (int d = 0; d < D; ++d)
            u[d] = dir(rng);
        x += Real(0.499) * skin * u.normalized();
    }
    C.nb(support, C.P.x).select_pairs(wide, selected, square);
    C.nb(support, C.P.x).build_list(C.cells, fresh, square, none, all);

    REQUIRE(selected.pairs == fresh.pairs);
    CHECK(pair_set(selected) == pair_set(fresh));
    // The selection keeps the wider list's order and stores r^2 (the factor given) exactly.
    for (std::size_t k = 0; k + 1 < selected.offset.size(); ++k) {
        const std::uint32_t i = selected.first + static_cast<std::uint32_t>(k);
        std::uint32_t last_pos = 0;
        for (std::uint32_t p = selected.offset[k]; p < selected.offset[k + 1]; ++p) {
            const std::uint32_t j = selected.j[p];
            const auto* b = wide.j.data() + wide.offset[k];
            const auto* e = wide.j.data() + wide.offset[k + 1];
            const auto pos = static_cast<std::uint32_t>(std::find(b, e, j) - b);
            REQUIRE(pos < static_cast<std::uint32_t>(e - b));
            CHECK((p == selected.offset[k] || pos > last_pos));
            last_pos = pos;
            // The same expression as the pair loops (for_each_listed) use.
            const Vec<D> d = selected.periodic ? Vec<D>(C.P.x[i] + selected.shift[p] - C.P.x[j])
                                               : Vec<D>(C.P.x[i] - C.P.x[j]);
            CHECK(selected.factor[p] == d.squaredNorm());
        }
    }
}

} // namespace

TEST_CASE("Pairs selected from a Verlet list equal a fresh search after moves below skin/2") {
    for (unsigned seed = 1; seed <= 3; ++seed) {
        check_selection<2>(false, seed);
        check_selection<2>(true, seed);
        check_selection<3>(false, seed);
    }
}

TEST_CASE("A move beyond skin/2 can lose a pair: the rebuild criterion is needed") {
    // Two particles just outside support + skin of each other, moving towards each other by
    // more than skin/2 each, end up within the support, but the wider list does not hold them.
    Particles<2> P;
    const Real support = 0.1, skin = 0.02;
    P.push_back(0, Kind::fluid, Vec<2>(0.40, 0.5), Vec<2>::Zero(), 1000, 1);
    P.push_back(1, Kind::fluid, Vec<2>(0.40 + support + skin + 0.001, 0.5), Vec<2>::Zero(), 1000,
                1);
    CellGrid<2> grid = CellGrid<2>::make(Vec<2>::Zero(), Vec<2>::Ones(), support + skin, {});
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    rebin(grid, P, ranges, occ);
    std::vector<CellIndex> cells;
    for (const auto& c : occ)
        cells.push_back(c.cell);
    NeighbourList<2> wide, selected;
    Neighbourhood<2>{&grid, &ranges, std::span<const Vec<2>>(P.x), support + skin}.build_list(
        cells, wide, square, none, all);
    P.x[0][0] += 0.6 * skin;
    P.x[1][0] -= 0.6 * skin;
    REQUIRE((P.x[0] - P.x[1]).norm() < support);
    Neighbourhood<2>{&grid, &ranges, std::span<const Vec<2>>(P.x), support}.select_pairs(
        wide, selected, square);
    CHECK(selected.pairs == 2); // each particle with itself only
}

namespace {

// A pair function with N sums of the kind the pair loops form (gradient-like sums and scalar
// ones), in plain components as lane_sum_over_pairs wants.
template <int D, std::size_t N>
std::array<Real, N> pair_sums(std::uint32_t j, const typename Neighbourhood<D>::Dx& dx, Real r2,
                              Real factor) {
    std::array<Real, N> out;
    for (std::size_t k = 0; k < N; ++k)
        out[k] = k % 3 == 2 ? r2 * Real((j + k) % 7) : factor * dx[k % D] * Real(k + 1);
    return out;
}

template <int D, std::size_t N>
void check_lane_sums(bool periodic, unsigned seed) {
    std::mt19937 rng(seed);
    const int n = D == 2 ? 24 : 10;
    const Real dx = Real(1) / n, support = Real(2.4) * dx;
    Cloud<D> C(n, support, 0, periodic, rng);
    const auto factor = [](Real r2) { return std::exp(-r2); };
    const auto nb = C.nb(support, C.P.x);
    NeighbourList<D> whole, tail;
    nb.build_list(C.cells, whole, factor, none, all);
    // The same rows again in a list of the second half of the cells only: each row now starts
    // elsewhere in memory (another group's list), which must not change a bit of its sums.
    const std::size_t half = C.cells.size() / 2;
    nb.build_list(std::span<const CellIndex>(C.cells).subspan(half), tail, factor, none, all);
    auto listed = nb, tail_listed = nb;
    listed.list = &whole;
    tail_listed.list = &tail;
    const auto f = [](std::uint32_t j, const typename Neighbourhood<D>::Dx& d, Real r2, Real F) {
        return pair_sums<D, N>(j, d, r2, F);
    };
    double worst = 0;
    for (std::size_t c = 0; c < C.cells.size(); ++c) {
        const AdjacentCells<D> adj = nb.adjacent(C.cells[c]);
        for (std::uint32_t i = nb.begin(C.cells[c]), stop = nb.end(C.cells[c]); i < stop; ++i) {
            const auto scanned = nb.template lane_sum_over_pairs<N>(adj, i, factor, f);
            const auto in_list = listed.template lane_sum_over_pairs<N>(adj, i, factor, f);
            for (std::size_t k = 0; k < N; ++k)
                worst = std::max(worst, std::abs(double(in_list[k] - scanned[k])) /
                                            (std::abs(double(scanned[k])) + 1e-3));
            if (c >= half) {
                const auto in_tail = tail_listed.template lane_sum_over_pairs<N>(adj, i, factor, f);
                CHECK(in_tail == in_list);
            }
        }
    }
    // Over a list the lanes add in another order than the scan: equal to round-off.
    CHECK(worst < 1e-12);
}

} // namespace

TEST_CASE("Sums over listed pairs in vector lanes: the scan's sums to round-off, and the same "
          "bits wherever a row sits in memory") {
    // N = 3 and N = 9 (the most accumulators: the 3-D renormalised density gradient's).
    for (unsigned seed = 1; seed <= 2; ++seed) {
        check_lane_sums<2, 3>(false, seed);
        check_lane_sums<2, 3>(true, seed);
        check_lane_sums<3, 3>(false, seed);
        check_lane_sums<2, 9>(true, seed);
        check_lane_sums<3, 9>(false, seed);
    }
}

// The solver's Rebinner is called again at every rebuild with the ranges it filled last time
// and a halo cell an unpack set since: it must leave exactly what a one-off rebin into fresh
// ranges gives (a rank's particles filling a small part of the grid), storing only the
// occupied cells.
TEST_CASE("a repeated rebin clears the halo cells and equals a fresh rebin") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> in_patch(Real(0.2), Real(0.3));
    std::normal_distribution<Real> step(0, Real(0.004));
    const auto grid = CellGrid<2>::make(Vec<2>::Zero(), Vec<2>::Ones(), Real(0.01), {});
    Particles<2> P;
    for (int k = 0; k < 600; ++k)
        P.push_back(static_cast<ParticleId>(k), Kind::fluid, Vec<2>(in_patch(rng), in_patch(rng)),
                    Vec<2>::Zero(), 1000, 1);
    Rebinner<2> rebinner;
    CellRanges ranges;
    std::vector<CellOccupancy> occ;
    rebinner(grid, P, ranges, occ);
    for (int round = 0; round < 3; ++round) {
        // A halo cell far from the particles, as an unpack sets it (past the owned ones).
        const CellIndex halo = grid.linear(grid.coords(Vec<2>(Real(0.9), Real(0.9 - 0.1 * round))));
        ranges.reserve(1);
        ranges.set(halo, 600, 610);
        for (auto& x : P.x)
            x += Vec<2>(step(rng), step(rng)); // many cross into another cell
        Particles<2> copy = P;
        CellRanges fresh;
        std::vector<CellOccupancy> fresh_occ;
        const bool moved = rebin(grid, copy, fresh, fresh_occ);
        CHECK(rebinner(grid, P, ranges, occ) == moved);
        CHECK(moved);
        CHECK(P.id == copy.id);
        CHECK(P.x == copy.x);
        for (CellIndex c = 0; c < grid.cell_count(); ++c) { // the halo cell cleared too
            CHECK(ranges.begin(c) == fresh.begin(c));
            CHECK(ranges.end(c) == fresh.end(c));
        }
        CHECK(ranges.end(halo) == 0);
        REQUIRE(occ.size() == fresh_occ.size());
        for (std::size_t k = 0; k < occ.size(); ++k) {
            CHECK(occ[k].cell == fresh_occ[k].cell);
            CHECK(occ[k].key == fresh_occ[k].key);
            CHECK(occ[k].count == fresh_occ[k].count);
        }
        CHECK(ranges.stored() == occ.size());
    }
}
