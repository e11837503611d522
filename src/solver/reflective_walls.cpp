// The reflective walls of a case (reflective_walls.hpp).
#include "sluice/solver/reflective_walls.hpp"

#include "sluice/geometry/surface_index.hpp"

#include "vec_triple.hpp"

#include <algorithm>
#include <string>

namespace sluice {

namespace {

// A mesh's elements as reflective faces: the fluid is on the side their normals point to (a
// surface's front, a solid's outside), so a move that enters an element from its front is
// mirrored.
template <int D>
class MeshFaces final : public CrossedFaces<D> {
public:
    explicit MeshFaces(std::shared_ptr<const SurfaceIndex> shape) : shape_(std::move(shape)) {}

    [[nodiscard]] std::optional<FaceEntry<D>> first_entry(const Vec<D>& a,
                                                          const Vec<D>& b) const override {
        const auto c =
            shape_->first_crossing(to_triple<D>(a), to_triple<D>(b), CrossingSense::entering_front);
        if (!c)
            return std::nullopt;
        return FaceEntry<D>{
            {to_vec<D>(c->anchor), to_vec<D>(c->normal)}, to_vec<D>(c->point), Real(c->fraction)};
    }

private:
    std::shared_ptr<const SurfaceIndex> shape_;
};

} // namespace

template <int D>
Reflector<D> reflective_walls(const CaseConfig& cfg) {
    Reflector<D> r;
    r.restitution = Real(cfg.restitution);
    if (cfg.walls == WallModel::reflective) {
        static constexpr const char* names[3][2] = {{"x-", "x+"}, {"y-", "y+"}, {"z-", "z+"}};
        for (int d = 0; d < D; ++d)
            for (int side = 0; side < 2; ++side) {
                const std::string face = names[d][side];
                if (std::find(cfg.tank_faces.begin(), cfg.tank_faces.end(), face) ==
                    cfg.tank_faces.end())
                    continue;
                Plane<D> pl;
                pl.point[d] = Real(side == 0 ? cfg.tank_lo[static_cast<std::size_t>(d)]
                                             : cfg.tank_hi[static_cast<std::size_t>(d)]);
                pl.normal[d] = side == 0 ? 1.0 : -1.0;
                r.planes.push_back(pl);
            }
        for (const WallMesh& m : cfg.meshes)
            r.surfaces.push_back(std::make_shared<MeshFaces<D>>(m.shape));
    }
    for (const WallPlane& wp : cfg.planes) {
        Plane<D> pl{to_vec<D>(wp.point), to_vec<D>(wp.normal)};
        pl.normal.normalize();
        r.planes.push_back(pl);
    }
    return r;
}

template Reflector<2> reflective_walls<2>(const CaseConfig&);
template Reflector<3> reflective_walls<3>(const CaseConfig&);

} // namespace sluice
