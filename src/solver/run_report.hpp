#pragma once
// The end-of-run report of the driver (run.cpp): neighbour census and per-rank profile as
// JSON for summary.json, and the table printed on several ranks. Private to src/solver.
#include "sluice/core/neighbour_census.hpp"
#include "sluice/io/case_config.hpp"
#include "sluice/io/run_result.hpp"
#include "sluice/solver/simulation.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace sluice {

nlohmann::json census_json(const NeighbourCensus& n);

// One sentence on the fluid's spacing for the log and a failure message: how many fluid
// particles crowd a fluid neighbour (closer than dx/2), the closest pair in dx, and how many
// are alone.
std::string spacing_sentence(const NeighbourCensus& n, Real dx);

// Whether the spacing is worth a warning: at least 1 % of the fluid crowded.
bool crowded_warning(const NeighbourCensus& n);

// Per-rank profile as a flat list of numbers (same layout on every rank).
template <int D>
std::vector<double> profile_numbers(const Simulation<D>& sim);

// The end-of-run table (rank 0, when `print`) and its JSON form for summary.json, from every
// rank's profile_numbers.
nlohmann::json parallel_report(const std::vector<std::string>& stages,
                               const std::vector<std::vector<double>>& per_rank, bool print);

// What summary.json reports beyond the Simulation and the RunResult: the neighbour census at
// the start and the end (over `support`; fluid particles closer than `crowded` to a fluid
// neighbour count as crowded), and the segment's place in a restarted run.
struct RunFigures {
    Real support = 0;
    Real crowded = 0; // crowded_below(dx): half the initial spacing [m] (spacing_census.hpp)
    NeighbourCensus census_start, census_end;
    long start_step = 0;             // the step this segment started from
    bool resumed = false;            // a restart
    double earlier_wall_seconds = 0; // the earlier segments' time loops (checkpoint)
    int threads = 1;
};

// Collective: gathers every rank's profile; rank 0 prints the table on several ranks (unless
// `quiet`) and writes summary.json into `out_dir`.
template <int D>
void write_run_summary(const Simulation<D>& sim, const CaseConfig& cfg, const std::string& out_dir,
                       bool quiet, const RunResult& result, const RunFigures& f);

extern template std::vector<double> profile_numbers<2>(const Simulation<2>&);
extern template std::vector<double> profile_numbers<3>(const Simulation<3>&);
extern template void write_run_summary<2>(const Simulation<2>&, const CaseConfig&,
                                          const std::string&, bool, const RunResult&,
                                          const RunFigures&);
extern template void write_run_summary<3>(const Simulation<3>&, const CaseConfig&,
                                          const std::string&, bool, const RunResult&,
                                          const RunFigures&);

} // namespace sluice
