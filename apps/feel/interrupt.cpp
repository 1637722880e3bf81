// The stop flag and the handlers that set it (interrupt.hpp).
#include "interrupt.hpp"

#include <signal.h>

namespace feel::cli {
namespace {

// A signal handler may only touch lock-free atomics.
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> g_stop{false};

extern "C" void on_stop_signal(int /*signal*/) { g_stop.store(true, std::memory_order_relaxed); }

struct sigaction stop_action() {
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    return action;
}

}  // namespace

std::atomic<bool>& stop_requested() noexcept { return g_stop; }

ScopedStopSignals::ScopedStopSignals() {
    const struct sigaction action = stop_action();
    sigaction(SIGINT, &action, &previous_int_);
    sigaction(SIGTERM, &action, &previous_term_);
}

ScopedStopSignals::~ScopedStopSignals() {
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
}

}  // namespace feel::cli
