// The exact orientation predicate against exact integer arithmetic (__int128), on inputs built
// to be collinear or within one rounding of it, where the plain double formula is wrong.
#include "sluice/physics/exact_orientation.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>

using namespace sluice;

namespace {

__extension__ using Int128 = __int128; // GCC/Clang built-in; __extension__: not ISO C++

// Exact sign for integer coordinates below 2^52 in magnitude: products of differences fit
// in 107 bits.
int int128_sign(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx,
                std::int64_t cy) {
    const Int128 det =
        static_cast<Int128>(bx - ax) * (cy - ay) - static_cast<Int128>(by - ay) * (cx - ax);
    return (det > 0) - (det < 0);
}

int naive_sign(const Vec<2>& a, const Vec<2>& b, const Vec<2>& c) {
    const double d = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    return (d > 0) - (d < 0);
}

} // namespace

TEST_CASE("exact orientation agrees with integer arithmetic where doubles round") {
    std::mt19937_64 rng(12345);
    const std::int64_t big = std::int64_t{1} << 51;
    std::uniform_int_distribution<std::int64_t> coord(-big, big);
    std::uniform_int_distribution<std::int64_t> small(-3, 3);
    int naive_wrong = 0;
    const int n = 200000;
    for (int t = 0; t < n; ++t) {
        // a, b random; c on the line through them (a + k (b - a)) moved by a few units:
        // the determinant is 0 or tiny against coordinates of 2^51.
        const std::int64_t ax = coord(rng) / 4, ay = coord(rng) / 4;
        const std::int64_t dx = coord(rng) / 8, dy = coord(rng) / 8;
        const std::int64_t bx = ax + dx, by = ay + dy;
        const std::int64_t cx = ax + 2 * dx + small(rng), cy = ay + 2 * dy + small(rng);
        const int exact = int128_sign(ax, ay, bx, by, cx, cy);
        // Scale by a power of two (exact) so the inputs are not integers.
        const double s = std::ldexp(1.0, -60);
        const Vec<2> a(static_cast<double>(ax) * s, static_cast<double>(ay) * s);
        const Vec<2> b(static_cast<double>(bx) * s, static_cast<double>(by) * s);
        const Vec<2> c(static_cast<double>(cx) * s, static_cast<double>(cy) * s);
        REQUIRE(orientation_sign(a, b, c) == exact);
        REQUIRE(orientation_sign_expansion(a, b, c) == exact);
        REQUIRE(orientation_sign(b, c, a) == exact); // cyclic shift: same sign
        REQUIRE(orientation_sign(b, a, c) == -exact);
        naive_wrong += naive_sign(a, b, c) != exact ? 1 : 0;
    }
    // The inputs do defeat plain doubles (else this test would prove nothing).
    MESSAGE("plain double formula wrong in " << naive_wrong << " of " << n << " cases");
    CHECK(naive_wrong > 100);
}

TEST_CASE("orientation of clear cases and exact zero") {
    CHECK(orientation_sign({0, 0}, {1, 0}, {0, 1}) == 1);
    CHECK(orientation_sign({0, 0}, {0, 1}, {1, 0}) == -1);
    // Points on y = x are exactly collinear whatever their rounding; the naive formula agrees
    // here, the filter must not invent a sign.
    CHECK(orientation_sign({0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}) == 0);
    CHECK(orientation_sign({1e-300, 1e-300}, {0.7, 0.7}, {1e300, 1e300}) == 0);
    // Kettner et al. (2008): points on the line y = x near (0.5, 0.5), where the rounded
    // determinant's sign is noise. (0.5 + k u, 0.5) is left of/on/right of the line through
    // (12, 12) and (24, 24) as k < 0, = 0, > 0.
    const double u = std::ldexp(1.0, -53);
    for (int k = -20; k <= 20; ++k) {
        const Vec<2> p(0.5 + k * u, 0.5);
        const int expected = k > 0 ? -1 : (k < 0 ? 1 : 0);
        CHECK(orientation_sign(p, {12, 12}, {24, 24}) == expected);
    }
}
