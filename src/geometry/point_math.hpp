#pragma once
// Arithmetic on Point3 for the geometry layer's own files (one definition: the sanitizer
// builds compile the layer as one unity file).
#include "sluice/geometry/surface_geometry.hpp"

#include <cmath>

namespace sluice::detail {

inline double dot(const Point3& a, const Point3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Point3 minus(const Point3& a, const Point3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline Point3 cross(const Point3& a, const Point3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double norm(const Point3& a) {
    return std::sqrt(dot(a, a));
}

} // namespace sluice::detail
