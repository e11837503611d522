// The end-of-run report (run_report.hpp).
#include "run_report.hpp"

#include "sluice/io/summary.hpp"
#include "sluice/tasks/comm.hpp"

#include <cmath>
#include <cstring>
#include <span>

#include <fmt/format.h>

namespace sluice {

nlohmann::json census_json(const NeighbourCensus& n) {
    nlohmann::json j = {{"fluid_particles", n.fluid},       {"wall_particles", n.wall},
                        {"fluid_fluid", n.fluid_fluid},     {"fluid_wall", n.fluid_wall},
                        {"wall_fluid", n.wall_fluid},       {"wall_wall", n.wall_wall},
                        {"fluid_crowded", n.fluid_crowded}, {"fluid_isolated", n.fluid_isolated}};
    // null where there is no fluid pair at all (JSON has no infinity)
    j["closest_fluid_pair"] = std::isfinite(n.closest_fluid_pair)
                                  ? nlohmann::json(n.closest_fluid_pair)
                                  : nlohmann::json(nullptr);
    return j;
}

// "dx/2": the threshold of crowded_below (spacing_census.hpp).
std::string spacing_sentence(const NeighbourCensus& n, Real dx) {
    std::string s = fmt::format(
        "{} of {} fluid particles ({:.2g} %) have a fluid neighbour closer than dx/2",
        n.fluid_crowded, n.fluid,
        n.fluid > 0 ? 100.0 * static_cast<double>(n.fluid_crowded) / static_cast<double>(n.fluid)
                    : 0.0);
    if (std::isfinite(n.closest_fluid_pair))
        s += fmt::format(", the closest pair is {:.3g} dx apart", n.closest_fluid_pair / dx);
    if (n.fluid_isolated > 0)
        s += fmt::format(", {} have no fluid neighbour", n.fluid_isolated);
    return s;
}

bool crowded_warning(const NeighbourCensus& n) {
    return n.fluid_crowded * 100 >= n.fluid && n.fluid_crowded > 0;
}

// Per-rank profile as a flat list of numbers (same layout on every rank).
template <int D>
std::vector<double> profile_numbers(const Simulation<D>& sim) {
    const auto& pr = sim.profile();
    std::vector<double> v(pr.stage_busy.begin(), pr.stage_busy.end());
    v.push_back(pr.halo_pack_busy);
    v.push_back(pr.busy());
    v.push_back(pr.graph_wall);
    v.push_back(pr.between_wall);
    v.push_back(pr.comm);
    v.push_back(pr.exposed);
    v.push_back(static_cast<double>(tasks::Comm::bytes_sent()));
    v.push_back(static_cast<double>(sim.owned()));
    v.push_back(pr.task_cpu);
    v.push_back(pr.halo_pack_cpu);
    for (std::size_t s = 0; s < pr.stage_busy.size(); ++s) // the stages' CPU, as stage_busy
        v.push_back(s < pr.stage_cpu.size() ? pr.stage_cpu[s] : 0.0);
    return v;
}

// The end-of-run table (rank 0) and its JSON form for summary.json.
nlohmann::json parallel_report(const std::vector<std::string>& stages,
                               const std::vector<std::vector<double>>& per_rank, bool print) {
    const std::size_t S = stages.size();
    nlohmann::json ranks = nlohmann::json::array();
    std::vector<double> busy;
    double comm = 0, exposed = 0, bytes = 0, task_cpu = 0;
    std::vector<double> stage_total(S, 0.0), stage_cpu_total(S, 0.0);
    if (print) {
        std::string head = "rank";
        for (const auto& s : stages)
            head += fmt::format(" {:>9}", s);
        fmt::print(stderr, "{} {:>9} {:>9} {:>9} {:>9} {:>9} {:>8} {:>10}\n", head, "halo", "busy",
                   "comm", "hidden", "idle-msg", "overlap", "sent");
    }
    for (std::size_t r = 0; r < per_rank.size(); ++r) {
        const auto& v = per_rank[r];
        nlohmann::json j;
        nlohmann::json st = nlohmann::json::object();
        for (std::size_t s = 0; s < S; ++s) {
            st[stages[s]] = v[s];
            stage_total[s] += v[s];
        }
        const double halo = v[S], b = v[S + 1], gw = v[S + 2], bw = v[S + 3], c = v[S + 4],
                     x = v[S + 5], sent = v[S + 6], owned = v[S + 7], cpu = v[S + 8],
                     halo_cpu = v[S + 9];
        nlohmann::json st_cpu = nlohmann::json::object();
        for (std::size_t s = 0; s < S; ++s) {
            st_cpu[stages[s]] = v[S + 10 + s];
            stage_cpu_total[s] += v[S + 10 + s];
        }
        j["rank"] = r;
        j["stage_busy_seconds"] = st;
        j["halo_pack_seconds"] = halo;
        j["busy_seconds"] = b;
        // The tasks' thread CPU time: their work, which busy_seconds (wall intervals)
        // overstates when ranks x threads exceed the cores.
        j["task_cpu_seconds"] = cpu;
        j["stage_task_cpu_seconds"] = st_cpu;
        j["halo_pack_cpu_seconds"] = halo_cpu;
        j["graph_wall_seconds"] = gw;
        j["between_steps_wall_seconds"] = bw;
        j["communication_seconds"] = c;
        j["idle_waiting_for_messages_seconds"] = x;
        j["hidden_communication_seconds"] = c - x;
        j["overlap_efficiency"] = c > 0 ? (c - x) / c : 1.0;
        j["bytes_sent"] = sent;
        j["particles_at_end"] = owned;
        ranks.push_back(j);
        busy.push_back(b);
        comm += c;
        exposed += x;
        bytes += sent;
        task_cpu += cpu;
        if (print) {
            std::string line = fmt::format("{:>4}", r);
            for (std::size_t s = 0; s < S; ++s)
                line += fmt::format(" {:>8.2f}s", v[s]);
            fmt::print(stderr,
                       "{} {:>8.2f}s {:>8.2f}s {:>8.3f}s {:>8.3f}s {:>8.3f}s {:>7.1f}% {:>10}\n",
                       line, halo, b, c, c - x, x, 100 * (c > 0 ? (c - x) / c : 1.0),
                       fmt::format("{:.1f} MB", sent / 1e6));
        }
    }
    nlohmann::json total;
    nlohmann::json st = nlohmann::json::object();
    for (std::size_t s = 0; s < S; ++s)
        st[stages[s]] = stage_total[s];
    total["stage_busy_seconds"] = st;
    total["task_cpu_seconds"] = task_cpu;
    nlohmann::json st_cpu = nlohmann::json::object();
    for (std::size_t s = 0; s < S; ++s)
        st_cpu[stages[s]] = stage_cpu_total[s];
    total["stage_task_cpu_seconds"] = st_cpu;
    total["communication_seconds"] = comm;
    total["idle_waiting_for_messages_seconds"] = exposed;
    total["hidden_communication_seconds"] = comm - exposed;
    total["overlap_efficiency"] = comm > 0 ? (comm - exposed) / comm : 1.0;
    total["load_imbalance"] = tasks::imbalance(busy);
    total["bytes_sent"] = bytes;
    if (print)
        fmt::print(stderr,
                   "total: overlap efficiency {:.1f}%, load imbalance (max/mean busy) {:.3f}, "
                   "{:.1f} MB sent\n",
                   100 * (comm > 0 ? (comm - exposed) / comm : 1.0), tasks::imbalance(busy),
                   bytes / 1e6);
    nlohmann::json out;
    out["ranks"] = ranks;
    out["total"] = total;
    return out;
}

template <int D>
void write_run_summary(const Simulation<D>& sim, const CaseConfig& cfg, const std::string& out_dir,
                       bool quiet, const RunResult& result, const RunFigures& f) {
    // Per-rank profile to rank 0.
    const auto mine = profile_numbers(sim);
    const auto gathered = sim.comm().gather(std::span<const std::byte>(
        reinterpret_cast<const std::byte*>(mine.data()), mine.size() * sizeof(double)));
    const double rebin_seconds = sim.rebin_seconds_total(); // rank 0's
    if (sim.comm().rank() != 0)
        return;

    std::vector<std::vector<double>> per_rank;
    for (const auto& b : gathered) {
        std::vector<double> v(b.size() / sizeof(double));
        std::memcpy(v.data(), b.data(), b.size());
        per_rank.push_back(std::move(v));
    }
    const auto names = sim.stage_names();
    const nlohmann::json parallel =
        parallel_report(names, per_rank, !quiet && sim.comm().parallel());

    nlohmann::json extra;
    const auto& graph = sim.graph();
    extra["stage_busy_seconds"] = parallel["total"]["stage_busy_seconds"];
    extra["rebin_seconds"] = rebin_seconds;
    extra["cell_groups"] = graph.group_count();
    extra["decompositions"] = sim.decompositions();
    extra["list_rebuilds"] = sim.list_rebuilds();
    // Steps whose graph started before the previous step's agreement completed, and those of
    // them run again (docs/ARCHITECTURE.md, "Time step").
    extra["steps_run_ahead"] = sim.steps_run_ahead();
    extra["steps_run_ahead_discarded"] = sim.steps_run_ahead_discarded();
    extra["last_dt"] = sim.dt();
    if (f.resumed)
        extra["restarted_from_step"] = f.start_step;
    // wall_seconds covers this segment; this, every segment since step 0.
    extra["wall_seconds_all_segments"] = f.earlier_wall_seconds + result.wall_seconds;
    extra["parallel"] = parallel;
    extra["neighbours"] = {{"support", f.support},
                           {"crowded_below", f.crowded},
                           {"start", census_json(f.census_start)},
                           {"end", census_json(f.census_end)}};
    nlohmann::json rebal = nlohmann::json::array();
    for (const auto& r : sim.rebalances())
        rebal.push_back({{"step", r.step},
                         {"imbalance_before", r.imbalance_before},
                         {"predicted_after", r.predicted_after},
                         {"particles_moved", r.particles_moved},
                         {"seconds", r.seconds},
                         {"at_rebuild", r.at_rebuild}});
    extra["rebalances"] = rebal;
    nlohmann::json hist = nlohmann::json::array();
    for (const auto& h : sim.balance_history())
        hist.push_back({{"step", h.step}, {"imbalance", h.imbalance}});
    extra["imbalance_history"] = hist;
    write_summary(out_dir, cfg, result, f.threads, sim.comm().size(), extra);
}

template std::vector<double> profile_numbers<2>(const Simulation<2>&);
template std::vector<double> profile_numbers<3>(const Simulation<3>&);
template void write_run_summary<2>(const Simulation<2>&, const CaseConfig&, const std::string&,
                                   bool, const RunResult&, const RunFigures&);
template void write_run_summary<3>(const Simulation<3>&, const CaseConfig&, const std::string&,
                                   bool, const RunResult&, const RunFigures&);

} // namespace sluice
