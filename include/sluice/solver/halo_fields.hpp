#pragma once
// The particle fields of the halo exchanges of one step (docs/ARCHITECTURE.md, "Halo
// exchanges"). Each carries what the next stage reads of particles owned by a peer:
//   state     (start of step)  id, kind, x, v, rho, mass,        -> density, walls, accel
//                              x_ref (with a Verlet skin)
//   pressure  (after density)  p, p/rho^2, m/rho, and rho        -> walls, accel, drift
//                              (summation) or the renormalised
//                              grad rho (delta-SPH)
//   walls     (after walls)    wall particles: p, rho, mass, v_bc -> accel
//   velocity  (after kick)     fluid particles: v^{n+1/2}         -> drift (continuity)
// Each field is one row of a table (the constructor): the particles it carries and the
// particle arrays it copies, in order; sizes, packing and unpacking follow from the row.
// Pure data movement between the particle arrays and byte buffers; the step graph decides
// when, MPI is the runtime's.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/solver/halo_plan.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <array>
#include <cstring>
#include <optional>
#include <type_traits>
#include <vector>

namespace sluice {

template <int D>
class HaloFields final : public tasks::HaloData {
public:
    enum class What { state, pressure, walls, velocity };
    std::vector<What> what; // per exchange of the graph
    // The exchange's name in traces and profiles.
    [[nodiscard]] const char* name(What w) const { return field(w).name; }
    // Whether the state exchange records the halo cells' particle ranges: only on steps that
    // rebuild the neighbour lists (between rebuilds the particles stay where they were sorted,
    // although they may have moved into the next cell).
    bool assign_cells = true;

    HaloFields(Particles<D>& P, CellRanges& ranges, const CellGrid<D>& grid, const HaloPlan& plan,
               bool summation, bool gradient, bool reference_positions)
        : P_(P), ranges_(ranges), grid_(grid), plan_(plan), reference_(reference_positions) {
        using PD = Particles<D>;
        Field& state = fields_[static_cast<std::size_t>(What::state)];
        state = {"state",
                 std::nullopt,
                 {column<&PD::id>(), column<&PD::kind>(), column<&PD::x>(), column<&PD::v>(),
                  column<&PD::rho>(), column<&PD::mass>()}};
        if (reference_)
            state.columns.push_back(column<&PD::x_ref>());
        Field& pressure = fields_[static_cast<std::size_t>(What::pressure)];
        pressure = {"pressure",
                    std::nullopt,
                    {column<&PD::p>(), column<&PD::p_over_rho2>(), column<&PD::volume>()}};
        if (summation)
            pressure.columns.push_back(column<&PD::rho>());
        if (gradient)
            pressure.columns.push_back(column<&PD::grad_rho>());
        fields_[static_cast<std::size_t>(What::walls)] = {
            "walls",
            Kind::wall,
            {column<&PD::p>(), column<&PD::rho>(), column<&PD::mass>(), column<&PD::v_bc>()}};
        fields_[static_cast<std::size_t>(What::velocity)] = {
            "velocity", Kind::fluid, {column<&PD::v_half>()}};
    }

    [[nodiscard]] std::size_t recv_bytes(int e, int p) const override {
        const auto k = static_cast<std::size_t>(p);
        return bytes(field(what[static_cast<std::size_t>(e)]), plan_.recv_count[k],
                     plan_.recv_walls[k]);
    }

    void pack(int e, int p, tasks::Bytes& out) override {
        const Field& f = field(what[static_cast<std::size_t>(e)]);
        const auto k = static_cast<std::size_t>(p);
        out.reserve(out.size() + bytes(f, plan_.send_count[k], plan_.send_walls[k]));
        const std::size_t row = row_bytes(f);
        for (CellIndex c : plan_.send_cells[k])
            for (std::uint32_t i = ranges_.begin[c]; i < ranges_.end[c]; ++i)
                if (!f.only || P_.kind[i] == *f.only) {
                    const std::size_t n = out.size();
                    out.resize(n + row);
                    std::byte* to = out.data() + n;
                    for (const Column& col : f.columns) {
                        col.put(P_, i, to);
                        to += col.size;
                    }
                }
    }

    void unpack(int e, int p, std::span<const std::byte> in) override {
        const What w = what[static_cast<std::size_t>(e)];
        const Field& f = field(w);
        const auto k = static_cast<std::size_t>(p);
        const std::size_t first = plan_.recv_offset[k], last = first + plan_.recv_count[k];
        const std::byte* from = in.data();
        // The state exchange brings each halo particle's kind, which selects the particles of
        // the later fields.
        for (std::size_t i = first; i < last; ++i)
            if (!f.only || P_.kind[i] == *f.only)
                for (const Column& col : f.columns) {
                    col.take(P_, i, from);
                    from += col.size;
                }
        if (w == What::state && assign_cells)
            assign_halo_cells(first, last);
    }

private:
    // One particle array a field copies: its element size, and the copies of particle i's
    // element to and from a buffer, each with the element's size known at compile time (a
    // memcpy of a run-time size is a library call per element). The arrays are looked up at
    // each use: they grow with the halo.
    struct Column {
        std::size_t size;
        void (*put)(const Particles<D>&, std::size_t, std::byte*);
        void (*take)(Particles<D>&, std::size_t, const std::byte*);
    };
    template <auto Member>
    static Column column() {
        using Element = typename std::remove_reference_t<decltype(std::declval<Particles<D>&>().*
                                                                  Member)>::value_type;
        return {sizeof(Element),
                [](const Particles<D>& P, std::size_t i, std::byte* to) {
                    std::memcpy(to, static_cast<const void*>(&(P.*Member)[i]), sizeof(Element));
                },
                [](Particles<D>& P, std::size_t i, const std::byte* from) {
                    std::memcpy(static_cast<void*>(&(P.*Member)[i]), from, sizeof(Element));
                }};
    }
    struct Field {
        const char* name = "?";
        std::optional<Kind> only; // the particles it carries (all if empty)
        std::vector<Column> columns;
    };
    [[nodiscard]] const Field& field(What w) const { return fields_[static_cast<std::size_t>(w)]; }

    // Bytes of one exchange of `f` for n particles of which w are walls.
    [[nodiscard]] static std::size_t bytes(const Field& f, std::size_t n, std::size_t w) {
        const std::size_t count = !f.only ? n : *f.only == Kind::wall ? w : n - w;
        return count * row_bytes(f);
    }
    // Bytes of one particle's row of `f`.
    [[nodiscard]] static std::size_t row_bytes(const Field& f) {
        std::size_t row = 0;
        for (const Column& col : f.columns)
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
            ranges_.begin[c] = static_cast<std::uint32_t>(i);
            ranges_.end[c] = static_cast<std::uint32_t>(j);
            i = j;
        }
    }

    Particles<D>& P_;
    CellRanges& ranges_;
    const CellGrid<D>& grid_;
    const HaloPlan& plan_;
    bool reference_;
    std::array<Field, 4> fields_; // per What
};

} // namespace sluice
