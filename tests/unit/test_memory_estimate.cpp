// The memory estimate per rank (sluice/io/memory_estimate.hpp): its sizes parsed exactly, the
// halo layer against the lattice counted by hand, the terms against their definitions, and the
// refusal naming the file and particles.dx.
#include "sluice/io/errors.hpp"
#include "sluice/io/memory_estimate.hpp"

#include <doctest/doctest.h>

#include <string>

using namespace sluice;

TEST_CASE("memory sizes: binary and decimal units, anything else refused") {
    CHECK(*parse_memory_size("4GiB") == 4.0 * 1024 * 1024 * 1024);
    CHECK(*parse_memory_size("4 GiB") == 4.0 * 1024 * 1024 * 1024);
    CHECK(*parse_memory_size("1.5G") == 1.5 * 1024 * 1024 * 1024);
    CHECK(*parse_memory_size("512mib") == 512.0 * 1024 * 1024);
    CHECK(*parse_memory_size("2TB") == 2e12);
    CHECK(*parse_memory_size("2e9") == 2e9);
    CHECK(*parse_memory_size("100B") == 100);
    for (const char* bad :
         {"", "GiB", "-1GiB", "0", "4 GiBs", "4 PiB", "nan", "inf", "4 G B", "1e400"})
        CHECK_MESSAGE(!parse_memory_size(bad), std::string(bad));
}

TEST_CASE("halo layer: the lattice sites one support around a compact region") {
    // 2-D: 100 x 100 owned sites, support 2.6 dx -> 3 layers: 106^2 - 100^2.
    CHECK(halo_particles_per_rank(2, 1e4, 1e6, 2.6, 4) == doctest::Approx(1236));
    // 3-D: 20^3 owned sites, 3 layers: 26^3 - 20^3.
    CHECK(halo_particles_per_rank(3, 8000, 1e6, 3.0, 8) == doctest::Approx(9576));
    // No more than the particles of the other ranks; none on one rank.
    CHECK(halo_particles_per_rank(2, 1e4, 1.1e4, 2.6, 2) == doctest::Approx(1000));
    CHECK(halo_particles_per_rank(2, 1e4, 1e4, 2.6, 1) == 0);
}

TEST_CASE("memory estimate: the terms add up, the busiest rank's share is fluid first") {
    MemoryInputs in;
    in.dimension = 3;
    in.cells = 1e6;
    in.support_over_dx = 3;
    in.state_bytes = 400;
    in.ranks = 1;
    // The cost of one fluid and of one wall particle, from cases of only one kind.
    in.fluid = 1e6;
    const double fluid = estimate_memory(in).particles / 1e6;
    in.fluid = 0;
    in.walls = 1e6;
    const double wall = estimate_memory(in).particles / 1e6;
    CHECK(fluid > 4 * wall); // lists of every neighbour against lists of fluid neighbours
    CHECK(wall > in.state_bytes);

    in.fluid = 8e6;
    in.walls = 2e6;
    const MemoryEstimate one = estimate_memory(in);
    CHECK(one.particles_per_rank == 1e7);
    CHECK(one.particles == doctest::Approx(8e6 * fluid + 2e6 * wall));
    CHECK(one.halo == 0);
    CHECK(one.totals == 0);
    CHECK(one.grid == grid_bytes_per_rank(3, 1e7, 0, 3, 1e6));
    // Empty space costs nothing; a full domain costs its cells, however many particles.
    CHECK(grid_bytes_per_rank(3, 2.7e7, 0, 3, 1e9) == 1e6 * grid_bytes_per_rank(3, 27, 0, 3, 1e9));
    CHECK(grid_bytes_per_rank(3, 1e9, 0, 3, 1e6) == grid_bytes_per_rank(3, 2e9, 0, 3, 1e6));
    CHECK(one.total() == one.baseline + one.particles + one.grid);
    // 10 ranks of 1e6 particles: the busiest holds fluid only; the grid of its own cells and
    // halo; the halo copies' state; the fluid's ids and masses on rank 0.
    in.ranks = 10;
    const MemoryEstimate ten = estimate_memory(in);
    CHECK(ten.fluid_per_rank == 1e6);
    CHECK(ten.particles == doctest::Approx(1e6 * fluid));
    CHECK(ten.grid == grid_bytes_per_rank(3, 1e6, ten.halo_particles, 3, 1e6));
    CHECK(ten.grid < one.grid);
    CHECK(ten.baseline == one.baseline);
    CHECK(ten.halo == doctest::Approx(400 * halo_particles_per_rank(3, 1e6, 1e7, 3, 10)));
    CHECK(ten.totals > 0);
    in.fluid *= 2;
    CHECK(estimate_memory(in).totals == doctest::Approx(2 * ten.totals));
    // 4 ranks of 2.5e6: 2e6 fluid are not a share, so the busiest holds them and 5e5 walls.
    in.fluid = 2e6;
    in.walls = 8e6;
    in.ranks = 4;
    CHECK(estimate_memory(in).particles == doctest::Approx(2e6 * fluid + 5e5 * wall));
}

TEST_CASE("a case over the limit is refused naming the file and particles.dx") {
    CaseConfig cfg;
    cfg.source_file = "big.toml";
    MemoryInputs in;
    in.dimension = 3;
    in.fluid = 2e8;
    in.support_over_dx = 3;
    in.state_bytes = 400;
    const MemoryLimit limit{8.0 * 1024 * 1024 * 1024, "--max-memory 8.0 GiB"};
    in.ranks = 1;
    try {
        check_memory(cfg, estimate_memory(in), limit);
        FAIL("not refused");
    } catch (const CaseError& e) {
        CHECK(e.file() == "big.toml");
        CHECK(e.key() == "particles.dx");
        CHECK(std::string(e.what()).find("--max-memory 8.0 GiB") != std::string::npos);
    }
    in.ranks = 1000;
    CHECK_NOTHROW(check_memory(cfg, estimate_memory(in), limit));
}
