// Proof that the ThreadSanitizer stage checks the task graph's edges (tasks/src/tsan_sync.hpp).
// Two groups, neighbours of each other, two stages: (stage 0, group 0) writes a value that
// (stage 1, group 1) reads, as a neighbourhood stage reads its neighbours' previous results.
//   declared  stage 1 has neighbourhood reach: the edge (0,0) -> (1,1) exists; TSan is silent.
//   missing   stage 1 is declared with self reach: the edge is missing, and TSan must report
//             the data race on `value` (tests/tsan/expect_race.sh checks that it does).
// In `missing`, the two tasks first wait for each other (relaxed atomics, which TSan does not
// count as ordering), so that they run at the same time on two threads: one thread running
// both in turn would be ordered by program order, and TSan could not see the missing edge.
// Exit code 0 when the value read is the one written; 3 if the tasks never met.
#include "sluice/tasks/step_graph.hpp"

#include <tbb/global_control.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <string_view>
#include <thread>

namespace {

// Spins until `flag` is set; false after 10 s (fewer than two threads ran the tasks).
bool wait_for(const std::atomic<bool>& flag) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (!flag.load(std::memory_order_relaxed))
        if (std::chrono::steady_clock::now() > give_up)
            return false;
        else
            std::this_thread::yield();
    return true;
}

} // namespace

int main(int argc, char** argv) {
    using namespace sluice::tasks;
    const bool missing = argc > 1 && std::string_view(argv[1]) == "missing";
    tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);

    double value = 0; // written by (0, 0), read by (1, 1)
    double seen = -1;
    std::atomic<bool> reader_started{false}, written{false};
    bool writer_met = true, reader_met = true;
    StepGraph graph(
        {{"write", Reach::self}, {"read", missing ? Reach::self : Reach::neighbourhood}},
        {{1}, {0}}, [&](int stage, int group) {
            if (stage == 0 && group == 0) {
                if (missing)
                    writer_met = wait_for(reader_started);
                value = 42;
                written.store(true, std::memory_order_relaxed);
            } else if (stage == 1 && group == 1) {
                reader_started.store(true, std::memory_order_relaxed);
                if (missing)
                    reader_met = wait_for(written);
                seen = value;
            }
        });
    graph.run();
    if (!writer_met || !reader_met) {
        std::puts("missing_edge: the two tasks did not run at the same time");
        return 3;
    }
    std::printf("missing_edge: read %g\n", seen);
    return seen == 42 ? 0 : 1;
}
