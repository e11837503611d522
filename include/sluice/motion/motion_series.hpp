#pragma once
// A coordinate of a motion given as a time series (a motion file's column): interpolated by
// Boost's modified Akima spline (Akima 1970, with the weights of Akima 1991/MATLAB's makima),
// which follows the data without the overshoot of a global cubic spline and is C1: the
// velocity is continuous, the acceleration piecewise linear. Before the first row the value
// is the first row's; the case reader refuses a run longer than the series.
#include "sluice/motion/signal.hpp"

#include <vector>

namespace sluice {

// The series value(t) - value(t_0) with its derivatives; t strictly increasing, >= 2 rows
// (fewer than 4 rows,
// too few for the spline: piecewise linear). The acceleration is the derivative of the spline's
// velocity.
Signal series_signal(std::vector<double> t, std::vector<double> value);

} // namespace sluice
