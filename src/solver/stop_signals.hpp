#pragma once
// SIGTERM and SIGINT as a request to stop cleanly (checkpoint, then exit) instead of dying.
// Private to the driver (run.cpp).
namespace sluice {

class StopSignals {
public:
    // Installs the handlers for the lifetime of the object. Each handler fires once: a second
    // SIGINT/SIGTERM gets the default action (an impatient Ctrl-C still kills).
    StopSignals();
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;

    // The signal received since construction (SIGTERM or SIGINT), or 0.
    [[nodiscard]] static int received();
};

} // namespace sluice
