#pragma once
// One step as a dependency graph: a node per (stage, cell group). A stage that reads its
// neighbours' results of the previous stage ("neighbourhood" reach) waits for the previous
// stage of the group and of every adjacent group; a "self" stage waits for its own group only.
// There is no barrier between stages beyond these edges. The graph is built once per
// decomposition and replayed every step (tbb::flow continue_nodes re-arm after each run).
#include "sluice/tasks/decomposition.hpp"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sluice::tasks {

enum class Reach { self, neighbourhood };

struct StageSpec {
    std::string name;
    Reach reach = Reach::neighbourhood; // what the stage needs of the previous stage
};

class StepGraph {
public:
    // body(stage, group) does the work of one node. It must touch only the group's own
    // particles for writing.
    using Body = std::function<void(int stage, int group)>;

    StepGraph(std::vector<StageSpec> stages, const std::vector<std::vector<int>>& neighbours,
              Body body);
    ~StepGraph();
    StepGraph(const StepGraph&) = delete;
    StepGraph& operator=(const StepGraph&) = delete;

    // Runs every node once, in dependency order, and returns when all have finished.
    // An exception thrown by a node body is rethrown here (after the graph is reset).
    void run();

    [[nodiscard]] int stage_count() const { return static_cast<int>(stages_.size()); }
    [[nodiscard]] int group_count() const { return groups_; }
    [[nodiscard]] const std::vector<StageSpec>& stages() const { return stages_; }
    [[nodiscard]] const std::vector<std::vector<int>>& neighbours() const { return neighbours_; }

    // Busy seconds of each (stage, group) node in the last run.
    [[nodiscard]] double node_seconds(int stage, int group) const {
        return last_seconds_[static_cast<std::size_t>(stage * groups_ + group)];
    }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::vector<StageSpec> stages_;
    std::vector<std::vector<int>> neighbours_;
    int groups_ = 0;
    Body body_;
    std::vector<double> last_seconds_;
};

} // namespace sluice::tasks
