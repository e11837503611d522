#pragma once
// A sum of doubles that does not depend on the order of its terms: each term is rounded to a
// fixed-point multiple of 2^-64 and added as a 128-bit integer, which is associative, so a
// sum over particles comes out bitwise the same however they are split between threads, cell
// groups and ranks (a free body's load, summed over its wall particles wherever they are).
// Terms must stay below 2^62 in magnitude (4.6e18: a force or moment in SI units far past any
// physical one); add() reports a term that does not fit instead of wrapping.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace sluice {

class ExactSum {
public:
    __extension__ using Int = __int128;
    static constexpr int kFractionBits = 64;

    // Adds x; false (and nothing added) when |x| is too large or not finite.
    bool add(double x) {
        const double scaled = std::ldexp(x, kFractionBits);
        if (!(std::fabs(scaled) < std::ldexp(1.0, 126)))
            return false;
        value_ += static_cast<Int>(std::nearbyint(scaled));
        return true;
    }
    void add(const ExactSum& o) { value_ += o.value_; }
    [[nodiscard]] double value() const {
        return std::ldexp(static_cast<double>(value_), -kFractionBits);
    }
    // The raw 16 bytes, for messages (the same layout on every rank of one machine type).
    void to_bytes(std::byte* out) const { std::memcpy(out, &value_, sizeof(value_)); }
    static ExactSum from_bytes(const std::byte* in) {
        ExactSum s;
        std::memcpy(&s.value_, in, sizeof(s.value_));
        return s;
    }
    static constexpr std::size_t bytes = sizeof(Int);
    bool operator==(const ExactSum&) const = default;

private:
    Int value_ = 0;
};

} // namespace sluice
