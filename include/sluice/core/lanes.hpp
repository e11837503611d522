#pragma once
// Four double lanes for pair loops that read a neighbour's fields as one packed record: GCC's
// vector types (the arithmetic operators, comparisons and `?:` work lane by lane) and the AVX
// shuffles that turn four 32-byte rows into four lanes; with AVX2, a store that keeps the lanes
// a mask selects (for filtering a list). Only where the build targets AVX (SLUICE_NATIVE on a
// machine that has it); callers keep a scalar path for the others.
// No physics here: the pair formulas are in include/sluice/physics/.
#include "sluice/core/types.hpp"

#if defined(__AVX__)
#include <immintrin.h>
#endif

#include <array>
#include <cstdint>

namespace sluice {

#if defined(__AVX__) && !defined(SLUICE_SINGLE_PRECISION)
inline constexpr bool lanes_available = true;

using Real4 = double __attribute__((vector_size(32)));
using Mask4 = long long __attribute__((vector_size(32))); // all bits set in a true lane

// The 32 bytes at p (aligned) as four lanes.
inline Real4 load_lanes(const Real* p) {
    return Real4(_mm256_load_pd(p));
}

// Rows a, b, c, d of four values each become columns: afterwards a holds the first value of
// each row, b the second, c the third, d the fourth (a 4x4 transpose in eight shuffles).
inline void transpose_lanes(Real4& a, Real4& b, Real4& c, Real4& d) {
    const __m256d t0 = _mm256_unpacklo_pd(__m256d(a), __m256d(b)); // a0 b0 a2 b2
    const __m256d t1 = _mm256_unpackhi_pd(__m256d(a), __m256d(b)); // a1 b1 a3 b3
    const __m256d t2 = _mm256_unpacklo_pd(__m256d(c), __m256d(d)); // c0 d0 c2 d2
    const __m256d t3 = _mm256_unpackhi_pd(__m256d(c), __m256d(d)); // c1 d1 c3 d3
    a = Real4(_mm256_permute2f128_pd(t0, t2, 0x20));
    b = Real4(_mm256_permute2f128_pd(t1, t3, 0x20));
    c = Real4(_mm256_permute2f128_pd(t0, t2, 0x31));
    d = Real4(_mm256_permute2f128_pd(t1, t3, 0x31));
}

// Two consecutive values at each of four addresses as two sets of lanes: first = (p0[0], p1[0],
// p2[0], p3[0]), second = (p0[1], p1[1], p2[1], p3[1]): four 16-byte loads and two shuffles, for
// a field stored as pairs (a 2-D vector) read at four particles.
inline void load_pair_lanes(const Real* p0, const Real* p1, const Real* p2, const Real* p3,
                            Real4& first, Real4& second) {
    const __m256d a = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0)),
                                           _mm_loadu_pd(p2), 1); // p0[0] p0[1] p2[0] p2[1]
    const __m256d b = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p1)),
                                           _mm_loadu_pd(p3), 1); // p1[0] p1[1] p3[0] p3[1]
    first = Real4(_mm256_unpacklo_pd(a, b));
    second = Real4(_mm256_unpackhi_pd(a, b));
}

// The lanes' sum in a fixed order, ((l0 + l1) + (l2 + l3)): with a fixed assignment of pairs to
// lanes, a sum over lanes is as reproducible as a sequential one.
inline Real sum_lanes(const Real4& v) {
    return (v[0] + v[1]) + (v[2] + v[3]);
}

#if defined(__AVX2__)
namespace detail {
// For each 4-bit lane mask: the indices that move the masked lanes, in order, to the front;
// the lanes after them take lane 0 (their values are written past the end and overwritten).
// Bytes for four 32-bit values (pshufb), 32-bit halves for four 64-bit values (vpermd).
consteval std::array<std::array<std::uint8_t, 16>, 16> compress_bytes_32() {
    std::array<std::array<std::uint8_t, 16>, 16> t{};
    for (int m = 0; m < 16; ++m) {
        int k = 0;
        for (int l = 0; l < 4; ++l)
            if (m & (1 << l)) {
                for (int b = 0; b < 4; ++b)
                    t[m][4 * k + b] = static_cast<std::uint8_t>(4 * l + b);
                ++k;
            }
        for (; k < 4; ++k)
            for (int b = 0; b < 4; ++b)
                t[m][4 * k + b] = static_cast<std::uint8_t>(b);
    }
    return t;
}
consteval std::array<std::array<std::int32_t, 8>, 16> compress_halves_64() {
    std::array<std::array<std::int32_t, 8>, 16> t{};
    for (int m = 0; m < 16; ++m) {
        int k = 0;
        for (int l = 0; l < 4; ++l)
            if (m & (1 << l)) {
                t[m][2 * k] = 2 * l;
                t[m][2 * k + 1] = 2 * l + 1;
                ++k;
            }
        for (; k < 4; ++k) {
            t[m][2 * k] = 0;
            t[m][2 * k + 1] = 1;
        }
    }
    return t;
}
alignas(64) inline constexpr auto compress_32 = compress_bytes_32();
alignas(64) inline constexpr auto compress_64 = compress_halves_64();
} // namespace detail

// Stores the lanes of `ids` and `values` whose bit is set in `mask` (bit l: lane l), in lane
// order, at ids_out[0..] and values_out[0..], and returns how many. Four values are written to
// each output whatever the mask: both need room for four.
inline int compress_store(int mask, __m128i ids, Real4 values, std::uint32_t* ids_out,
                          Real* values_out) {
    const __m128i byte_order = _mm_load_si128(reinterpret_cast<const __m128i*>(
        detail::compress_32[static_cast<std::size_t>(mask)].data()));
    const __m256i half_order = _mm256_load_si256(reinterpret_cast<const __m256i*>(
        detail::compress_64[static_cast<std::size_t>(mask)].data()));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(ids_out), _mm_shuffle_epi8(ids, byte_order));
    _mm256_storeu_pd(values_out, _mm256_castsi256_pd(_mm256_permutevar8x32_epi32(
                                     _mm256_castpd_si256(__m256d(values)), half_order)));
    return __builtin_popcount(static_cast<unsigned>(mask));
}
#endif
#else
inline constexpr bool lanes_available = false;
#endif

} // namespace sluice
