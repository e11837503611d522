#pragma once
// Reflective walls (Tak 2024, its Steps 3 and 5-9): a particle whose move in a step
// takes it through a wall face is mirrored back across the face's plane, and the velocity
// component against the face's normal is reversed and scaled by the restitution coefficient e
// (e = 0: the particle keeps only its tangential velocity; e = 1: an elastic bounce).
//
// Faces come as infinite planes (the tank's faces, [[walls.planes]]) or as the elements of a
// surface (the triangles of a mesh, the segments of a 2-D polyline) that a CrossedFaces
// answers for: the first face a straight move enters from its front, the side its normal
// points to, where the fluid is. A move that leaves a face from behind is not reflected, so
// a particle mirrored onto the front of one face is not sent back by a coplanar neighbour.
#include "sluice/core/types.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace sluice {

template <int D>
struct Plane {
    Vec<D> point = Vec<D>::Zero();
    Vec<D> normal = Vec<D>::Zero(); // unit, pointing into the fluid
};

// Mirrors x across the plane when it lies behind it; v_half and v (the two velocities the
// leap-frog carries) lose their component against the normal, times (1 + e).
template <int D>
void mirror_behind(const Plane<D>& pl, Real restitution, Vec<D>& x, Vec<D>& v_half, Vec<D>& v) {
    const Real s = (x - pl.point).dot(pl.normal);
    if (s >= 0)
        return;
    x -= 2 * s * pl.normal;
    const Real vn_half = v_half.dot(pl.normal);
    if (vn_half < 0)
        v_half -= (1 + restitution) * vn_half * pl.normal;
    const Real vn = v.dot(pl.normal);
    if (vn < 0)
        v -= (1 + restitution) * vn * pl.normal;
}

// Keeps a particle on the fluid side of every plane.
template <int D>
void reflect(const std::vector<Plane<D>>& planes, Real restitution, Vec<D>& x, Vec<D>& v_half,
             Vec<D>& v) {
    for (const Plane<D>& pl : planes)
        mirror_behind(pl, restitution, x, v_half, v);
}

// Where a move a -> b enters a face: the face's plane (a point of the face, its unit normal
// towards the fluid) and the point of the face the move meets, at `fraction` of the way.
template <int D>
struct FaceEntry {
    Plane<D> plane;
    Vec<D> at;
    Real fraction = 0;
};

// A surface of reflective faces (a mesh): the first of its faces that a move enters from the
// front. Implementations answer concurrently from many threads (const, no state).
template <int D>
class CrossedFaces {
public:
    virtual ~CrossedFaces() = default;
    [[nodiscard]] virtual std::optional<FaceEntry<D>> first_entry(const Vec<D>& a,
                                                                  const Vec<D>& b) const = 0;
};

// Every reflective wall of a case.
template <int D>
struct Reflector {
    std::vector<Plane<D>> planes;
    std::vector<std::shared_ptr<const CrossedFaces<D>>> surfaces;
    Real restitution = 0;

    // A particle in a concave corner of a surface may enter a face again after each mirror;
    // after this many it stays where its last entry met the surface.
    static constexpr int max_bounces = 8;

    [[nodiscard]] bool empty() const { return planes.empty() && surfaces.empty(); }

    // The move from `from` to x in one step: mirrored across each surface face it enters, in
    // the order it meets them (the next entry is searched from the last one's point towards
    // the mirrored position), then kept in front of every plane.
    void apply(const Vec<D>& from, Vec<D>& x, Vec<D>& v_half, Vec<D>& v) const {
        Vec<D> a = from;
        for (int bounce = 0; !surfaces.empty(); ++bounce) {
            std::optional<FaceEntry<D>> first;
            for (const auto& s : surfaces) {
                auto e = s->first_entry(a, x);
                if (e && (!first || e->fraction < first->fraction))
                    first = e;
            }
            if (!first)
                break;
            if (bounce == max_bounces) {
                x = first->at;
                break;
            }
            mirror_behind(first->plane, restitution, x, v_half, v);
            a = first->at;
        }
        reflect(planes, restitution, x, v_half, v);
    }
};

} // namespace sluice
