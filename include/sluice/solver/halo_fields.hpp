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
// Pure data movement between the particle arrays and byte buffers; the step graph decides
// when, MPI is the runtime's.
#include "sluice/core/cell_grid.hpp"
#include "sluice/core/particles.hpp"
#include "sluice/solver/halo_plan.hpp"
#include "sluice/tasks/step_graph.hpp"

#include <vector>

namespace sluice {

template <int D>
class HaloFields final : public tasks::HaloData {
public:
    enum class What { state, pressure, walls, velocity };
    std::vector<What> what; // per exchange of the graph
    // The exchange's name in traces and profiles.
    static const char* name(What w) {
        switch (w) {
        case What::state:
            return "state";
        case What::pressure:
            return "pressure";
        case What::walls:
            return "walls";
        case What::velocity:
            return "velocity";
        }
        return "?";
    }
    // Whether the state exchange records the halo cells' particle ranges: only on steps that
    // rebuild the neighbour lists (between rebuilds the particles stay where they were sorted,
    // although they may have moved into the next cell).
    bool assign_cells = true;

    HaloFields(Particles<D>& P, CellRanges& ranges, const CellGrid<D>& grid, const HaloPlan& plan,
               bool summation, bool gradient, bool reference_positions)
        : P_(P), ranges_(ranges), grid_(grid), plan_(plan), summation_(summation),
          gradient_(gradient), reference_(reference_positions) {}

    [[nodiscard]] std::size_t recv_bytes(int e, int p) const override {
        const auto k = static_cast<std::size_t>(p);
        return bytes(what[static_cast<std::size_t>(e)], plan_.recv_count[k], plan_.recv_walls[k]);
    }

    void pack(int e, int p, tasks::Bytes& out) override {
        using tasks::put;
        const What kind = what[static_cast<std::size_t>(e)];
        const auto k = static_cast<std::size_t>(p);
        out.reserve(bytes(kind, plan_.send_count[k], plan_.send_walls[k]));
        for (CellIndex c : plan_.send_cells[k])
            for (std::uint32_t i = ranges_.begin[c]; i < ranges_.end[c]; ++i)
                switch (kind) {
                case What::state:
                    put(out, P_.id[i]);
                    put(out, P_.kind[i]);
                    put(out, P_.x[i]);
                    put(out, P_.v[i]);
                    put(out, P_.rho[i]);
                    put(out, P_.mass[i]);
                    if (reference_)
                        put(out, P_.x_ref[i]);
                    break;
                case What::pressure:
                    put(out, P_.p[i]);
                    put(out, P_.p_over_rho2[i]);
                    put(out, P_.volume[i]);
                    if (summation_)
                        put(out, P_.rho[i]);
                    if (gradient_)
                        put(out, P_.grad_rho[i]);
                    break;
                case What::walls:
                    if (P_.kind[i] != Kind::wall)
                        break;
                    put(out, P_.p[i]);
                    put(out, P_.rho[i]);
                    put(out, P_.mass[i]);
                    put(out, P_.v_bc[i]);
                    break;
                case What::velocity:
                    if (P_.kind[i] == Kind::fluid)
                        put(out, P_.v_half[i]);
                    break;
                }
    }

    void unpack(int e, int p, std::span<const std::byte> in) override {
        using tasks::take_into;
        const auto k = static_cast<std::size_t>(p);
        const std::size_t first = plan_.recv_offset[k], last = first + plan_.recv_count[k];
        std::size_t pos = 0;
        switch (what[static_cast<std::size_t>(e)]) {
        case What::state: {
            for (std::size_t i = first; i < last; ++i) {
                take_into(in, pos, P_.id[i]);
                take_into(in, pos, P_.kind[i]);
                take_into(in, pos, P_.x[i]);
                take_into(in, pos, P_.v[i]);
                take_into(in, pos, P_.rho[i]);
                take_into(in, pos, P_.mass[i]);
                if (reference_)
                    take_into(in, pos, P_.x_ref[i]);
            }
            // Cells of the sort: by the positions of the last rebuild.
            const std::vector<Vec<D>>& sorted_by = reference_ ? P_.x_ref : P_.x;
            // The peer sent whole cells in key order: each halo cell is one contiguous run.
            for (std::size_t i = first; assign_cells && i < last;) {
                const CellIndex c = grid_.linear(grid_.coords(sorted_by[i]));
                std::size_t j = i + 1;
                while (j < last && grid_.linear(grid_.coords(sorted_by[j])) == c)
                    ++j;
                ranges_.begin[c] = static_cast<std::uint32_t>(i);
                ranges_.end[c] = static_cast<std::uint32_t>(j);
                i = j;
            }
            break;
        }
        case What::pressure:
            for (std::size_t i = first; i < last; ++i) {
                take_into(in, pos, P_.p[i]);
                take_into(in, pos, P_.p_over_rho2[i]);
                take_into(in, pos, P_.volume[i]);
                if (summation_)
                    take_into(in, pos, P_.rho[i]);
                if (gradient_)
                    take_into(in, pos, P_.grad_rho[i]);
            }
            break;
        case What::walls:
            for (std::size_t i = first; i < last; ++i)
                if (P_.kind[i] == Kind::wall) {
                    take_into(in, pos, P_.p[i]);
                    take_into(in, pos, P_.rho[i]);
                    take_into(in, pos, P_.mass[i]);
                    take_into(in, pos, P_.v_bc[i]);
                }
            break;
        case What::velocity:
            for (std::size_t i = first; i < last; ++i)
                if (P_.kind[i] == Kind::fluid)
                    take_into(in, pos, P_.v_half[i]);
            break;
        }
    }

private:
    // Bytes of one exchange for n particles of which w are walls.
    [[nodiscard]] std::size_t bytes(What kind, std::size_t n, std::size_t w) const {
        switch (kind) {
        case What::state:
            return n * (sizeof(ParticleId) + sizeof(Kind) + (reference_ ? 3 : 2) * sizeof(Vec<D>) +
                        2 * sizeof(Real));
        case What::pressure:
            return n * (3 * sizeof(Real) + (summation_ ? sizeof(Real) : 0) +
                        (gradient_ ? sizeof(Vec<D>) : 0));
        case What::walls:
            return w * (3 * sizeof(Real) + sizeof(Vec<D>));
        case What::velocity:
            return (n - w) * sizeof(Vec<D>);
        }
        return 0;
    }

    Particles<D>& P_;
    CellRanges& ranges_;
    const CellGrid<D>& grid_;
    const HaloPlan& plan_;
    bool summation_, gradient_, reference_;
};

} // namespace sluice
