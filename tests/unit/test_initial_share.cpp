// The distributed start (initial_share.hpp) against generating every particle: the per-cell
// counts are the Rebinner's occupied cells of the whole set, the cut points are those of
// cutting the whole set, and the ranks' shares are a partition of the whole set, each particle
// bit for bit the one add_fluid_blocks / add_wall_particles make, each on its owner.
#include "sluice/core/rebin.hpp"
#include "sluice/io/case_reader.hpp"
#include "sluice/physics/kernels.hpp"
#include "sluice/solver/initial_share.hpp"
#include "sluice/solver/initial_state.hpp"

#include "case_files.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

using namespace sluice;

namespace {

template <int D>
bool same_bits(const Vec<D>& a, const Vec<D>& b) {
    return std::memcmp(a.data(), b.data(), sizeof(Real) * D) == 0;
}

template <int D>
void check_case(const CaseConfig& cfg) {
    const Eos eos{cfg.eos, Real(cfg.rho0), Real(cfg.sound_speed), Real(cfg.gamma),
                  Real(cfg.background_pressure)};
    const double support = kernel_support_factor(cfg.kernel) * cfg.h_over_dx * cfg.dx;
    const int layers = wall_layers(support, cfg.dx);
    // Every particle, as the start of earlier versions built them on every rank.
    Particles<D> all;
    add_fluid_blocks<D>(cfg, eos, all);
    if (cfg.walls == WallModel::dummy)
        add_wall_particles<D>(cfg, layers, all);
    REQUIRE(all.size() > 500);
    // A grid of small cells (about 3 dx) over the tank and its walls: many cells to cut.
    Vec<D> lo, hi;
    std::array<bool, D> periodic{};
    for (int d = 0; d < D; ++d) {
        lo[d] = Real(cfg.tank_lo[d] - (layers + 1) * cfg.dx);
        hi[d] = Real(cfg.tank_hi[d] + (layers + 1) * cfg.dx);
    }
    const CellGrid<D> grid = CellGrid<D>::make(lo, hi, Real(3 * cfg.dx), periodic);

    const InitialCensus census = initial_census<D>(cfg, eos, layers, grid);
    Particles<D> sorted = all;
    CellRanges ranges;
    std::vector<CellOccupancy> occupied;
    rebin(grid, sorted, ranges, occupied);
    CHECK(census.particles == all.size());
    REQUIRE(census.cells.size() == occupied.size());
    std::vector<tasks::CurveUnit> units;
    for (std::size_t k = 0; k < occupied.size(); ++k) {
        CHECK(census.cells[k].key == occupied[k].key);
        CHECK(census.cells[k].cost == double(occupied[k].count));
        units.push_back({occupied[k].key, double(occupied[k].count)});
    }
    Real vmax = 0;
    for (std::size_t i = 0; i < all.size(); ++i)
        vmax = std::max(vmax, all.v[i].norm());
    CHECK(census.max_speed == vmax);

    std::map<ParticleId, std::size_t> index; // id -> position in `all`
    for (std::size_t i = 0; i < all.size(); ++i)
        index[all.id[i]] = i;
    for (int ranks = 1; ranks <= 4; ++ranks) {
        CAPTURE(ranks);
        const tasks::RankLayout layout = initial_layout<D>(cfg, grid, census, ranks);
        const tasks::RankLayout whole =
            ranks == 1 ? tasks::RankLayout{}
            : cfg.initial_decomposition == InitialDecomposition::key_range
                ? tasks::cut_ranks_by_key(grid, ranks)
                : tasks::cut_ranks(units, ranks);
        CHECK(layout.key_begin == whole.key_begin);
        std::vector<int> seen(all.size(), 0);
        std::size_t total = 0;
        for (int r = 0; r < ranks; ++r) {
            CAPTURE(r);
            Particles<D> mine;
            const InitialShare share = initial_share<D>(cfg, eos, layers, grid, r, ranks, &mine);
            CHECK(share.layout.key_begin == whole.key_begin);
            CHECK(share.max_speed == vmax); // the whole case's, whatever the share
            total += mine.size();
            for (std::size_t i = 0; i < mine.size(); ++i) {
                CHECK(whole.rank_of(grid.morton(grid.coords(mine.x[i]))) == r);
                const auto it = index.find(mine.id[i]);
                REQUIRE(it != index.end());
                const std::size_t j = it->second;
                ++seen[j];
                CHECK(mine.kind[i] == all.kind[j]);
                CHECK(same_bits<D>(mine.x[i], all.x[j]));
                CHECK(same_bits<D>(mine.x_ref[i], all.x_ref[j]));
                CHECK(same_bits<D>(mine.v[i], all.v[j]));
                CHECK(same_bits<D>(mine.v_half[i], all.v_half[j]));
                CHECK(std::memcmp(&mine.rho[i], &all.rho[j], sizeof(Real)) == 0);
                CHECK(std::memcmp(&mine.mass[i], &all.mass[j], sizeof(Real)) == 0);
            }
            // Reserved exactly: appending the share never doubled an array.
            Particles<D>::for_each_array(
                [&](auto member) { CHECK((mine.*member).capacity() == mine.size()); });
        }
        CHECK(total == all.size());
        CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
    }
    // A restart keeps nothing and still learns the start's largest speed.
    const InitialShare none = initial_share<D>(cfg, eos, layers, grid, 1, 3, nullptr);
    CHECK(none.max_speed == vmax);
}

} // namespace

TEST_CASE("2-D dam break with jitter and an obstacle: counts, cuts and shares") {
    // Hydrostatic, settled (continuity), jittered fluid; dummy walls on three faces; a box.
    std::ifstream in(std::filesystem::path(SLUICE_SOURCE_DIR) / "cases" / "dam_break_2d.toml");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const CaseConfig cfg = read_case(
        testing::write_case("dam_break_box",
                            text + "\n[[walls.boxes]]\nlo = [0.9, 0.0]\nhi = [1.0, 0.1]\n"),
        {"particles.dx=0.02", "particles.jitter=0.01"});
    REQUIRE(cfg.jitter > 0);
    REQUIRE(cfg.boxes.size() == 1);
    check_case<2>(cfg);
}

TEST_CASE("2-D cuts by key range") {
    const CaseConfig cfg =
        read_case(std::string(SLUICE_SOURCE_DIR) + "/cases/dam_break_2d.toml",
                  {"particles.dx=0.02", "runtime.initial_decomposition=\"key-range\""});
    REQUIRE(cfg.initial_decomposition == InitialDecomposition::key_range);
    check_case<2>(cfg);
}

TEST_CASE("3-D dam break with a column obstacle: counts, cuts and shares") {
    const CaseConfig cfg =
        read_case(std::string(SLUICE_SOURCE_DIR) + "/perf/cases/dam_break_3d_obstacle.toml",
                  {"particles.dx=0.04"});
    check_case<3>(cfg);
}
