#pragma once
// ThreadSanitizer's view of the task graph's ordering. Debian's oneTBB is not built with
// -fsanitize=thread, so TSan cannot see that a task runs after the tasks it was spawned by,
// nor that graph.wait_for_all() returns after every task. The step graph tells it instead,
// with TSan's annotation API, exactly the happens-before edges it declares: a node releases
// its own token when its body ends and acquires its predecessors' tokens when it starts. TSan
// then checks that these edges order every conflicting access of the node bodies; an edge
// missing from the graph is reported as a data race (tests/tsan/missing_edge.cpp).
// Outside a TSan build both functions are empty.
#if defined(__SANITIZE_THREAD__)
#define SLUICE_TSAN 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define SLUICE_TSAN 1
#endif
#endif

#ifdef SLUICE_TSAN
#include <sanitizer/tsan_interface.h>
#endif

namespace sluice::tasks::tsan {

#ifdef SLUICE_TSAN
inline constexpr bool active = true;
#else
inline constexpr bool active = false;
#endif

// Everything this thread did so far happens before whatever a later acquire(token) follows.
inline void release([[maybe_unused]] const void* token) {
#ifdef SLUICE_TSAN
    __tsan_release(const_cast<void*>(token));
#endif
}

// What was done before every earlier release(token) happens before what this thread does next.
inline void acquire([[maybe_unused]] const void* token) {
#ifdef SLUICE_TSAN
    __tsan_acquire(const_cast<void*>(token));
#endif
}

} // namespace sluice::tasks::tsan
