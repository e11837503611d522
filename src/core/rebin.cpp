#include "sluice/core/rebin.hpp"

#include <algorithm>
#include <numeric>

namespace sluice {

template <int D>
bool rebin(const CellGrid<D>& grid, Particles<D>& P, CellRanges& ranges,
           std::vector<CellOccupancy>& occupied) {
    const std::size_t n = P.size();
    std::vector<MortonKey> key(n);
    std::vector<CellIndex> cell(n);
    bool sorted = true;
    for (std::size_t i = 0; i < n; ++i) {
        const auto c = grid.coords(P.x[i]);
        key[i] = grid.morton(c);
        cell[i] = grid.linear(c);
        if (i > 0 && (key[i] < key[i - 1] || (key[i] == key[i - 1] && P.id[i] < P.id[i - 1])))
            sorted = false;
    }
    if (!sorted) {
        std::vector<std::size_t> perm(n);
        std::iota(perm.begin(), perm.end(), std::size_t{0});
        std::sort(perm.begin(), perm.end(), [&](std::size_t a, std::size_t b) {
            return key[a] != key[b] ? key[a] < key[b] : P.id[a] < P.id[b];
        });
        P.permute(perm);
        std::vector<MortonKey> k2(n);
        std::vector<CellIndex> c2(n);
        for (std::size_t i = 0; i < n; ++i) {
            k2[i] = key[perm[i]];
            c2[i] = cell[perm[i]];
        }
        key.swap(k2);
        cell.swap(c2);
    }
    ranges.begin.assign(grid.cell_count(), 0);
    ranges.end.assign(grid.cell_count(), 0);
    occupied.clear();
    for (std::size_t i = 0; i < n;) {
        std::size_t j = i;
        while (j < n && cell[j] == cell[i])
            ++j;
        ranges.begin[cell[i]] = static_cast<std::uint32_t>(i);
        ranges.end[cell[i]] = static_cast<std::uint32_t>(j);
        occupied.push_back({cell[i], key[i], static_cast<std::uint32_t>(j - i)});
        i = j;
    }
    return !sorted;
}

template bool rebin<2>(const CellGrid<2>&, Particles<2>&, CellRanges&, std::vector<CellOccupancy>&);
template bool rebin<3>(const CellGrid<3>&, Particles<3>&, CellRanges&, std::vector<CellOccupancy>&);

} // namespace sluice
