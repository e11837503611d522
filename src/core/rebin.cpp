#include "sluice/core/rebin.hpp"

#include <algorithm>

namespace sluice {

template <int D>
bool Rebinner<D>::operator()(const CellGrid<D>& grid, Particles<D>& P, CellRanges& ranges,
                             std::vector<CellOccupancy>& occupied) {
    const std::size_t n = P.size();
    key_.resize(n);
    cell_.resize(n);
    bool sorted = true;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = grid.coords(P.x[i]);
        key_[i] = grid.morton(c);
        cell_[i] = grid.linear(c);
        if (i > 0 && (key_[i] < key_[i - 1] || (key_[i] == key_[i - 1] && P.id[i] < P.id[i - 1])))
            sorted = false;
    }
    if (!sorted) {
        // Counting sort by cell, cells taken in Morton order, stable. The few particles that
        // entered a cell this step then sit among its others in storage order, so each cell's
        // run is put back in id order by an insertion sort (nearly sorted). The sort's slots
        // are the distinct keys present (a key is a cell), found from the runs of equal keys
        // of the previous order: O(n + cells log cells) in the rank's particles and occupied
        // cells, nothing per cell of the grid.
        distinct_.clear();
        for (std::size_t i = 0; i < n; ++i)
            if (i == 0 || key_[i] != key_[i - 1])
                distinct_.push_back(key_[i]);
        std::sort(distinct_.begin(), distinct_.end());
        distinct_.erase(std::unique(distinct_.begin(), distinct_.end()), distinct_.end());
        place_.resize(n);
        start_.assign(distinct_.size(), 0);
        // A run's key is mostly the one after the previous run's (the order is nearly
        // sorted): that is checked before a binary search.
        for (std::size_t i = 0; i < n; ++i) {
            if (i > 0 && key_[i] == key_[i - 1]) {
                place_[i] = place_[i - 1];
            } else {
                const std::size_t next = i > 0 ? place_[i - 1] + std::size_t{1} : 0;
                place_[i] = static_cast<std::uint32_t>(
                    next < distinct_.size() && distinct_[next] == key_[i]
                        ? next
                        : std::lower_bound(distinct_.begin(), distinct_.end(), key_[i]) -
                              distinct_.begin());
            }
            ++start_[place_[i]];
        }
        std::uint32_t running = 0;
        for (std::uint32_t& s : start_) {
            const std::uint32_t count = s;
            s = running;
            running += count;
        }
        perm_.resize(n);
        for (std::size_t i = 0; i < n; ++i)
            perm_[start_[place_[i]]++] = i;
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
    std::size_t runs = 0;
    for (std::size_t i = 0; i < n; ++i)
        runs += i == 0 || cell_[i] != cell_[i - 1] ? 1 : 0;
    ranges.reset(runs);
    occupied.clear();
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i;
        while (j < n && cell_[j] == cell_[i])
            ++j;
        ranges.set(cell_[i], static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
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
