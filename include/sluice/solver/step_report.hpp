#pragma once
// What one rank reports of a step to the others (src/solver/step_agreement.cpp): sent as soon
// as the step's graph has finished, collected where the decision is first needed.
#include "sluice/tasks/comm.hpp"

#include <cstdint>
#include <string>

namespace sluice {

// Fixed size, so that one all-gather round carries it (no round for the sizes).
struct StepReport {
    double acoustic = 0, viscous = 0, force = 0; // time-step limits [s]
    double speed = 0, disp2 = 0;                 // largest speed, squared displacement
    double busy = 0;                             // task seconds of the step (the balancer)
    std::int64_t failed = 0;                     // StepFailure
    std::int64_t requests = 0;                   // StepRequest flags
    std::int64_t leaving = 0;                    // fluid particles outside the domain (removed)
};

enum StepFailure : std::int64_t { failure_none = 0, failure_physical = 1, failure_internal = 2 };

// A rank's report in flight: what it sent, its own failure message (broadcast only if the
// ranks agree that it is the first failing rank), and the all-gather that carries it.
struct PendingStepReport {
    StepReport mine;
    std::string failure;
    tasks::PendingAllGather gather;
    double posted = 0; // clock_seconds() when it left
};

} // namespace sluice
