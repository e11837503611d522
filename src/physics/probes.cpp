// Bulk detection (cell hash + union-find) and the probes built on it.
#include "sluice/physics/probes.hpp"

#include "sluice/physics/cell_hash.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace sluice {
namespace {

// Disjoint sets with union by size and path halving: near-constant time per operation.
class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n), size_(n, 1) {
        for (std::size_t i = 0; i < n; ++i)
            parent_[i] = i;
    }
    std::size_t find(std::size_t i) {
        while (parent_[i] != i) {
            parent_[i] = parent_[parent_[i]];
            i = parent_[i];
        }
        return i;
    }
    void unite(std::size_t a, std::size_t b) {
        a = find(a);
        b = find(b);
        if (a == b)
            return;
        if (size_[a] < size_[b])
            std::swap(a, b);
        parent_[b] = a;
        size_[a] += size_[b];
    }

private:
    std::vector<std::size_t> parent_, size_;
};

} // namespace

template <int D>
std::vector<std::size_t> bulk_fluid(const Particles<D>& ps, Real dx) {
    std::vector<std::size_t> fluid;
    for (std::size_t i = 0; i < ps.size(); ++i)
        if (ps.kind[i] == Kind::fluid)
            fluid.push_back(i);
    return bulk_fluid(ps, dx, fluid);
}

template <int D>
std::vector<std::size_t> bulk_fluid(const Particles<D>& ps, Real dx,
                                    const std::vector<std::size_t>& fluid) {
    const std::size_t n = fluid.size();
    if (n == 0)
        return {};

    const Real link = Real(1.5) * dx;
    const Real link2 = link * link;

    // Bucket particles by cell (cell size = link distance, so linked pairs are in adjacent
    // cells): counting sort into a compact layout, O(N).
    std::unordered_map<CellKey<D>, std::size_t, CellKeyHash<D>> cell_index;
    cell_index.reserve(n);
    std::vector<std::size_t> cell_of_particle(n, SIZE_MAX);
    std::vector<std::size_t> count;
    for (std::size_t k = 0; k < n; ++k) {
        CellKey<D> key;
        if (!cell_key_of<D>(ps.x[fluid[k]], 1 / link, key))
            continue;
        const auto [it, added] = cell_index.try_emplace(key, count.size());
        if (added)
            count.push_back(0);
        cell_of_particle[k] = it->second;
        ++count[it->second];
    }
    std::vector<std::size_t> start(count.size() + 1, 0);
    for (std::size_t c = 0; c < count.size(); ++c)
        start[c + 1] = start[c] + count[c];
    std::vector<std::size_t> members(start.back());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < n; ++k)
        if (cell_of_particle[k] != SIZE_MAX)
            members[fill[cell_of_particle[k]]++] = k;

    UnionFind uf(n);
    const auto offsets = cell_neighbour_offsets<D>();
    for (const auto& [key, c] : cell_index) {
        for (const auto& off : offsets) {
            CellKey<D> nk;
            for (std::size_t a = 0; a < static_cast<std::size_t>(D); ++a)
                nk[a] = key[a] + off[a];
            const auto nb = cell_index.find(nk);
            if (nb == cell_index.end() || nb->second < c)
                continue; // each cell pair once
            const std::size_t other = nb->second;
            for (std::size_t s = start[c]; s < start[c + 1]; ++s) {
                const std::size_t k = members[s];
                // Within one cell, each pair once as well.
                for (std::size_t t = other == c ? s + 1 : start[other]; t < start[other + 1]; ++t) {
                    const std::size_t m = members[t];
                    if ((ps.x[fluid[k]] - ps.x[fluid[m]]).squaredNorm() <= link2)
                        uf.unite(k, m);
                }
            }
        }
    }

    // Largest component; ties go to the one with the smallest id, independent of ordering.
    std::vector<std::size_t> size(n, 0);
    std::vector<ParticleId> min_id(n, std::numeric_limits<ParticleId>::max());
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t r = uf.find(k);
        ++size[r];
        min_id[r] = std::min(min_id[r], ps.id[fluid[k]]);
    }
    std::size_t best = uf.find(0);
    for (std::size_t r = 0; r < n; ++r)
        if (size[r] > size[best] ||
            (size[r] == size[best] && size[r] > 0 && min_id[r] < min_id[best]))
            best = r;

    std::vector<std::size_t> bulk;
    bulk.reserve(size[best]);
    for (std::size_t k = 0; k < n; ++k)
        if (uf.find(k) == best)
            bulk.push_back(fluid[k]);
    return bulk;
}

template <int D>
Real water_level(const Particles<D>& ps, const std::vector<std::size_t>& bulk, Real dx, Real x) {
    bool wet = false;
    Real top = -std::numeric_limits<Real>::infinity();
    for (std::size_t i : bulk) {
        if (std::abs(ps.x[i][0] - x) > dx)
            continue;
        top = std::max(top, ps.x[i][D - 1]);
        wet = true;
    }
    return wet ? top + dx / 2 : std::numeric_limits<Real>::quiet_NaN();
}

template <int D>
Real water_level(const Particles<D>& ps, Real dx, Real x) {
    return water_level(ps, bulk_fluid(ps, dx), dx, x);
}

template <int D>
Real surge_front(const Particles<D>& ps, const std::vector<std::size_t>& bulk, Real dx) {
    if (bulk.empty())
        return std::numeric_limits<Real>::quiet_NaN();
    Real front = -std::numeric_limits<Real>::infinity();
    for (std::size_t i : bulk)
        front = std::max(front, ps.x[i][0]);
    return front + dx / 2;
}

template <int D>
Real surge_front(const Particles<D>& ps, Real dx) {
    return surge_front(ps, bulk_fluid(ps, dx), dx);
}

template <int D>
Real water_level_at(const Particles<D>& ps, const std::vector<std::size_t>& bulk, Real dx, Real x,
                    Real y) {
    bool wet = false;
    Real top = -std::numeric_limits<Real>::infinity();
    for (std::size_t i : bulk) {
        if (std::abs(ps.x[i][0] - x) > dx || (D == 3 && std::abs(ps.x[i][1] - y) > dx))
            continue;
        top = std::max(top, ps.x[i][D - 1]);
        wet = true;
    }
    return wet ? top + dx / 2 : std::numeric_limits<Real>::quiet_NaN();
}

template <int D>
Real gauge_water_level(const Particles<D>& ps, Real dx, Real x, std::optional<Real> y) {
    const Real reach = gauge_bulk_reach * dx;
    std::vector<std::size_t> slab;
    for (std::size_t i = 0; i < ps.size(); ++i)
        if (ps.kind[i] == Kind::fluid && std::abs(ps.x[i][0] - x) <= reach &&
            !(D == 3 && y && std::abs(ps.x[i][1] - *y) > reach))
            slab.push_back(i);
    const auto bulk = bulk_fluid(ps, dx, slab);
    return D == 3 && y ? water_level_at(ps, bulk, dx, x, *y) : water_level(ps, bulk, dx, x);
}

template <int D>
FrontColumns<D>::FrontColumns(Real dx, int axis, bool negative)
    : dx_(dx), axis_(axis), depth_(axis == D - 1 ? 0 : D - 1), sign_(negative ? -1 : 1) {}

template <int D>
void FrontColumns<D>::add(const Particles<D>& ps, std::size_t end) {
    // Column key: the cell along every axis but `depth`.
    for (std::size_t i = 0; i < end; ++i) {
        if (ps.kind[i] != Kind::fluid)
            continue;
        CellKey<D> key;
        if (!cell_key_of<D>(ps.x[i], 1 / dx_, key))
            continue;
        key[static_cast<std::size_t>(depth_)] = 0;
        merge(key, Column{1, sign_ * ps.x[i][axis_]});
    }
}

template <int D>
void FrontColumns<D>::merge(const CellKey<D>& key, const Column& c) {
    Column& mine = columns_[key];
    mine.count += c.count;
    mine.furthest = std::max(mine.furthest, c.furthest);
}

template <int D>
Real FrontColumns<D>::front(Real min_thickness) const {
    const long needed = std::max(1L, std::lround(min_thickness / dx_));
    Real front = -std::numeric_limits<Real>::infinity();
    for (const auto& [key, c] : columns_)
        if (c.count >= needed)
            front = std::max(front, c.furthest);
    if (front == -std::numeric_limits<Real>::infinity())
        return std::numeric_limits<Real>::quiet_NaN();
    return sign_ * (front + dx_ / 2);
}

template <int D>
Real surge_front_directed(const Particles<D>& ps, Real dx, int axis, bool negative,
                          Real min_thickness) {
    FrontColumns<D> columns(dx, axis, negative);
    columns.add(ps, ps.size());
    return columns.front(min_thickness);
}

template Real water_level_at<2>(const Particles<2>&, const std::vector<std::size_t>&, Real, Real,
                                Real);
template Real water_level_at<3>(const Particles<3>&, const std::vector<std::size_t>&, Real, Real,
                                Real);
template Real surge_front_directed<2>(const Particles<2>&, Real, int, bool, Real);
template Real surge_front_directed<3>(const Particles<3>&, Real, int, bool, Real);
template std::vector<std::size_t> bulk_fluid<2>(const Particles<2>&, Real);
template std::vector<std::size_t> bulk_fluid<3>(const Particles<3>&, Real);
template std::vector<std::size_t> bulk_fluid<2>(const Particles<2>&, Real,
                                                const std::vector<std::size_t>&);
template std::vector<std::size_t> bulk_fluid<3>(const Particles<3>&, Real,
                                                const std::vector<std::size_t>&);
template Real gauge_water_level<2>(const Particles<2>&, Real, Real, std::optional<Real>);
template Real gauge_water_level<3>(const Particles<3>&, Real, Real, std::optional<Real>);
template class FrontColumns<2>;
template class FrontColumns<3>;
template Real water_level<2>(const Particles<2>&, Real, Real);
template Real water_level<3>(const Particles<3>&, Real, Real);
template Real water_level<2>(const Particles<2>&, const std::vector<std::size_t>&, Real, Real);
template Real water_level<3>(const Particles<3>&, const std::vector<std::size_t>&, Real, Real);
template Real surge_front<2>(const Particles<2>&, Real);
template Real surge_front<3>(const Particles<3>&, Real);
template Real surge_front<2>(const Particles<2>&, const std::vector<std::size_t>&, Real);
template Real surge_front<3>(const Particles<3>&, const std::vector<std::size_t>&, Real);
template Real pressure_probe<2, AnyKernel<2>>(const Particles<2>&, const AnyKernel<2>&,
                                              const Vec<2>&, Real);
template Real pressure_probe<3, AnyKernel<3>>(const Particles<3>&, const AnyKernel<3>&,
                                              const Vec<3>&, Real);

} // namespace sluice
