// The migration of a Verlet-list rebuild (docs/ARCHITECTURE.md, "Between steps"): particles
// whose cell now belongs to a peer go to it, and the same round carries the halo counts that
// the next halo plan needs, so a rebuild waits for its neighbours once instead of twice.
//
// Why one round is enough. After the migration, rank B receives as halo from its peer A every
// particle in A's cells adjacent to B's cells. Those are A's kept particles there, which A
// counts, and the migrants that land there, which their senders count: a migrant is sent by a
// rank S to the owner A of its new cell, so S knows the cell and every rank adjacent to it.
// S is a peer of A and B a peer of A, so B is within two peer steps of S
// (tasks::two_step_ranks): S tells B directly. Every rank therefore sends one message to each
// rank within two peer steps: the halo counts it knows for the receiver, as (holder, particles,
// walls) triples, followed by the migrants if the receiver is a peer. No formula; particles
// are moved and counted.
#include "sluice/solver/rank_exchange.hpp"

#include "particle_messages.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

namespace sluice {

// Named rather than anonymous: the tallies are captured by a lambda inside the RankExchange<D>
// member template, and a type of an anonymous namespace there draws GCC's -Wsubobject-linkage
// in the unity builds of the sanitizer presets.
namespace detail {

// What a rank tells another about the halo it will receive from `holder`.
struct HaloTally {
    std::uint64_t holder, count, walls;
};

void add_tally(std::vector<HaloTally>& tallies, int holder, std::uint64_t count,
               std::uint64_t walls) {
    const auto h = static_cast<std::uint64_t>(holder);
    for (auto& t : tallies)
        if (t.holder == h) {
            t.count += count;
            t.walls += walls;
            return;
        }
    tallies.push_back({h, count, walls});
}

std::size_t index_in(const std::vector<int>& sorted, int rank) {
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), rank);
    return it != sorted.end() && *it == rank ? static_cast<std::size_t>(it - sorted.begin())
                                             : sorted.size();
}

} // namespace detail

template <int D>
tasks::MessageRecord RankExchange<D>::migrate(Particles<D>& P) {
    // A particle moves less than one cell per step, so it can only enter a peer's cell.
    const double t0 = tasks::clock_seconds();
    const int me = comm_.rank();
    const std::size_t nreach = reach_.size();
    std::vector<tasks::Bytes> migrants(nreach);
    std::vector<std::vector<detail::HaloTally>> tallies(nreach);
    halo_in_count_.assign(peers_.size(), 0);
    halo_in_walls_.assign(peers_.size(), 0);
    std::vector<std::size_t> keep;
    keep.reserve(P.size());

    // Particles of one cell are mostly consecutive (the arrays are sorted at every rebuild), so
    // a run of equal cells is counted once: its owner and the ranks it is a halo cell of.
    CellIndex run_cell = 0;
    int run_owner = -1;
    std::uint64_t run_count = 0, run_walls = 0;
    std::vector<int> facing;
    auto flush_run = [&] {
        for (int b : facing) {
            if (b == me) {
                // A migrant of ours lands in a halo cell of ours: we receive it back as halo.
                const std::size_t p = detail::index_in(peers_, run_owner);
                halo_in_count_[p] += run_count;
                halo_in_walls_[p] += run_walls;
                continue;
            }
            const std::size_t r = detail::index_in(reach_, b);
            if (r == nreach)
                throw std::logic_error(fmt::format("rank {} is not within two peer steps of "
                                                   "rank {}",
                                                   b, me));
            detail::add_tally(tallies[r], run_owner, run_count, run_walls);
        }
        run_count = run_walls = 0;
    };
    for (std::size_t i = 0; i < P.size(); ++i) {
        const auto c = grid_.coords(P.x[i]);
        const CellIndex cell = grid_.linear(c);
        if (run_owner < 0 || cell != run_cell) {
            if (run_owner >= 0)
                flush_run();
            run_cell = cell;
            run_owner = layout_.rank_of(grid_.morton(c));
            tasks::adjacent_owners(grid_, layout_, cell, run_owner, facing);
            if (run_owner != me && detail::index_in(peers_, run_owner) == peers_.size())
                throw std::logic_error(fmt::format("particle {} jumped to rank {}, not a "
                                                   "neighbour of rank {}",
                                                   P.id[i], run_owner, me));
        }
        ++run_count;
        run_walls += P.kind[i] == Kind::wall ? 1 : 0;
        if (run_owner == me)
            keep.push_back(i);
        else
            messages::pack_particle(P, i, migrants[detail::index_in(reach_, run_owner)]);
    }
    if (run_owner >= 0)
        flush_run();

    std::vector<tasks::Bytes> out(nreach), in;
    std::size_t bytes = 0;
    for (std::size_t r = 0; r < nreach; ++r) {
        tasks::put(out[r], static_cast<std::uint64_t>(tallies[r].size()));
        for (const auto& t : tallies[r]) {
            tasks::put(out[r], t.holder);
            tasks::put(out[r], t.count);
            tasks::put(out[r], t.walls);
        }
        out[r].insert(out[r].end(), migrants[r].begin(), migrants[r].end());
        bytes += out[r].size();
    }
    comm_.exchange(reach_, out, in, 11);
    if (keep.size() != P.size()) {
        P.permute(keep);
        P.resize(keep.size());
    }
    for (std::size_t r = 0; r < nreach; ++r) {
        std::size_t pos = 0;
        const auto n = tasks::take<std::uint64_t>(in[r], pos);
        for (std::uint64_t k = 0; k < n; ++k) {
            const auto holder = static_cast<int>(tasks::take<std::uint64_t>(in[r], pos));
            const std::size_t p = detail::index_in(peers_, holder);
            if (p == peers_.size())
                throw std::logic_error(fmt::format("rank {} was told of a halo from rank {}, "
                                                   "not a peer",
                                                   me, holder));
            halo_in_count_[p] += tasks::take<std::uint64_t>(in[r], pos);
            halo_in_walls_[p] += tasks::take<std::uint64_t>(in[r], pos);
        }
        messages::unpack_particles<D>(std::span<const std::byte>(in[r]).subspan(pos), P);
    }
    halo_in_known_ = true;
    return {"migrate", -1, true, bytes, t0, tasks::clock_seconds()};
}

template tasks::MessageRecord RankExchange<2>::migrate(Particles<2>&);
template tasks::MessageRecord RankExchange<3>::migrate(Particles<3>&);

} // namespace sluice
