#pragma once
// Probes: scalar measurements of the particle state, sampled once per probe interval.
// Pure functions over all particles (O(N) per call, no neighbour structure needed); only fluid
// particles are measured. The vertical axis is the last one: y in 2-D, z in 3-D.
#include "sluice/core/particles.hpp"
#include "sluice/physics/cell_hash.hpp"
#include "sluice/physics/kernels.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <variant>
#include <vector>

namespace sluice {

namespace detail {
template <class T>
struct is_variant : std::false_type {};
template <class... T>
struct is_variant<std::variant<T...>> : std::true_type {};
} // namespace detail

// Pressure at `point` by Shepard-normalised kernel interpolation over fluid particles:
//   p(point) = sum_j p_j W_j V_j / sum_j W_j V_j,   V_j = m_j / rho_j,
// so a probe near the free surface or a wall is not biased by the missing neighbours.
// Returns NaN when no fluid particle lies within the kernel support of `point` (the probe is
// dry). `kernel` is any kernel type of kernels.hpp or an AnyKernel<D>. Each p_j is read as
// max(p_j, p_min): the pressure the scheme applies (the projection scheme applies no tension,
// projection.hpp P7; WCSPH reads p_min = -infinity, every pressure as it is).
template <int D, class K>
Real pressure_probe(const Particles<D>& ps, const K& kernel, const Vec<D>& point,
                    Real p_min = -std::numeric_limits<Real>::infinity()) {
    if constexpr (detail::is_variant<K>::value) {
        return std::visit([&](const auto& k) { return pressure_probe(ps, k, point, p_min); },
                          kernel);
    } else {
        const Real support2 = kernel.support() * kernel.support();
        Real num = 0, den = 0;
        for (std::size_t j = 0; j < ps.size(); ++j) {
            if (ps.kind[j] != Kind::fluid)
                continue;
            const Real r2 = (ps.x[j] - point).squaredNorm();
            if (r2 >= support2)
                continue;
            const Real wv = kernel.W(std::sqrt(r2)) * ps.mass[j] / ps.rho[j];
            num += std::max(ps.p[j], p_min) * wv;
            den += wv;
        }
        return den > 0 ? num / den : std::numeric_limits<Real>::quiet_NaN();
    }
}

// Indices (ascending) of the fluid particles forming the bulk: fluid particles are linked when
// their distance is <= 1.5 dx, and the bulk is the connected component with the most
// particles (ties: the one holding the smallest particle id). Spray droplets and detached jets
// are therefore excluded. Empty when there is no fluid. O(N) with a cell hash + union-find.
template <int D>
std::vector<std::size_t> bulk_fluid(const Particles<D>& ps, Real dx);
// The same among the fluid particles `candidates` (indices into ps, ascending) only.
template <int D>
std::vector<std::size_t> bulk_fluid(const Particles<D>& ps, Real dx,
                                    const std::vector<std::size_t>& candidates);

// The functions below find the bulk themselves; when several probes are sampled at the same
// time, compute bulk_fluid() once and pass it to the overloads taking `bulk`.

// Free-surface height at horizontal position x: among bulk fluid particles with
// |x_i - x| <= dx (in 3-D: over the whole slab, across the tank width), the highest vertical
// coordinate, plus dx/2 (a particle stands for a lattice cell of size dx, so a block of
// height H filled at dx gives exactly H). NaN when no bulk particle is in the column (dry).
template <int D>
Real water_level(const Particles<D>& ps, Real dx, Real x);
template <int D>
Real water_level(const Particles<D>& ps, const std::vector<std::size_t>& bulk, Real dx, Real x);

// Water level at a point of the floor in 3-D: as above over the column |x_i - x| <= dx,
// |y_i - y| <= dx (a gauge of half-width dx around (x, y), not the whole tank width).
template <int D>
Real water_level_at(const Particles<D>& ps, const std::vector<std::size_t>& bulk, Real dx, Real x,
                    Real y);

// The level a water-level gauge reads (the run's `water_level` probes): the highest particle
// of the gauge's column (|x_i - x| <= dx; with `y`, in 3-D, also |y_i - y| <= dx; without,
// across the whole width) that belongs to the bulk of the gauge's surroundings, plus dx/2.
// The surroundings are the fluid within gauge_bulk_reach dx of the gauge (the same bounds
// widened); their bulk is their largest set of particles linked within 1.5 dx (bulk_fluid
// over them alone). Spray above the gauge is not bulk; the surroundings' width lets the bulk
// link through particles beside the column, where a disordered surface leaves gaps wider
// than 1.5 dx inside a column two particles wide. The reading depends on the surroundings'
// particles only, so it can be evaluated on them alone, wherever the rest of the fluid is
// held. NaN when no bulk particle is in the column.
inline constexpr int gauge_bulk_reach = 6;
template <int D>
Real gauge_water_level(const Particles<D>& ps, Real dx, Real x, std::optional<Real> y);

// Surge front (the original definition, kept for code that asks for it): the largest x over
// the bulk fluid, plus dx/2 (the cell edge, as above). NaN when there is no fluid.
template <int D>
Real surge_front(const Particles<D>& ps, Real dx);
template <int D>
Real surge_front(const Particles<D>& ps, const std::vector<std::size_t>& bulk, Real dx);

// Surge front along a direction (axis `axis`, towards + or -), defined by a minimum fluid
// thickness so that it does not jump back when the tip thins or detaches from the bulk.
// Fluid particles (all of them, not only the bulk) are binned into columns: cells of size dx
// along every axis except the "depth" axis (the vertical one, or, for a vertical direction,
// the first horizontal one), which a column spans whole. A column is *thick* when it holds at
// least max(1, round(min_thickness / dx)) particles, i.e. min_thickness of fluid depth at
// that point. The front is the furthest position along the direction of a particle in a
// thick column, plus dx/2 (minus, for a negative direction): the reported value is a
// coordinate on `axis`. A single droplet or a one-particle film is not a front; a thin tip
// two particles deep still is, wherever it is. NaN when no column is thick.
template <int D>
Real surge_front_directed(const Particles<D>& ps, Real dx, int axis, bool negative,
                          Real min_thickness);

// surge_front_directed in two parts, so that each rank can bin its own particles and one rank
// merge the columns: a column's count adds up and its furthest position is a maximum, so the
// front is the same for any split of the particles and any merge order.
template <int D>
class FrontColumns {
public:
    struct Column {
        long count = 0;
        Real furthest = -std::numeric_limits<Real>::infinity(); // along the signed direction
    };
    FrontColumns(Real dx, int axis, bool negative);
    // Bins the fluid particles [0, end) of ps.
    void add(const Particles<D>& ps, std::size_t end);
    // Adds a column binned elsewhere.
    void merge(const CellKey<D>& key, const Column& c);
    [[nodiscard]] const std::unordered_map<CellKey<D>, Column, CellKeyHash<D>>& columns() const {
        return columns_;
    }
    // The front: the furthest position of a column holding at least
    // max(1, round(min_thickness / dx)) particles, plus dx/2 (a coordinate on the axis); NaN
    // when no column is that thick.
    [[nodiscard]] Real front(Real min_thickness) const;

private:
    Real dx_;
    int axis_, depth_;
    Real sign_;
    std::unordered_map<CellKey<D>, Column, CellKeyHash<D>> columns_;
};

extern template std::vector<std::size_t> bulk_fluid<2>(const Particles<2>&, Real);
extern template std::vector<std::size_t> bulk_fluid<3>(const Particles<3>&, Real);
extern template std::vector<std::size_t> bulk_fluid<2>(const Particles<2>&, Real,
                                                       const std::vector<std::size_t>&);
extern template std::vector<std::size_t> bulk_fluid<3>(const Particles<3>&, Real,
                                                       const std::vector<std::size_t>&);
extern template Real gauge_water_level<2>(const Particles<2>&, Real, Real, std::optional<Real>);
extern template Real gauge_water_level<3>(const Particles<3>&, Real, Real, std::optional<Real>);
extern template class FrontColumns<2>;
extern template class FrontColumns<3>;
extern template Real water_level<2>(const Particles<2>&, Real, Real);
extern template Real water_level<3>(const Particles<3>&, Real, Real);
extern template Real water_level_at<2>(const Particles<2>&, const std::vector<std::size_t>&, Real,
                                       Real, Real);
extern template Real water_level_at<3>(const Particles<3>&, const std::vector<std::size_t>&, Real,
                                       Real, Real);
extern template Real surge_front_directed<2>(const Particles<2>&, Real, int, bool, Real);
extern template Real surge_front_directed<3>(const Particles<3>&, Real, int, bool, Real);
extern template Real surge_front<2>(const Particles<2>&, Real);
extern template Real surge_front<3>(const Particles<3>&, Real);
extern template Real water_level<2>(const Particles<2>&, const std::vector<std::size_t>&, Real,
                                    Real);
extern template Real water_level<3>(const Particles<3>&, const std::vector<std::size_t>&, Real,
                                    Real);
extern template Real surge_front<2>(const Particles<2>&, const std::vector<std::size_t>&, Real);
extern template Real surge_front<3>(const Particles<3>&, const std::vector<std::size_t>&, Real);
extern template Real pressure_probe<2, AnyKernel<2>>(const Particles<2>&, const AnyKernel<2>&,
                                                     const Vec<2>&, Real);
extern template Real pressure_probe<3, AnyKernel<3>>(const Particles<3>&, const AnyKernel<3>&,
                                                     const Vec<3>&, Real);

} // namespace sluice
