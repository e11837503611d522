#pragma once
// The byte layout of a particle that changes owner (migration, rebalance) or is gathered for
// output: its whole persistent state plus its last pressure and acceleration, so snapshots
// written after a migration are unchanged. Pure data movement, no formula.
#include "sluice/core/particles.hpp"
#include "sluice/tasks/comm.hpp"

#include <span>

namespace sluice::messages {

template <int D>
constexpr std::size_t particle_bytes = sizeof(ParticleId) + sizeof(Kind) +
                                       (5 * D + 3) * sizeof(Real);

template <int D>
void pack_particle(const Particles<D>& P, std::size_t i, tasks::Bytes& b) {
    tasks::put(b, P.id[i]);
    tasks::put(b, P.kind[i]);
    tasks::put(b, P.x[i]);
    tasks::put(b, P.x_ref[i]);
    tasks::put(b, P.v[i]);
    tasks::put(b, P.v_half[i]);
    tasks::put(b, P.a[i]);
    tasks::put(b, P.rho[i]);
    tasks::put(b, P.mass[i]);
    tasks::put(b, P.p[i]);
}

// Appends every particle in `b` to P.
template <int D>
void unpack_particles(std::span<const std::byte> b, Particles<D>& P) {
    const std::size_t n = b.size() / particle_bytes<D>;
    std::size_t i = P.size(), pos = 0;
    P.resize(i + n);
    for (std::size_t k = 0; k < n; ++k, ++i) {
        tasks::take_into(b, pos, P.id[i]);
        tasks::take_into(b, pos, P.kind[i]);
        tasks::take_into(b, pos, P.x[i]);
        tasks::take_into(b, pos, P.x_ref[i]);
        tasks::take_into(b, pos, P.v[i]);
        tasks::take_into(b, pos, P.v_half[i]);
        tasks::take_into(b, pos, P.a[i]);
        tasks::take_into(b, pos, P.rho[i]);
        tasks::take_into(b, pos, P.mass[i]);
        tasks::take_into(b, pos, P.p[i]);
    }
}

} // namespace sluice::messages
