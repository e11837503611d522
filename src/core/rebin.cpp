#include "sluice/core/rebin.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace sluice {

template <int D>
void Rebinner<D>::prepare(const CellGrid<D>& grid) {
    if (!morton_order_.empty() && grid.dims == dims_)
        return;
    dims_ = grid.dims;
    const std::size_t cells = grid.cell_count();
    std::vector<MortonKey> key(cells);
    for (std::size_t c = 0; c < cells; ++c)
        key[c] = grid.morton(grid.unlinear(static_cast<CellIndex>(c)));
    morton_order_.resize(cells);
    std::iota(morton_order_.begin(), morton_order_.end(), CellIndex{0});
    std::sort(morton_order_.begin(), morton_order_.end(),
              [&](CellIndex a, CellIndex b) { return key[a] < key[b]; });
    morton_keys_.resize(cells);
    for (std::size_t k = 0; k < cells; ++k)
        morton_keys_[k] = key[morton_order_[k]];
    start_.assign(cells, 0);
}

template <int D>
bool Rebinner<D>::operator()(const CellGrid<D>& grid, Particles<D>& P, CellRanges& ranges,
                             std::vector<CellOccupancy>& occupied) {
    prepare(grid);
    const std::size_t n = P.size();
    key_.resize(n);
    cell_.resize(n);
    bool sorted = true;
    MortonKey lowest = std::numeric_limits<MortonKey>::max(), highest = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = grid.coords(P.x[i]);
        key_[i] = grid.morton(c);
        cell_[i] = grid.linear(c);
        lowest = std::min(lowest, key_[i]);
        highest = std::max(highest, key_[i]);
        if (i > 0 && (key_[i] < key_[i - 1] || (key_[i] == key_[i - 1] && P.id[i] < P.id[i - 1])))
            sorted = false;
    }
    if (!sorted) {
        // Counting sort by cell, cells taken in Morton order, stable. The few particles that
        // entered a cell this step then sit among its others in storage order, so each cell's
        // run is put back in id order by an insertion sort (nearly sorted). Only the cells
        // between the lowest and the highest key present are walked: a rank's particles lie
        // in its own stretch of the curve (plus a little for those about to leave), so the
        // sort costs O(n + the rank's cells), not O(n + the grid's).
        for (std::size_t i = 0; i < n; ++i)
            ++start_[cell_[i]];
        const auto from = std::lower_bound(morton_keys_.begin(), morton_keys_.end(), lowest);
        const auto to = std::upper_bound(from, morton_keys_.end(), highest);
        const auto first = static_cast<std::size_t>(from - morton_keys_.begin());
        const auto last = static_cast<std::size_t>(to - morton_keys_.begin());
        std::uint32_t running = 0;
        for (std::size_t k = first; k < last; ++k) {
            const CellIndex c = morton_order_[k];
            const std::uint32_t count = start_[c];
            if (count == 0)
                continue; // empty cells keep their zero
            start_[c] = running;
            running += count;
        }
        perm_.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            perm_[start_[cell_[i]]++] = i;
        for (std::size_t i = 0; i < n; ++i)
            start_[cell_[i]] = 0; // back to all zeros for the next call
        for (std::size_t b = 0; b < n;) {
            std::size_t e = b + 1;
            while (e < n && cell_[perm_[e]] == cell_[perm_[b]])
                ++e;
            for (std::size_t k = b + 1; k < e; ++k) {
                const std::size_t moving = perm_[k];
                std::size_t m = k;
                for (; m > b && P.id[perm_[m - 1]] > P.id[moving]; --m)
                    perm_[m] = perm_[m - 1];
                perm_[m] = moving;
            }
            b = e;
        }
        P.permute(perm_);
        key_sorted_.resize(n);
        cell_sorted_.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            key_sorted_[i] = key_[perm_[i]];
            cell_sorted_[i] = cell_[perm_[i]];
        }
        key_.swap(key_sorted_);
        cell_.swap(cell_sorted_);
    }
    ranges.reset(grid.cell_count());
    occupied.clear();
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i;
        while (j < n && cell_[j] == cell_[i])
            ++j;
        ranges.begin[cell_[i]] = static_cast<std::uint32_t>(i);
        ranges.end[cell_[i]] = static_cast<std::uint32_t>(j);
        ranges.owned_cells.push_back(cell_[i]);
        occupied.push_back({cell_[i], key_[i], static_cast<std::uint32_t>(j - i)});
        i = j;
    }
    return !sorted;
}

template <int D>
bool rebin(const CellGrid<D>& grid, Particles<D>& P, CellRanges& ranges,
           std::vector<CellOccupancy>& occupied) {
    Rebinner<D> r;
    return r(grid, P, ranges, occupied);
}

template class Rebinner<2>;
template class Rebinner<3>;
template bool rebin<2>(const CellGrid<2>&, Particles<2>&, CellRanges&, std::vector<CellOccupancy>&);
template bool rebin<3>(const CellGrid<3>&, Particles<3>&, CellRanges&, std::vector<CellOccupancy>&);

} // namespace sluice
