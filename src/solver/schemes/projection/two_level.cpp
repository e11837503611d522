// The coarse level of the two-level preconditioner (projection.preconditioner = "two_level";
// docs/PROJECTION.md, "Preconditioner"), built once per step before the solve: which aggregate
// each particle's row belongs to, the rows of A P of this rank's particles and A_c = R A P,
// gathered from every rank and factorised on each (the coarse system is global and small).
#include "projection_scheme.hpp"

#include <algorithm>
#include <cstring>

namespace sluice {

namespace {

// One cell per aggregate (~10 particles in 2-D with the tanks' quintic kernel, cell edge
// 3.1 dx). Measured on the dx = 0.01 dam break to 0.3 s, 1 thread: 8.5 iterations per step and
// 8.0 s CPU with one cell, 13.9 and 8.2 s with 2^D cells; with the block ILU(0) after the
// coarse step 6.2 / 9.8 iterations but 10.7 / 10.0 s (its factorisation costs more than it
// saves); block_ilu0 alone 31.1 iterations, 13.2 s (perf/projection/README.md).
constexpr int kAggregateCells = 1;

template <class T>
std::span<const std::byte> bytes_of(const std::vector<T>& v) {
    return {reinterpret_cast<const std::byte*>(v.data()), v.size() * sizeof(T)};
}

template <class T>
void append_from(const tasks::Bytes& b, std::vector<T>& out) {
    const std::size_t n = b.size() / sizeof(T);
    const std::size_t at = out.size();
    out.resize(at + n);
    if (n > 0)
        std::memcpy(out.data() + at, b.data(), n * sizeof(T));
}

} // namespace

template <int D>
void ProjectionScheme<D>::restrict_owned(const std::vector<Real>& v,
                                         std::vector<double>& out) const {
    const ProjectionData<D>& d = *proj_;
    out.assign(d.coarse.keys.size(), 0.0);
    for (const NeighbourList<D>& list : neighbours_.lists) {
        const std::uint32_t lo = list.first;
        const auto hi = static_cast<std::uint32_t>(list.first + list.offset.size() - 1);
        for (std::uint32_t i = lo; i < hi; ++i)
            if (const std::int32_t c = d.coarse.of[i]; c >= 0)
                out[static_cast<std::size_t>(c)] += double(v[i]);
    }
}

template <int D>
bool ProjectionScheme<D>::setup_coarse() {
    ProjectionData<D>& d = *proj_;
    CoarseLevel& c = d.coarse;
    const auto key_of = [&](std::size_t i) {
        return aggregate_key<D>(cells_.grid, P_.x[i], kAggregateCells);
    };
    // The aggregates that hold a row of this rank, then of every rank (sorted, the same list
    // everywhere). A Dirichlet row (P5) is in none: P is 0 there, so its p stays exactly 0.
    std::vector<std::uint64_t> mine;
    for (const NeighbourList<D>& list : neighbours_.lists) {
        const auto hi = static_cast<std::uint32_t>(list.first + list.offset.size() - 1);
        for (std::uint32_t i = list.first; i < hi; ++i)
            if (d.row[i] != PpeRow::surface)
                mine.push_back(key_of(i));
    }
    std::sort(mine.begin(), mine.end());
    mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
    if (rank_.comm.parallel()) {
        const double t0 = tasks::clock_seconds();
        const auto all = rank_.comm.all_gather(bytes_of(mine));
        rank_.between.push_back({"coarse keys", -1, true, mine.size() * sizeof(std::uint64_t), t0,
                                 tasks::clock_seconds()});
        c.keys.clear();
        for (const auto& b : all)
            append_from(b, c.keys);
        std::sort(c.keys.begin(), c.keys.end());
        c.keys.erase(std::unique(c.keys.begin(), c.keys.end()), c.keys.end());
    } else {
        c.keys = std::move(mine);
    }
    // The aggregate of every particle whose row is not a Dirichlet row; for the halo, the
    // coarse_mark run has just set y = 1 on those rows.
    c.of.assign(P_.size(), -1);
    for (std::size_t i = 0; i < P_.size(); ++i) {
        if (d.y[i] != Real(1))
            continue;
        const std::uint64_t key = key_of(i);
        const auto at = std::lower_bound(c.keys.begin(), c.keys.end(), key);
        if (at != c.keys.end() && *at == key)
            c.of[i] = static_cast<std::int32_t>(at - c.keys.begin());
    }
    // The rows of A P = (I - [a_ij]) P of this rank's particles, per group (columns sorted,
    // equal ones summed in list order), and their sums per aggregate, R A P.
    c.entries.clear();
    for (std::size_t g = 0; g < d.groups.size(); ++g) {
        ProjectionGroup<D>& G = d.groups[g];
        const NeighbourList<D>& list = neighbours_.lists[g];
        const std::uint32_t lo = list.first;
        const auto hi = static_cast<std::uint32_t>(list.first + list.offset.size() - 1);
        G.ap_outer.assign(1, 0);
        G.ap_col.clear();
        G.ap_val.clear();
        for (std::uint32_t i = lo; i < hi; ++i) {
            if (const std::int32_t ci = c.of[i]; ci >= 0) {
                // A row meets a few aggregates (at most 3^D): each column found by a linear
                // search among those met so far, its sum taken in list order, then the row's
                // columns sorted.
                const std::size_t start = G.ap_col.size();
                const auto add = [&](std::int32_t col, double v) {
                    for (std::size_t q = start; q < G.ap_col.size(); ++q)
                        if (G.ap_col[q] == col) {
                            G.ap_val[q] += v;
                            return;
                        }
                    G.ap_col.push_back(col);
                    G.ap_val.push_back(v);
                };
                add(ci, 1.0);
                for (std::uint32_t p = list.offset[i - lo]; p < list.offset[i - lo + 1]; ++p)
                    if (const std::int32_t cj = c.of[list.j[p]]; cj >= 0 && G.a[p] != 0)
                        add(cj, -double(G.a[p]));
                for (std::size_t q = start + 1; q < G.ap_col.size(); ++q)
                    for (std::size_t at = q; at > start && G.ap_col[at - 1] > G.ap_col[at]; --at) {
                        std::swap(G.ap_col[at - 1], G.ap_col[at]);
                        std::swap(G.ap_val[at - 1], G.ap_val[at]);
                    }
                for (std::size_t q = start; q < G.ap_col.size(); ++q)
                    c.entries.push_back({ci, G.ap_col[q], G.ap_val[q]});
            }
            G.ap_outer.push_back(static_cast<int>(G.ap_col.size()));
        }
    }
    merge_coarse_entries(c.entries);
    const auto n = static_cast<int>(c.keys.size());
    for (auto* v : {&c.r, &c.p, &c.s, &c.v, &c.t, &c.e})
        v->assign(c.keys.size(), 0.0);
    if (!rank_.comm.parallel())
        return c.system.factor(n, c.entries);
    // Every rank factorises the same matrix: the ranks' parts in rank order.
    const double t0 = tasks::clock_seconds();
    const auto all = rank_.comm.all_gather(bytes_of(c.entries));
    rank_.between.push_back({"coarse operator", -1, true, c.entries.size() * sizeof(CoarseEntry),
                             t0, tasks::clock_seconds()});
    std::vector<CoarseEntry> global;
    for (const auto& b : all)
        append_from(b, global);
    return c.system.factor(n, global);
}

template void ProjectionScheme<2>::restrict_owned(const std::vector<Real>&,
                                                  std::vector<double>&) const;
template void ProjectionScheme<3>::restrict_owned(const std::vector<Real>&,
                                                  std::vector<double>&) const;
template bool ProjectionScheme<2>::setup_coarse();
template bool ProjectionScheme<3>::setup_coarse();

} // namespace sluice
