#pragma once
// Fixed-order neighbour iteration over the cell-sorted particle arrays. This order (adjacent
// cells in the order of adjacent_cells(), particles inside a cell by id) is what makes every
// neighbour sum, and so the whole result, independent of threads, groups and ranks.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/cell_ranges.hpp"
#include "sluice/core/lanes.hpp"

#include <array>
#include <span>
#include <vector>

namespace sluice {

// The adjacent cells of one cell and their particle ranges, computed once and reused for all
// its particles (a range lookup is a hash probe, CellRanges).
template <int D>
struct AdjacentCells {
    NeighbourCell<D> cell[D == 2 ? 9 : 27];
    CellRanges::Range range[D == 2 ? 9 : 27];
    int count = 0;
};

// Neighbours of a contiguous range of particles (one cell group), found once per step and
// reused by every stage of that step: positions do not change within a step, so the list is
// exact. Pairs are kept in the order of the cell scan, so sums are bitwise the same as
// without the list. Buffers keep their capacity between steps (no allocation in a step).
template <int D>
struct NeighbourList {
    std::uint32_t first = 0;                // index of the first particle of the range
    std::vector<std::uint32_t> offset;      // pairs of particle first + k: [offset[k], offset[k+1])
    std::vector<std::uint32_t> j;           // neighbour index
    std::vector<Vec<D>> shift;              // periodic image shift added to x_i - x_j (only when
                                            // an axis is periodic: every shift is zero otherwise)
    std::vector<Real> factor;               // per pair: the radial factor given to build_list
    std::size_t pairs = 0;                  // pairs found (the arrays may be longer)
    bool periodic = false;                  // whether `shift` holds the image shifts
    std::vector<AdjacentCells<D>> adjacent; // scratch: adjacent cells of each cell of the range
    [[nodiscard]] bool covers(std::uint32_t i) const {
        return i >= first && i + 1 < first + offset.size();
    }
};

template <int D>
struct Neighbourhood {
    const CellGrid<D>* grid = nullptr;
    const CellRanges* cells = nullptr;
    std::span<const Vec<D>> x;
    Real support = 0;
    const NeighbourList<D>* list = nullptr; // when set, used for the particles it covers

    // Adjacent cells of c; none when the list covers c's particles (then for_each_neighbour
    // never looks at them, and finding them was 3 % of a step).
    [[nodiscard]] AdjacentCells<D> adjacent(CellIndex c) const {
        AdjacentCells<D> a;
        if (list != nullptr) {
            const CellRanges::Range own = cells->range(c);
            if (own.begin < own.end && list->covers(own.begin))
                return a;
        }
        a.count = adjacent_cells(*grid, c, a.cell);
        for (int k = 0; k < a.count; ++k)
            a.range[k] = cells->range(a.cell[k].cell);
        return a;
    }

    // Calls f(j, dx, r2) for every particle j (i itself included) with |x_i - x_j| < support,
    // where dx = x_i - x_j with the periodic image applied. `adj` are the adjacent cells of
    // the cell holding i.
    template <class F>
    void for_each_neighbour(const AdjacentCells<D>& adj, std::uint32_t i, F&& f) const {
        if (list != nullptr && list->covers(i)) {
            for_each_listed(i, f);
            return;
        }
        const Real support2 = support * support;
        const Vec<D> xi = x[i];
        for (int k = 0; k < adj.count; ++k) {
            const Vec<D> xis = xi + adj.cell[k].shift;
            const std::uint32_t e = adj.range[k].end;
            for (std::uint32_t j = adj.range[k].begin; j < e; ++j) {
                const Vec<D> dx = xis - x[j];
                const Real r2 = dx.squaredNorm();
                if (r2 < support2)
                    f(j, dx, r2);
            }
        }
    }

    // sum + the sum over the pairs of i (as for_each_neighbour) of f(j, dx, r2, factor(r2)),
    // added in pair order. factor(r2) is taken from the list (computed once per step by
    // build_list with the same function), computed here otherwise: the kernel gradient factor
    // (dW/dr)/r is what every gradient sum needs, and sqrt + kernel per pair is most of a
    // stage's arithmetic, so the stages of a step share one evaluation. The running sum is a local
    // of this loop rather than a variable the pair function captures by reference: GCC then keeps
    // it in registers (with a captured accumulator it stored and reloaded it every pair, a
    // store-forwarding stall per pair).
    template <class T, class G, class F>
    [[nodiscard]] T sum_over_pairs(const AdjacentCells<D>& adj, std::uint32_t i, const G& factor,
                                   T sum, F&& f) const {
        if (list != nullptr && list->covers(i)) {
            const std::uint32_t k = i - list->first;
            const Vec<D> xi = x[i];
            const std::uint32_t b = list->offset[k], e = list->offset[k + 1];
            if (!list->periodic) {
                for (std::uint32_t p = b; p < e; ++p) {
                    const std::uint32_t j = list->j[p];
                    const Vec<D> dx = xi - x[j];
                    sum += f(j, dx, dx.squaredNorm(), list->factor[p]);
                }
            } else {
                for (std::uint32_t p = b; p < e; ++p) {
                    const std::uint32_t j = list->j[p];
                    const Vec<D> dx = xi + list->shift[p] - x[j];
                    sum += f(j, dx, dx.squaredNorm(), list->factor[p]);
                }
            }
            return sum;
        }
        for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>& dx, Real r2) {
            sum += f(j, dx, r2, factor(r2));
        });
        return sum;
    }

    // Pair displacement as plain components (see lane_sum_over_pairs).
    using Dx = std::array<Real, D>;

    // The sums over the pairs of i of f(j, dx, r2, factor(r2)) -> std::array<Real, N>
    // (N <= 9: the renormalised density gradient's 3-D matrix and vector), with dx = x_i - x_j as a
    // Dx. Over a list this is an `omp simd` reduction: the compiler gives each vector lane every
    // W-th pair and adds the lanes at the end, so the pair arithmetic runs W pairs per instruction.
    // A pair function for it is written in plain components (no Eigen vectors, whose 2-D operations
    // are SSE intrinsics the vectoriser cannot widen) and without branches (selects instead). The
    // order of the additions depends on W (a build setting) and on the list, which is the same for
    // any threads, groups and ranks, so results stay bitwise invariant across them (the build turns
    // off peeling for alignment, see CMakeLists.txt). Off a list, pairs are added in
    // for_each_neighbour's order.
    template <std::size_t N, class G, class F>
    [[nodiscard]] std::array<Real, N> lane_sum_over_pairs(const AdjacentCells<D>& adj,
                                                          std::uint32_t i, const G& factor,
                                                          F&& f) const {
        static_assert(N >= 1 && N <= 9);
        static_assert(sizeof(Vec<D>) == D * sizeof(Real), "positions are read as D-strided");
        std::array<Real, N> sum{};
        if (list == nullptr || !list->covers(i)) {
            for_each_neighbour(adj, i, [&](std::uint32_t j, const Vec<D>& dxv, Real r2) {
                Dx dx;
                for (int d = 0; d < D; ++d)
                    dx[d] = dxv[d];
                const std::array<Real, N> c = f(j, dx, r2, factor(r2));
                for (std::size_t n = 0; n < N; ++n)
                    sum[n] += c[n];
            });
            return sum;
        }
        const std::uint32_t k = i - list->first;
        const std::uint32_t b = list->offset[k], e = list->offset[k + 1];
        const Real* X = x.data()->data();
        const std::uint32_t* js = list->j.data();
        const Real* fs = list->factor.data();
        Dx xi;
        for (int d = 0; d < D; ++d)
            xi[d] = x[i][d];
        // One loop for both kinds of list; `periodic` adds the image shift of each pair.
        const auto lanes = [&]<bool periodic>() {
            const Vec<D>* shift = list->shift.data();
            // One named accumulator per sum (an array section in the reduction clause does
            // not vectorise with GCC 12); those beyond N stay zero and are optimised away.
            Real s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0, s8 = 0;
#pragma omp simd reduction(+ : s0, s1, s2, s3, s4, s5, s6, s7, s8)
            for (std::uint32_t p = b; p < e; ++p) {
                const std::uint32_t j = js[p];
                Dx dx;
                Real r2 = 0;
                for (int d = 0; d < D; ++d) {
                    Real xid = xi[d];
                    if constexpr (periodic)
                        xid += shift[p][d];
                    dx[d] = xid - X[D * j + d];
                    r2 += dx[d] * dx[d];
                }
                const std::array<Real, N> c = f(j, dx, r2, fs[p]);
                s0 += c[0];
                if constexpr (N > 1)
                    s1 += c[1];
                if constexpr (N > 2)
                    s2 += c[2];
                if constexpr (N > 3)
                    s3 += c[3];
                if constexpr (N > 4)
                    s4 += c[4];
                if constexpr (N > 5)
                    s5 += c[5];
                if constexpr (N > 6)
                    s6 += c[6];
                if constexpr (N > 7)
                    s7 += c[7];
                if constexpr (N > 8)
                    s8 += c[8];
            }
            return std::array<Real, 9>{s0, s1, s2, s3, s4, s5, s6, s7, s8};
        };
        const std::array<Real, 9> s =
            list->periodic ? lanes.template operator()<true>() : lanes.template operator()<false>();
        for (std::size_t n = 0; n < N; ++n)
            sum[n] = s[n];
        return sum;
    }

private:
    // The listed pairs of i (the list must cover i): f(j, dx, r2).
    template <class F>
    void for_each_listed(std::uint32_t i, F&& f) const {
        const std::uint32_t k = i - list->first;
        const Vec<D> xi = x[i];
        const std::uint32_t b = list->offset[k], e = list->offset[k + 1];
        if (!list->periodic) {
            for (std::uint32_t p = b; p < e; ++p) {
                const std::uint32_t j = list->j[p];
                const Vec<D> dx = xi - x[j];
                f(j, dx, dx.squaredNorm());
            }
        } else {
            for (std::uint32_t p = b; p < e; ++p) {
                const std::uint32_t j = list->j[p];
                const Vec<D> dx = xi + list->shift[p] - x[j];
                f(j, dx, dx.squaredNorm());
            }
        }
    }

public:
    // Fills `out` with the neighbours of the particles of `cells`, which must be contiguous
    // in the particle arrays and given in storage order (a cell group's cells), and with
    // factor(r2) for every pair (see sum_over_pairs). For a centre i with partial(i) true,
    // only the neighbours j with wanted(j) are listed (the solver lists only fluid partners of
    // wall particles: nothing reads wall-wall pairs, and in 3-D they are half of all pairs).
    // The wanted particles of every cell must come first in it (the solver's fluid particles
    // have lower ids than its walls, and a cell is sorted by id), so a partial centre scans
    // only that leading run: a wall particle deep in a wall scans almost nothing.
    template <class G, class Partial, class Wanted>
    SLUICE_FLATTEN void build_list(std::span<const CellIndex> group_cells, NeighbourList<D>& out,
                                   const G& factor, const Partial& partial,
                                   const Wanted& wanted) const {
        out.first = group_cells.empty() ? 0 : begin(group_cells.front());
        out.adjacent.resize(group_cells.size());
        std::size_t n_particles = 0;
        for (std::size_t g = 0; g < group_cells.size(); ++g) {
            out.adjacent[g] = adjacent(group_cells[g]);
            n_particles += end(group_cells[g]) - begin(group_cells[g]);
        }
        const bool periodic = grid->any_periodic();
        out.offset.resize(n_particles + 1);
        const Real support2 = support * support;
        // The scan below writes every candidate and keeps a pair by advancing n, so there must
        // be room for all candidates of a particle beyond n: checked once per particle (the
        // buffers only grow, doubling, and keep their capacity between steps). Sizing for all
        // candidates of the group at once would take ~1,700 entries per particle in 3-D.
        const auto reserve = [&](std::size_t need) {
            if (out.j.size() >= need)
                return;
            const std::size_t size = std::max(need, 2 * out.j.size());
            out.j.resize(size);
            out.factor.resize(size); // holds r2 until the last loop turns it into the factor
            if (periodic)
                out.shift.resize(size);
        };
        std::size_t n = 0, row = 0;
        out.offset[0] = 0;
        for (std::size_t g = 0; g < group_cells.size(); ++g) {
            const CellIndex c = group_cells[g];
            const AdjacentCells<D>& adj = out.adjacent[g];
            std::size_t candidates = 0;
            for (int k = 0; k < adj.count; ++k)
                candidates += adj.range[k].end - adj.range[k].begin;
            const CellRanges::Range own = cells->range(c);
            for (std::uint32_t i = own.begin; i < own.end; ++i) {
                reserve(n + candidates);
                std::uint32_t* js = out.j.data();
                Real* r2s = out.factor.data();
                const Vec<D> xi = x[i];
                const bool all = !partial(i);
                for (int k = 0; k < adj.count; ++k) {
                    const Vec<D> xis = xi + adj.cell[k].shift;
                    const std::uint32_t b = adj.range[k].begin, e = adj.range[k].end;
                    // Branch-free compaction: every candidate is written at n and kept by
                    // advancing n. About a third are kept, so an `if` mispredicts often.
                    if (periodic)
                        for (std::uint32_t j = b; j < e; ++j) {
                            const Real r2 = (xis - x[j]).squaredNorm();
                            out.shift[n] = adj.cell[k].shift;
                            js[n] = j;
                            r2s[n] = r2;
                            n += r2 < support2 && (all || wanted(j)) ? 1 : 0;
                        }
                    else if (all)
                        for (std::uint32_t j = b; j < e; ++j) {
                            const Real r2 = (xis - x[j]).squaredNorm();
                            js[n] = j;
                            r2s[n] = r2;
                            n += r2 < support2 ? 1 : 0;
                        }
                    else
                        for (std::uint32_t j = b; j < e && wanted(j); ++j) {
                            const Real r2 = (xis - x[j]).squaredNorm();
                            js[n] = j;
                            r2s[n] = r2;
                            n += r2 < support2 ? 1 : 0;
                        }
                }
                out.offset[++row] = static_cast<std::uint32_t>(n);
            }
        }
        out.pairs = n;
        out.periodic = periodic;
        kernel_factors(factor, out.factor.data(), n);
    }

    // Fills `out` from a wider list built earlier (a Verlet list: build_list with support +
    // skin at the last rebuild, whose pairs were then within that radius): keeps the pairs now
    // within `support`, in the wider list's order, with factor(r2) for each. Valid while no
    // particle has moved more than skin/2 since that build. Scanning the ~1.4 candidates per
    // pair of the wider list replaces scanning the ~3 candidates per pair of the 3^D cells.
    template <class G>
    SLUICE_FLATTEN void select_pairs(const NeighbourList<D>& wide, NeighbourList<D>& out,
                                     const G& factor) const {
        out.first = wide.first;
        const std::size_t bound = wide.pairs;
        if (out.j.size() < bound) {
            out.j.resize(bound);
            out.factor.resize(bound);
        }
        if (wide.periodic && out.shift.size() < bound)
            out.shift.resize(bound);
        out.offset.resize(wide.offset.size());
        const Real support2 = support * support;
        std::uint32_t* js = out.j.data();
        Real* r2s = out.factor.data();
        std::size_t n = 0;
        out.offset[0] = 0;
        const std::size_t rows = wide.offset.size() - 1;
        for (std::size_t k = 0; k < rows; ++k) {
            const Vec<D> xi = x[wide.first + k];
            const std::uint32_t b = wide.offset[k], e = wide.offset[k + 1];
            if (wide.periodic)
                for (std::uint32_t p = b; p < e; ++p) {
                    const std::uint32_t j = wide.j[p];
                    const Real r2 = (xi + wide.shift[p] - x[j]).squaredNorm();
                    out.shift[n] = wide.shift[p];
                    js[n] = j;
                    r2s[n] = r2;
                    n += r2 < support2 ? 1 : 0;
                }
            else {
                std::uint32_t p = b;
#if defined(__AVX2__) && !defined(SLUICE_SINGLE_PRECISION)
                // In 2-D, four candidates per instruction, kept by a compressing store (the
                // same pairs, in the same order, with the same r2 as the loop below). It
                // writes four entries at n <= p, so within the first p + 4 <= e <= bound.
                if constexpr (D == 2) {
                    const Real* X = x.data()->data();
                    const Real4 xi0 = Real4{0, 0, 0, 0} + xi[0], xi1 = Real4{0, 0, 0, 0} + xi[1];
                    const Real4 limit = Real4{0, 0, 0, 0} + support2;
                    for (; p + 4 <= e; p += 4) {
                        const std::uint32_t* j = wide.j.data() + p;
                        Real4 xj0, xj1;
                        load_pair_lanes(X + 2 * j[0], X + 2 * j[1], X + 2 * j[2], X + 2 * j[3], xj0,
                                        xj1);
                        const Real4 d0 = xi0 - xj0, d1 = xi1 - xj1;
                        Real4 sq0 = d0 * d0, sq1 = d1 * d1;
                        // Rounded products, as squaredNorm's: no fused multiply-add, so that r2
                        // is a fresh search's bit for bit (test_verlet_list).
                        asm("" : "+x"(sq0), "+x"(sq1));
                        const Real4 r2 = sq0 + sq1;
                        const int keep = _mm256_movemask_pd(__m256d(r2 < limit));
                        n += static_cast<std::size_t>(compress_store(
                            keep, _mm_loadu_si128(reinterpret_cast<const __m128i*>(j)), r2, js + n,
                            r2s + n));
                    }
                }
#endif
                for (; p < e; ++p) {
                    const std::uint32_t j = wide.j[p];
                    const Real r2 = (xi - x[j]).squaredNorm();
                    js[n] = j;
                    r2s[n] = r2;
                    n += r2 < support2 ? 1 : 0;
                }
            }
            out.offset[k + 1] = static_cast<std::uint32_t>(n);
        }
        out.pairs = n;
        out.periodic = wide.periodic;
        kernel_factors(factor, r2s, n);
    }

    // r2s[p] = factor(r2s[p]) for p < n, as one vector loop (scalar, it was about half of
    // select_pairs' time in 3-D). The factor is copied into a local first, so the kernel
    // constants it holds cannot alias r2s (GCC reloaded them every pair, or guarded the vector
    // loop with an alias check); that only works if the factor holds them by value, as
    // run_stage_with's does, not by reference. The cubic spline's loop also needs
    // -fno-trapping-math (CMakeLists.txt) to vectorise.
    template <class G>
    static void kernel_factors(const G& factor, Real* r2s, std::size_t n) {
        const G f = factor;
        for (std::size_t p = 0; p < n; ++p)
            r2s[p] = f(r2s[p]);
    }

    [[nodiscard]] std::uint32_t begin(CellIndex c) const {
        return cells->begin(c);
    }
    [[nodiscard]] std::uint32_t end(CellIndex c) const {
        return cells->end(c);
    }
};

#if defined(__AVX__) && !defined(SLUICE_SINGLE_PRECISION)
// The pairs of particle i's row of a 2-D list, four at a time, for the four-lane pair loops
// (physics/momentum_lanes.hpp, continuity_lanes.hpp): f(n, factor, xi, yi) with n the four
// neighbour indices, factor their listed factors and xi, yi particle i's position x_i plus each
// pair's periodic shift. Pair b + 4k + l of the row goes to lane l. A row's full groups of four
// load their indices and factors directly; past the row's end a lane takes particle i itself
// with a zero factor and no shift (its zero displacement and factor add nothing).
template <class F>
SLUICE_FLATTEN void for_pairs_in_fours(const NeighbourList<2>& list, std::uint32_t i,
                                       const Vec<2>& x_i, F&& f) {
    const std::uint32_t* js = list.j.data();
    const Real* factors = list.factor.data();
    const Vec<2>* shift = list.periodic ? list.shift.data() : nullptr;
    const std::uint32_t row = i - list.first;
    const std::uint32_t b = list.offset[row], e = list.offset[row + 1];
    const Real4 zero{0, 0, 0, 0};
    const Real4 xi_self = zero + x_i[0], yi_self = zero + x_i[1];
    std::uint32_t q = b;
    for (; q + 4 <= e; q += 4) {
        const std::uint32_t n[4] = {js[q], js[q + 1], js[q + 2], js[q + 3]};
        Real4 xi = xi_self, yi = yi_self;
        if (shift != nullptr) {
            Real4 sx, sy;
            load_pair_lanes(shift[q].data(), shift[q + 1].data(), shift[q + 2].data(),
                            shift[q + 3].data(), sx, sy);
            xi += sx;
            yi += sy;
        }
        f(n, Real4(_mm256_loadu_pd(factors + q)), xi, yi);
    }
    if (q < e) {
        std::uint32_t n[4];
        Real4 factor = zero, xi = xi_self, yi = yi_self;
        for (std::uint32_t l = 0; l < 4; ++l) {
            const bool in = q + l < e;
            n[l] = in ? js[q + l] : i;
            if (in) {
                factor[l] = factors[q + l];
                if (shift != nullptr) {
                    xi[l] += shift[q + l][0];
                    yi[l] += shift[q + l][1];
                }
            }
        }
        f(n, factor, xi, yi);
    }
}
#endif

} // namespace sluice
