#include "sluice/core/cell_grid.hpp"

#include <cmath>
#include <stdexcept>

namespace sluice {

template <int D>
CellGrid<D> CellGrid<D>::make(const Vec<D>& lo, const Vec<D>& hi, Real min_edge,
                              const std::array<bool, D>& periodic) {
    CellGrid g;
    g.lo = lo;
    g.length = hi - lo;
    g.periodic = periodic;
    for (int d = 0; d < D; ++d) {
        int n = static_cast<int>(std::floor(g.length[d] / min_edge));
        if (n < 1)
            n = 1;
        if (periodic[d] && n < 3)
            throw std::invalid_argument("periodic axis shorter than 3 kernel supports");
        // Morton keys interleave 21 bits per axis in 3-D (63 of a 64-bit key) and 32 in 2-D
        // (where `int` cells per axis is the tighter bound).
        if (D == 3 && n > (1 << 21))
            throw std::invalid_argument("grid: more than 2^21 cells along an axis in 3-D");
        g.dims[d] = n;
        g.edge[d] = g.length[d] / Real(n);
        g.inv_edge[d] = 1 / g.edge[d];
    }
    return g;
}

template <int D>
int adjacent_cells(const CellGrid<D>& grid, CellIndex c, NeighbourCell<D>* out) {
    const std::array<int, D> base = grid.unlinear(c);
    int count = 0;
    constexpr int total = D == 2 ? 9 : 27;
    for (int k = 0; k < total; ++k) {
        std::array<int, D> nc{};
        Vec<D> shift = Vec<D>::Zero();
        bool inside = true;
        int rest = k;
        for (int d = 0; d < D; ++d) {
            const int off = rest % 3 - 1;
            rest /= 3;
            int v = base[d] + off;
            if (v < 0 || v >= grid.dims[d]) {
                if (!grid.periodic[d]) {
                    inside = false;
                    break;
                }
                // The image of the wrapped cell lies one period beyond: x_i - x_j gains
                // +length when we wrapped below 0, -length above.
                shift[d] = v < 0 ? grid.length[d] : -grid.length[d];
                v = v < 0 ? v + grid.dims[d] : v - grid.dims[d];
            }
            nc[d] = v;
        }
        if (!inside)
            continue;
        out[count++] = NeighbourCell<D>{grid.linear(nc), shift};
    }
    return count;
}

template int adjacent_cells<2>(const CellGrid<2>&, CellIndex, NeighbourCell<2>*);
template int adjacent_cells<3>(const CellGrid<3>&, CellIndex, NeighbourCell<3>*);

template struct CellGrid<2>;
template struct CellGrid<3>;

} // namespace sluice
