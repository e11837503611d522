// doctest main that joins oneTBB's worker threads before exit, so LeakSanitizer does not
// report their per-thread runtime state as leaked.
#define DOCTEST_CONFIG_IMPLEMENT
#define TBB_PREVIEW_WAITING_FOR_WORKERS 1
#include <doctest/doctest.h>
#include <tbb/global_control.h>

int main(int argc, char** argv) {
    tbb::task_scheduler_handle handle{tbb::attach{}};
    doctest::Context context(argc, argv);
    const int result = context.run();
    tbb::finalize(handle, std::nothrow);
    return result;
}
