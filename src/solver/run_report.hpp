#pragma once
// The end-of-run report of the driver (run.cpp): neighbour census and per-rank profile as
// JSON for summary.json, and the table printed on several ranks. Private to src/solver.
#include "sluice/core/neighbour_census.hpp"
#include "sluice/solver/simulation.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace sluice {

nlohmann::json census_json(const NeighbourCensus& n);

// Per-rank profile as a flat list of numbers (same layout on every rank).
template <int D>
std::vector<double> profile_numbers(const Simulation<D>& sim);

// The end-of-run table (rank 0, when `print`) and its JSON form for summary.json, from every
// rank's profile_numbers.
nlohmann::json parallel_report(const std::vector<std::string>& stages,
                               const std::vector<std::vector<double>>& per_rank, bool print);

extern template std::vector<double> profile_numbers<2>(const Simulation<2>&);
extern template std::vector<double> profile_numbers<3>(const Simulation<3>&);

} // namespace sluice
