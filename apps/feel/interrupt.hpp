// Stopping a long-running command cleanly: a process-wide "stop" request.
//
// `feel device`, `feel play`, `feel stream` and `feel monitor` run until their work ends,
// a time passes, or the user asks them to stop (Ctrl-C, or SIGTERM from a service manager
// or a test). The signal handler may do almost nothing (async-signal safety), so it only
// sets a lock-free atomic flag; the commands poll it between steps (every few ms) and then
// stop, clean up (a device removes its socket) and print their summary.
#pragma once

#include <atomic>
#include <csignal>

namespace feel::cli {

// The request. run() clears it before each command; the handlers below set it.
[[nodiscard]] std::atomic<bool>& stop_requested() noexcept;

// Installs SIGINT and SIGTERM handlers that set stop_requested() for its lifetime and
// restores the previous ones after. Each handler is one-shot (SA_RESETHAND): a second
// Ctrl-C ends a process that did not stop by itself the default way.
class ScopedStopSignals {
public:
    ScopedStopSignals();
    ~ScopedStopSignals();
    ScopedStopSignals(const ScopedStopSignals&) = delete;
    ScopedStopSignals& operator=(const ScopedStopSignals&) = delete;

private:
    struct sigaction previous_int_ {};
    struct sigaction previous_term_ {};
};

}  // namespace feel::cli
