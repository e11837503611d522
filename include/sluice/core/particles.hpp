#pragma once
// Particle state as a structure of arrays. Arrays are kept sorted by (cell key, id) so that the
// particles of one cell are contiguous and every neighbour sum runs in a fixed order.
#include "sluice/core/types.hpp"

#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace sluice {

template <int D>
struct Particles {
    // State at the start of a step (read by every stage of the step).
    std::vector<ParticleId> id;
    std::vector<Kind> kind;
    std::vector<Vec<D>> x;  // position [m]
    std::vector<Vec<D>> v;  // velocity [m/s]
    std::vector<Real> rho;  // density [kg/m^3]
    std::vector<Real> mass; // [kg]: constant for fluid; wall particles rho_w dx^D, set each step
    // Position at the last neighbour-list rebuild (numerics.neighbour_skin): the particles are
    // sorted, and the Verlet lists built, by these positions until the next rebuild.
    std::vector<Vec<D>> x_ref;

    // Derived within a step.
    std::vector<Real> p;           // pressure [Pa]
    std::vector<Real> p_over_rho2; // fluid: p / rho^2, the pressure term's factor [m^5/(kg s^2)]
    std::vector<Real> volume;      // fluid: m / rho [m^D]
    std::vector<Vec<D>> a;         // acceleration [m/s^2]
    std::vector<Real> drho;        // density rate [kg/m^3/s] (continuity scheme)
    std::vector<Vec<D>> grad_rho;  // renormalised density gradient (delta-SPH)
    std::vector<Vec<D>> v_bc;      // wall particles: velocity seen by the viscous term (Adami)
    std::vector<Vec<D>> shift;     // particle-shifting displacement of this step

    // Leap-frog half-step velocity v^{n-1/2}. The kick advances it in place (only the
    // particle's own kick writes it, before any neighbour reads it); the drift, whose
    // continuity rate reads the neighbours' kicked v_half, writes the reflected one to
    // v_half_next.
    std::vector<Vec<D>> v_half;

    // Double buffer written by integration; swapped in at the end of the step so that no
    // stage ever reads a neighbour's half-written state.
    std::vector<Vec<D>> x_next, v_next, v_half_next;
    std::vector<Real> rho_next;

    [[nodiscard]] std::size_t size() const { return id.size(); }

    // Calls f(&Particles::array) for every per-particle array above. The static_assert below
    // the struct fails when an array is added without being listed here.
    template <class F>
    static constexpr void for_each_array(F&& f) {
        f(&Particles::id);
        f(&Particles::kind);
        f(&Particles::x);
        f(&Particles::v);
        f(&Particles::rho);
        f(&Particles::mass);
        f(&Particles::x_ref);
        f(&Particles::p);
        f(&Particles::p_over_rho2);
        f(&Particles::volume);
        f(&Particles::a);
        f(&Particles::drho);
        f(&Particles::grad_rho);
        f(&Particles::v_bc);
        f(&Particles::shift);
        f(&Particles::v_half);
        f(&Particles::x_next);
        f(&Particles::v_next);
        f(&Particles::v_half_next);
        f(&Particles::rho_next);
    }
    static constexpr std::size_t array_count() {
        std::size_t n = 0;
        for_each_array([&](auto) { ++n; });
        return n;
    }
    // Bytes of state one particle occupies: one element of every array (`sluice info`).
    static constexpr std::size_t bytes_per_particle() {
        std::size_t bytes = 0;
        for_each_array([&](auto member) {
            using Array = std::remove_reference_t<decltype(std::declval<Particles&>().*member)>;
            bytes += sizeof(typename Array::value_type);
        });
        return bytes;
    }

    void resize(std::size_t n) {
        id.resize(n);
        kind.resize(n, Kind::fluid);
        x.resize(n, Vec<D>::Zero());
        v.resize(n, Vec<D>::Zero());
        rho.resize(n, 0);
        mass.resize(n, 0);
        x_ref.resize(n, Vec<D>::Zero());
        p.resize(n, 0);
        p_over_rho2.resize(n, 0);
        volume.resize(n, 0);
        a.resize(n, Vec<D>::Zero());
        drho.resize(n, 0);
        grad_rho.resize(n, Vec<D>::Zero());
        v_bc.resize(n, Vec<D>::Zero());
        shift.resize(n, Vec<D>::Zero());
        v_half.resize(n, Vec<D>::Zero());
        x_next.resize(n, Vec<D>::Zero());
        v_next.resize(n, Vec<D>::Zero());
        v_half_next.resize(n, Vec<D>::Zero());
        rho_next.resize(n, 0);
    }

    // Capacity for n particles in every array (appending one by one then never reallocates).
    void reserve(std::size_t n) {
        for_each_array([&](auto member) { (this->*member).reserve(n); });
    }

    // Gives back the capacity beyond size() of every array: resize keeps it, so arrays that
    // once held more particles (e.g. a checkpoint's share before the restart distributed it)
    // would otherwise keep their largest size.
    void shrink_to_fit() {
        for_each_array([&](auto member) { (this->*member).shrink_to_fit(); });
    }

    // Appends one particle with the given state; derived fields start at zero.
    void push_back(ParticleId pid, Kind k, const Vec<D>& pos, const Vec<D>& vel, Real density,
                   Real m) {
        resize(size() + 1);
        const std::size_t i = size() - 1;
        id[i] = pid;
        kind[i] = k;
        x[i] = pos;
        v[i] = vel;
        rho[i] = density;
        mass[i] = m;
        x_ref[i] = pos;
        v_half[i] = vel;
    }

    // Reorders the state arrays so that new position i holds old particle perm[i].
    // Derived fields are not carried: they are recomputed every step.
    void permute(std::span<const std::size_t> perm);

    // Makes the double buffer the current state.
    void swap_buffers() {
        x.swap(x_next);
        v.swap(v_next);
        v_half.swap(v_half_next);
        rho.swap(rho_next);
    }

    [[nodiscard]] std::size_t count(Kind k) const;
    [[nodiscard]] Real total_mass() const;
};

extern template struct Particles<2>;
extern template struct Particles<3>;

// Every member is a per-particle array, and for_each_array lists them all.
static_assert(sizeof(Particles<2>) == Particles<2>::array_count() * sizeof(std::vector<Real>));
static_assert(sizeof(Particles<3>) == Particles<3>::array_count() * sizeof(std::vector<Real>));

} // namespace sluice
