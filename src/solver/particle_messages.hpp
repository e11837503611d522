#pragma once
// Byte layouts of the particle data that crosses rank boundaries. Pure data movement: which
// fields each message carries follows from what the stages read of their neighbours
// (docs/ARCHITECTURE.md, "Halo exchanges"); no formula lives here.
#include "sluice/core/particles.hpp"
#include "sluice/tasks/comm.hpp"

#include <cstring>
#include <span>

namespace sluice::messages {

using tasks::Bytes;

template <class T>
void put_raw(Bytes& b, const T& v) {
    const std::size_t n = b.size();
    b.resize(n + sizeof(T));
    std::memcpy(b.data() + n, &v, sizeof(T));
}
template <class T>
void get_raw(std::span<const std::byte> b, std::size_t& pos, T& v) {
    std::memcpy(static_cast<void*>(&v), b.data() + pos, sizeof(T)); // raw bytes of a plain value
    pos += sizeof(T);
}

// The whole persistent state of a particle (what a particle that changes owner takes along),
// plus its last pressure and acceleration so that output after migration is unchanged.
template <int D>
constexpr std::size_t migrant_bytes = sizeof(ParticleId) + sizeof(Kind) +
                                      (4 * D + 3) * sizeof(Real);

template <int D>
void pack_migrant(const Particles<D>& P, std::size_t i, Bytes& b) {
    put_raw(b, P.id[i]);
    put_raw(b, P.kind[i]);
    put_raw(b, P.x[i]);
    put_raw(b, P.v[i]);
    put_raw(b, P.v_half[i]);
    put_raw(b, P.a[i]);
    put_raw(b, P.rho[i]);
    put_raw(b, P.mass[i]);
    put_raw(b, P.p[i]);
}

// Appends every particle in `b` to P.
template <int D>
void unpack_migrants(std::span<const std::byte> b, Particles<D>& P) {
    const std::size_t n = b.size() / migrant_bytes<D>;
    std::size_t i = P.size(), pos = 0;
    P.resize(i + n);
    for (std::size_t k = 0; k < n; ++k, ++i) {
        get_raw(b, pos, P.id[i]);
        get_raw(b, pos, P.kind[i]);
        get_raw(b, pos, P.x[i]);
        get_raw(b, pos, P.v[i]);
        get_raw(b, pos, P.v_half[i]);
        get_raw(b, pos, P.a[i]);
        get_raw(b, pos, P.rho[i]);
        get_raw(b, pos, P.mass[i]);
        get_raw(b, pos, P.p[i]);
    }
}

// What output (snapshots, probes) needs of a particle.
template <int D>
constexpr std::size_t output_bytes = sizeof(ParticleId) + sizeof(Kind) + (3 * D + 3) * sizeof(Real);

template <int D>
void pack_output(const Particles<D>& P, std::size_t i, Bytes& b) {
    put_raw(b, P.id[i]);
    put_raw(b, P.kind[i]);
    put_raw(b, P.x[i]);
    put_raw(b, P.v[i]);
    put_raw(b, P.a[i]);
    put_raw(b, P.rho[i]);
    put_raw(b, P.mass[i]);
    put_raw(b, P.p[i]);
}

template <int D>
void unpack_output(std::span<const std::byte> b, Particles<D>& P) {
    const std::size_t n = b.size() / output_bytes<D>;
    std::size_t i = P.size(), pos = 0;
    P.resize(i + n);
    for (std::size_t k = 0; k < n; ++k, ++i) {
        get_raw(b, pos, P.id[i]);
        get_raw(b, pos, P.kind[i]);
        get_raw(b, pos, P.x[i]);
        get_raw(b, pos, P.v[i]);
        get_raw(b, pos, P.a[i]);
        get_raw(b, pos, P.rho[i]);
        get_raw(b, pos, P.mass[i]);
        get_raw(b, pos, P.p[i]);
    }
}

} // namespace sluice::messages
