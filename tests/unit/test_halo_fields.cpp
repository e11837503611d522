// Halo fields as a stage row declares them (include/sluice/solver/halo_fields.hpp): the
// particles a field carries and the arrays it copies, a particle array or a scheme's own, make
// the message's size, its packing and its unpacking.
#include "sluice/solver/halo_fields.hpp"

#include <doctest/doctest.h>

#include <vector>

namespace sluice {
namespace {

// A sender holding three particles in one cell (fluid, wall, fluid) and a receiver whose halo
// holds the same three at offset 0, with the kinds its state exchange brought.
struct Pair {
    CellGrid<2> grid = CellGrid<2>::make(Vec<2>(0, 0), Vec<2>(1, 1), Real(0.5), {false, false});
    Particles<2> from, to;
    CellRanges from_ranges, to_ranges;
    HaloPlan plan;

    Pair() {
        const std::vector<Kind> kinds{Kind::fluid, Kind::wall, Kind::fluid};
        for (Particles<2>* P : {&from, &to}) {
            P->resize(3);
            P->kind = kinds;
        }
        for (std::size_t i = 0; i < 3; ++i) {
            from.id[i] = static_cast<ParticleId>(10 + i);
            from.x[i] = Vec<2>(Real(0.1) * Real(i + 1), Real(0.2));
            from.p[i] = Real(100 + i);
            from.v_half[i] = Vec<2>(Real(i), Real(-1));
        }
        const CellIndex cell = grid.linear(grid.coords(from.x[0]));
        for (CellRanges* r : {&from_ranges, &to_ranges})
            r->reset(1);
        from_ranges.set(cell, 0, 3);
        plan.send_cells = {{cell}};
        plan.send_count = {3};
        plan.send_walls = {1};
        plan.recv_count = {3};
        plan.recv_walls = {1};
        plan.recv_offset = {0};
    }

    // Sends `sent` (the sender's declaration) and receives `received` (the receiver's).
    std::size_t exchange(const HaloField& sent, const HaloField& received) {
        HaloFields<2> out(from, from_ranges, grid, plan, false);
        HaloFields<2> in(to, to_ranges, grid, plan, false);
        in.record_halo_cells(true);
        out.exchanges = {sent};
        in.exchanges = {received};
        tasks::Bytes bytes;
        out.pack(0, 0, bytes);
        CHECK(bytes.size() == in.recv_bytes(0, 0));
        in.unpack(0, 0, bytes);
        return bytes.size();
    }
};

TEST_CASE("a field of the walls carries the wall particles' arrays only") {
    Pair pair;
    const std::size_t bytes =
        pair.exchange(HaloField{"walls", Kind::wall, {halo_column(pair.from.p)}},
                      HaloField{"walls", Kind::wall, {halo_column(pair.to.p)}});
    CHECK(bytes == sizeof(Real));
    CHECK(pair.to.p[0] == 0);
    CHECK(pair.to.p[1] == Real(101));
    CHECK(pair.to.p[2] == 0);
}

TEST_CASE("a field copies a scheme's own per-particle array like a particle array") {
    Pair pair;
    std::vector<Vec<2>> sent{Vec<2>(1, 2), Vec<2>(3, 4), Vec<2>(5, 6)};
    std::vector<Vec<2>> received(3, Vec<2>::Zero());
    const std::size_t bytes =
        pair.exchange(HaloField{"u_star", std::nullopt, {halo_column(sent)}},
                      HaloField{"u_star", std::nullopt, {halo_column(received)}});
    CHECK(bytes == 3 * sizeof(Vec<2>));
    CHECK(received == sent);
}

TEST_CASE("columns travel in their declared order, fluid particles only when asked") {
    Pair pair;
    const std::size_t bytes = pair.exchange(
        HaloField{
            "velocity", Kind::fluid, {halo_column(pair.from.v_half), halo_column(pair.from.p)}},
        HaloField{"velocity", Kind::fluid, {halo_column(pair.to.v_half), halo_column(pair.to.p)}});
    CHECK(bytes == 2 * (sizeof(Vec<2>) + sizeof(Real)));
    CHECK(pair.to.v_half[0] == pair.from.v_half[0]);
    CHECK(pair.to.v_half[1] == Vec<2>::Zero());
    CHECK(pair.to.v_half[2] == pair.from.v_half[2]);
    CHECK(pair.to.p[2] == Real(102));
}

TEST_CASE("the state brings the halo particles and their cells' ranges") {
    Pair pair;
    HaloFields<2> out(pair.from, pair.from_ranges, pair.grid, pair.plan, false);
    HaloFields<2> in(pair.to, pair.to_ranges, pair.grid, pair.plan, false);
    pair.to.kind.assign(3, Kind::wall); // overwritten by the state
    pair.exchange(out.state(), in.state());
    CHECK(pair.to.kind == pair.from.kind);
    CHECK(pair.to.id == pair.from.id);
    CHECK(pair.to.x == pair.from.x);
    const CellIndex cell = pair.grid.linear(pair.grid.coords(pair.from.x[0]));
    CHECK(pair.to_ranges.begin(cell) == 0);
    CHECK(pair.to_ranges.end(cell) == 3);
    // The halo cell is the one cell stored; a reset clears it.
    CHECK(pair.to_ranges.stored() == 1);
    pair.to_ranges.reset(1);
    CHECK(pair.to_ranges.end(cell) == 0);
    CHECK(pair.to_ranges.stored() == 0);
}

} // namespace
} // namespace sluice
