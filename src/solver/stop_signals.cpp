#include "stop_signals.hpp"

#include <csignal>

namespace sluice {

namespace {

volatile std::sig_atomic_t g_received = 0;

// Async-signal-safe: only stores the number.
extern "C" void on_stop_signal(int sig) {
    g_received = sig;
}

struct sigaction g_old_term {
}, g_old_int{};

} // namespace

StopSignals::StopSignals() {
    g_received = 0;
    struct sigaction sa {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART | SA_RESETHAND;
    sigaction(SIGTERM, &sa, &g_old_term);
    sigaction(SIGINT, &sa, &g_old_int);
}

StopSignals::~StopSignals() {
    sigaction(SIGTERM, &g_old_term, nullptr);
    sigaction(SIGINT, &g_old_int, nullptr);
}

int StopSignals::received() {
    return g_received;
}

} // namespace sluice
