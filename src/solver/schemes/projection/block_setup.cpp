// The block-Jacobi preconditioner's set-up (projection.preconditioner = "block_lu" or
// "block_ilu0"; docs/PROJECTION.md, "Preconditioner"): each group's diagonal block of the scaled
// system as compressed rows, factorised by block_preconditioner.cpp. Apart from the solver
// loop (projection_solver.cpp) because it runs once per step, per group, before it.
#include "projection_scheme.hpp"

#include <cstdint>
#include <vector>

namespace sluice {

// The block-Jacobi preconditioner of one group (projection.preconditioner = "block_lu" or
// "block_ilu0"): the rows of the group's particles of A = I - [a_ij], columns of the same group
// only, factorised.
// Rows without an entry in the block that no other row of the block refers to (wall particles
// away from the fluid) are identity rows that decouple: they are left out of the factorised
// block (z_i = r_i), which is then mostly the fluid rows and the walls next to them.
template <int D>
void ProjectionScheme<D>::factor_block(int group) {
    ProjectionData<D>& d = *proj_;
    const auto gi = static_cast<std::size_t>(group);
    ProjectionGroup<D>& G = d.groups[gi];
    const NeighbourList<D>& list = neighbours_.lists[gi];
    const std::uint32_t lo = list.first;
    const auto hi = static_cast<std::uint32_t>(list.first + list.offset.size() - 1);
    const auto in_block = [&](std::uint32_t i, std::uint32_t p) {
        const std::uint32_t j = list.j[p];
        return j >= lo && j < hi && j != i && G.a[p] != 0;
    };
    G.block_index.assign(hi - lo, -1);
    for (std::uint32_t i = lo; i < hi; ++i)
        for (std::uint32_t p = list.offset[i - lo]; p < list.offset[i - lo + 1]; ++p)
            if (in_block(i, p)) {
                G.block_index[i - lo] = 0;
                G.block_index[list.j[p] - lo] = 0;
            }
    std::int32_t n = 0;
    for (auto& b : G.block_index)
        if (b == 0)
            b = n++;
    // Compressed rows straight from the neighbour list: each row's entries sorted by column
    // (a stable insertion sort: a row holds ~30 entries in the list's scan order, nearly
    // sorted), duplicate columns (none unless a periodic image repeats) summed in list order.
    BlockRows& m = G.block_rows;
    m.outer.assign(1, 0);
    m.col.clear();
    m.val.clear();
    for (std::uint32_t i = lo; i < hi; ++i) {
        const std::int32_t k = G.block_index[i - lo];
        if (k < 0)
            continue;
        const std::size_t start = m.col.size();
        m.col.push_back(k);
        m.val.push_back(1.0);
        for (std::uint32_t p = list.offset[i - lo]; p < list.offset[i - lo + 1]; ++p) {
            if (!in_block(i, p))
                continue;
            const int c = G.block_index[list.j[p] - lo];
            const double v = -double(G.a[p]);
            std::size_t at = m.col.size();
            m.col.push_back(c);
            m.val.push_back(v);
            for (; at > start && m.col[at - 1] > c; --at) {
                m.col[at] = m.col[at - 1];
                m.val[at] = m.val[at - 1];
            }
            m.col[at] = c;
            m.val[at] = v;
        }
        std::size_t last = start;
        for (std::size_t q = start + 1; q < m.col.size(); ++q) {
            if (m.col[q] == m.col[last]) {
                m.val[last] += m.val[q];
                continue;
            }
            ++last;
            m.col[last] = m.col[q];
            m.val[last] = m.val[q];
        }
        m.col.resize(last + 1);
        m.val.resize(last + 1);
        m.outer.push_back(static_cast<int>(m.col.size()));
    }
    G.block.factor(m, case_.cfg.projection.preconditioner == PressurePreconditioner::block_lu
                          ? BlockMethod::lu
                          : BlockMethod::ilu0);
}

template void ProjectionScheme<2>::factor_block(int);
template void ProjectionScheme<3>::factor_block(int);

} // namespace sluice
