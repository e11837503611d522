#pragma once
// The halo fields of a step's exchanges (docs/ARCHITECTURE.md, "Halo exchanges"): what a
// stage's results travel as to the other ranks' next stages. A field is declared once, in the
// row of the stage that sends it (StageRow::sends, src/solver/step_scheme.hpp): its name, the
// particles it carries and the per-particle arrays it copies, in order; message sizes, packing
// and unpacking follow from that declaration, for every scheme. The state at the start of the
// step (HaloFields::state) is the one field every scheme sends first. Pure data movement
// between the arrays and byte buffers; the step graph decides when, MPI is the runtime's.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/cell_ranges.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/solver/halo_plan.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <cstring>
#include <optional>
#include <vector>

namespace sluice {

// One per-particle array that a halo field copies: a particle array, or a scheme's own array
// aligned with the particles (owned, then halo). Its element size, and the copies of element
// i to and from a buffer, each with the element's size known at compile time (a memcpy of a
// run-time size is a library call per element). The array is looked up at each use: it grows
// with the halo, and a swap of buffers leaves the vector where it is.
struct HaloColumn {
    std::size_t size = 0;
    void* array = nullptr; // the std::vector<T> it copies
    void (*put)(const void* array, std::size_t i, std::byte* to) = nullptr;
    void (*take)(void* array, std::size_t i, const std::byte* from) = nullptr;
};

template <class T>
HaloColumn halo_column(std::vector<T>& array) {
    return {sizeof(T), &array,
            [](const void* a, std::size_t i, std::byte* to) {
                const auto& v = *static_cast<const std::vector<T>*>(a);
                std::memcpy(to, static_cast<const void*>(&v[i]), sizeof(T));
            },
            [](void* a, std::size_t i, const std::byte* from) {
                auto& v = *static_cast<std::vector<T>*>(a);
                std::memcpy(static_cast<void*>(&v[i]), from, sizeof(T));
            }};
}

// A halo field: its exchange's name (traces, profiles), the particles it carries, and the
// arrays it copies of each, in order.
struct HaloField {
    const char* name = "?";
    std::optional<Kind> only;        // the particles it carries (all if empty)
    std::vector<HaloColumn> columns; // per particle, in this order
    // The state at the start of the step: it brings the halo particles (their kinds select
    // the particles of the later fields) and, on a rebuild, their cells' particle ranges.
    bool state = false;
};

// The halo data of one step graph: the fields of its exchanges, packed for and unpacked from
// the peers by the halo plan.
template <int D>
class HaloFields final : public tasks::HaloData {
public:
    std::vector<HaloField> exchanges; // per exchange of the graph (graph_of_rows)
    // Whether this step's state exchange records the halo cells' particle ranges: only on
    // steps that rebuild the neighbour lists (between rebuilds the particles stay where they
    // were sorted, although they may have moved into the next cell). Called by the main
    // thread before the step: it reserves room in `ranges` for a cell per halo particle (at
    // most), so that the unpacks, which run as concurrent tasks, insert without growing it.
    void record_halo_cells(bool rebuilt) {
        assign_cells_ = rebuilt;
        if (rebuilt) {
            std::size_t halo = 0;
            for (const std::size_t n : plan_.recv_count)
                halo += n;
            ranges_.reserve(halo);
        }
    }

    // reference_positions: with a Verlet skin, the state carries x_ref and the halo cells
    // are those of x_ref (the positions the particles were sorted by).
    HaloFields(Particles<D>& P, CellRanges& ranges, const CellGrid<D>& grid, const HaloPlan& plan,
               bool reference_positions)
        : P_(P), ranges_(ranges), grid_(grid), plan_(plan), reference_(reference_positions) {}

    // The state at the start of the step: id, kind, x, v, rho, mass (and x_ref with a skin).
    [[nodiscard]] HaloField state() const {
        HaloField f{"state",
                    std::nullopt,
                    {halo_column(P_.id), halo_column(P_.kind), halo_column(P_.x), halo_column(P_.v),
                     halo_column(P_.rho), halo_column(P_.mass)},
                    true};
        if (reference_)
            f.columns.push_back(halo_column(P_.x_ref));
        return f;
    }

    [[nodiscard]] std::size_t recv_bytes(int e, int p) const override {
        const auto k = static_cast<std::size_t>(p);
        return bytes(exchanges[static_cast<std::size_t>(e)], plan_.recv_count[k],
                     plan_.recv_walls[k]);
    }

    void pack(int e, int p, tasks::Bytes& out) override {
        const HaloField& f = exchanges[static_cast<std::size_t>(e)];
        const auto k = static_cast<std::size_t>(p);
        out.reserve(out.size() + bytes(f, plan_.send_count[k], plan_.send_walls[k]));
        const std::size_t row = row_bytes(f);
        for (CellIndex c : plan_.send_cells[k])
            for (std::uint32_t i = ranges_.begin(c), stop = ranges_.end(c); i < stop; ++i)
                if (!f.only || P_.kind[i] == *f.only) {
                    const std::size_t n = out.size();
                    out.resize(n + row);
                    std::byte* to = out.data() + n;
                    for (const HaloColumn& col : f.columns) {
                        col.put(col.array, i, to);
                        to += col.size;
                    }
                }
    }

    void unpack(int e, int p, std::span<const std::byte> in) override {
        const HaloField& f = exchanges[static_cast<std::size_t>(e)];
        const auto k = static_cast<std::size_t>(p);
        const std::size_t first = plan_.recv_offset[k], last = first + plan_.recv_count[k];
        const std::byte* from = in.data();
        // The state exchange brings each halo particle's kind, which selects the particles of
        // the later fields.
        for (std::size_t i = first; i < last; ++i)
            if (!f.only || P_.kind[i] == *f.only)
                for (const HaloColumn& col : f.columns) {
                    col.take(col.array, i, from);
                    from += col.size;
                }
        if (f.state && assign_cells_)
            assign_halo_cells(first, last);
    }

private:
    // Bytes of one exchange of `f` for n particles of which w are walls.
    [[nodiscard]] static std::size_t bytes(const HaloField& f, std::size_t n, std::size_t w) {
        const std::size_t count = !f.only ? n : *f.only == Kind::wall ? w : n - w;
        return count * row_bytes(f);
    }
    // Bytes of one particle's row of `f`.
    [[nodiscard]] static std::size_t row_bytes(const HaloField& f) {
        std::size_t row = 0;
        for (const HaloColumn& col : f.columns)
            row += col.size;
        return row;
    }

    // The halo cells' particle ranges, by the cells of the sort (the positions of the last
    // rebuild).
    void assign_halo_cells(std::size_t first, std::size_t last) {
        const std::vector<Vec<D>>& sorted_by = reference_ ? P_.x_ref : P_.x;
        // The peer sent whole cells in key order: each halo cell is one contiguous run.
        for (std::size_t i = first; i < last;) {
            const CellIndex c = grid_.linear(grid_.coords(sorted_by[i]));
            std::size_t j = i + 1;
            while (j < last && grid_.linear(grid_.coords(sorted_by[j])) == c)
                ++j;
            ranges_.set(c, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
            i = j;
        }
    }

    Particles<D>& P_;
    CellRanges& ranges_;
    const CellGrid<D>& grid_;
    const HaloPlan& plan_;
    bool reference_;
    bool assign_cells_ = false; // record_halo_cells
};

} // namespace sluice
