#include "sluice/core/particles.hpp"

#include "sluice/core/id_order_sum.hpp"

#include <algorithm>
#include <utility>

namespace sluice {

namespace {
template <class T>
void apply_permutation(std::vector<T>& data, std::span<const std::size_t> perm) {
    std::vector<T> out(perm.size());
    for (std::size_t i = 0; i < perm.size(); ++i)
        out[i] = data[perm[i]];
    data.swap(out);
}
} // namespace

template <int D>
void Particles<D>::permute(std::span<const std::size_t> perm) {
    apply_permutation(id, perm);
    apply_permutation(kind, perm);
    apply_permutation(x, perm);
    apply_permutation(v, perm);
    apply_permutation(rho, perm);
    apply_permutation(mass, perm);
    apply_permutation(x_ref, perm);
    apply_permutation(v_half, perm);
    // Pressure and acceleration of the last step are kept with their particle: probes and
    // snapshots written after a rebin still see consistent fields.
    apply_permutation(p, perm);
    apply_permutation(a, perm);
}

template <int D>
std::size_t Particles<D>::count(Kind k) const {
    return static_cast<std::size_t>(std::count(kind.begin(), kind.end(), k));
}

template <int D>
Real Particles<D>::total_mass() const {
    // Summed in id order, so the result does not depend on where particles are stored and
    // the exact conservation of mass can be checked with ==.
    std::vector<std::pair<ParticleId, Real>> m;
    m.reserve(size());
    for (std::size_t i = 0; i < size(); ++i)
        if (kind[i] == Kind::fluid)
            m.emplace_back(id[i], mass[i]);
    return sum_in_id_order(std::move(m));
}

Real sum_in_id_order(std::vector<std::pair<ParticleId, Real>> values) {
    std::sort(values.begin(), values.end());
    Real s = 0;
    for (const auto& [pid, v] : values)
        s += v;
    return s;
}

template struct Particles<2>;
template struct Particles<3>;

} // namespace sluice
