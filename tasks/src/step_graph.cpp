#include "sluice/tasks/step_graph.hpp"

#include <tbb/flow_graph.h>

namespace sluice::tasks {

using tbb::flow::continue_msg;
using Node = tbb::flow::continue_node<continue_msg>;

struct StepGraph::Impl {
    tbb::flow::graph graph;
    tbb::flow::broadcast_node<continue_msg> start{graph};
    std::vector<std::unique_ptr<Node>> nodes; // index stage * groups + group
};

StepGraph::StepGraph(std::vector<StageSpec> stages, const std::vector<std::vector<int>>& neighbours,
                     Body body)
    : impl_(std::make_unique<Impl>()), stages_(std::move(stages)), neighbours_(neighbours),
      groups_(static_cast<int>(neighbours.size())), body_(std::move(body)) {
    const std::size_t n = stages_.size() * static_cast<std::size_t>(groups_);
    last_seconds_.assign(n, 0.0);
    impl_->nodes.reserve(n);
    for (int s = 0; s < stage_count(); ++s)
        for (int g = 0; g < groups_; ++g) {
            const std::size_t slot = static_cast<std::size_t>(s * groups_ + g);
            impl_->nodes.push_back(std::make_unique<Node>(impl_->graph, [this, s, g, slot](
                                                                            const continue_msg&) {
                const auto t0 = std::chrono::steady_clock::now();
                body_(s, g);
                last_seconds_[slot] =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            }));
        }
    auto node = [&](int s, int g) -> Node& {
        return *impl_->nodes[static_cast<std::size_t>(s * groups_ + g)];
    };
    for (int g = 0; g < groups_; ++g) {
        tbb::flow::make_edge(impl_->start, node(0, g));
    }
    for (int s = 1; s < stage_count(); ++s)
        for (int g = 0; g < groups_; ++g) {
            tbb::flow::make_edge(node(s - 1, g), node(s, g));
            if (stages_[static_cast<std::size_t>(s)].reach == Reach::neighbourhood)
                for (int nb : neighbours_[static_cast<std::size_t>(g)]) {
                    tbb::flow::make_edge(node(s - 1, nb), node(s, g));
                }
        }
}

StepGraph::~StepGraph() = default;

void StepGraph::run() {
    impl_->start.try_put(continue_msg());
    try {
        impl_->graph.wait_for_all();
    } catch (...) {
        impl_->graph.reset();
        throw;
    }
}

} // namespace sluice::tasks
