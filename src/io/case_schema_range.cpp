// The ranges of the case schema's keys (case_schema.hpp): built for the table, written as the
// docs write them, and the reason a value lies outside one.
#include "case_schema.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <utility>

namespace sluice::case_file {
namespace {

Range interval(double lo, bool lo_open, double hi, bool hi_open) {
    Range r;
    r.lo = lo;
    r.lo_open = lo_open;
    r.hi = hi;
    r.hi_open = hi_open;
    return r;
}

} // namespace

Range closed(double lo, double hi) {
    return interval(lo, false, hi, false);
}
Range open(double lo, double hi) {
    return interval(lo, true, hi, true);
}
Range open_closed(double lo, double hi) {
    return interval(lo, true, hi, false);
}
Range closed_open(double lo, double hi) {
    return interval(lo, false, hi, true);
}
Range at_least(double lo) {
    return interval(lo, false, kInf, true);
}
Range above(double lo) {
    return interval(lo, true, kInf, true);
}
Range one_of(std::vector<std::string_view> choices) {
    Range r;
    r.choices = std::move(choices);
    return r;
}
Range words(std::string_view w) {
    Range r;
    r.words = w;
    return r;
}

namespace {

bool is_integer(const KeySpec& k) {
    return k.type == "integer";
}

// An end of an interval as the docs write it: "0.5", "1e6", "1e-9", "inf"; integers in full.
std::string bound_text(double v, bool integer) {
    if (std::isinf(v))
        return v > 0 ? "inf" : "-inf";
    if (integer || (v == std::floor(v) && std::abs(v) < 1e5))
        return fmt::format("{:.0f}", v);
    // The shortest %g form that reads back as v, with the exponent written "1e6", "1e-9".
    std::string out;
    for (int digits = 1; digits <= 17; ++digits) {
        out = fmt::format("{:.{}g}", v, digits);
        if (std::stod(out) == v)
            break;
    }
    const auto e = out.find('e');
    if (e == std::string::npos)
        return out;
    std::string exponent = out.substr(e + 1);
    const bool negative = exponent[0] == '-';
    exponent.erase(0, exponent.find_first_not_of("+-0"));
    return out.substr(0, e + 1) + (negative ? "-" : "") + exponent;
}

std::string interval_text(const KeySpec& k) {
    const Range& r = k.range;
    return fmt::format("{}{}, {}{}", r.lo_open ? '(' : '[', bound_text(r.lo, is_integer(k)),
                       bound_text(r.hi, is_integer(k)), r.hi_open ? ')' : ']');
}

// The key's unit as a message writes it after a value: " m/s", or "".
std::string unit_suffix(const KeySpec& k) {
    return k.unit.empty() ? std::string() : fmt::format(" {}", k.unit);
}

} // namespace

std::string range_text(const KeySpec& k) {
    const Range& r = k.range;
    std::string out;
    if (!r.choices.empty()) {
        out = choices_text(k);
    } else if (r.bounded()) {
        out = k.type == "vector" ? "each component in " + interval_text(k) : interval_text(k);
    }
    if (!r.words.empty())
        out += (out.empty() ? "" : "; ") + std::string(r.words);
    return out;
}

std::string range_violation(const KeySpec& k, double v) {
    const Range& r = k.range;
    const bool low = r.lo_open ? !(v > r.lo) : !(v >= r.lo);
    const bool high = r.hi_open ? !(v < r.hi) : !(v <= r.hi);
    if (!low && !high)
        return {};
    // A plausibility limit names the unit: a value beyond it is usually in the wrong one.
    if (r.plausibility && (high || r.lo == -r.hi))
        return fmt::format("{}{} is implausibly large (the limit is {}{}); check the units", v,
                           unit_suffix(k), bound_text(r.hi, is_integer(k)), unit_suffix(k));
    const bool one_sided = r.plausibility || std::isinf(low ? r.hi : r.lo);
    if (one_sided && low)
        return fmt::format("must be {} {}{}, got {}",
                           r.lo_open ? ">" : ">=", bound_text(r.lo, is_integer(k)), unit_suffix(k),
                           v);
    if (one_sided)
        return fmt::format("must be {} {}{}, got {}",
                           r.hi_open ? "<" : "<=", bound_text(r.hi, is_integer(k)), unit_suffix(k),
                           v);
    return fmt::format("must be in {}{}, got {}", interval_text(k), unit_suffix(k), v);
}

std::string choices_text(const KeySpec& k) {
    std::string out;
    for (const auto c : k.range.choices)
        out += (out.empty() ? "\"" : ", \"") + std::string(c) + "\"";
    return out;
}

} // namespace sluice::case_file
