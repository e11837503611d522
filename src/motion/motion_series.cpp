#include "sluice/motion/motion_series.hpp"

#include <boost/math/interpolators/makima.hpp>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>

namespace sluice {

Signal series_signal(std::vector<double> t, std::vector<double> value) {
    if (t.size() != value.size() || t.size() < 2)
        throw std::invalid_argument("series_signal: needs two or more (t, value) rows");
    const double t0 = t.front(), t1 = t.back();
    const double v0 = value.front();
    if (t.size() < 4) { // too few rows for the spline: straight lines between them
        return [t = std::move(t), value = std::move(value), v0](double s) {
            if (s <= t.front())
                return SignalValue{0, 0, 0};
            if (s >= t.back())
                return SignalValue{value.back() - v0, 0, 0};
            const auto k =
                static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), s) - t.begin());
            const double rate = (value[k] - value[k - 1]) / (t[k] - t[k - 1]);
            return SignalValue{value[k - 1] + rate * (s - t[k - 1]) - v0, rate, 0};
        };
    }
    using Spline = boost::math::interpolators::makima<std::vector<double>>;
    auto spline = std::make_shared<const Spline>(std::move(t), std::move(value));
    // Central differences of the C1 velocity, over a small part of the spacing.
    const double h = 1e-6 * (t1 - t0);
    return [spline, t0, t1, v0, h](double s) {
        if (s <= t0)
            return SignalValue{0, 0, 0};
        const double c = std::min(s, t1);
        const double lo = std::max(c - h, t0), hi = std::min(c + h, t1);
        return SignalValue{(*spline)(c)-v0, spline->prime(c),
                           (spline->prime(hi) - spline->prime(lo)) / (hi - lo)};
    };
}

} // namespace sluice
