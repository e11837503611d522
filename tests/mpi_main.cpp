// doctest main for the MPI tests (run by ctest under mpiexec): MPI lives for the whole run;
// every rank runs every test case, so collective calls stay matched.
#define DOCTEST_CONFIG_IMPLEMENT
#include "sluice/tasks/comm.hpp"

#include <doctest/doctest.h>

int main(int argc, char** argv) {
    sluice::tasks::MpiSession mpi(&argc, &argv);
    doctest::Context context(argc, argv);
    if (sluice::tasks::Comm::world().rank() != 0)
        context.setOption("out", "/dev/null"); // one report, from rank 0
    return context.run();
}
