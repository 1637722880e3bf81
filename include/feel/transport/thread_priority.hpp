// feel::transport — a report's way out at a real-time priority.
//
// A state report leaves the device's 1 kHz loop and crosses three threads before a host
// program sees it: the device's service thread (woken by the loop's doorbell), the host's
// I/O thread (woken by the connection) and, in the Studio, the sampler that records it for
// the plot and the pad. Each is an ordinary thread, so while other work holds the cores (a
// browser drawing the Studio takes most of one) each wake-up may wait for a scheduler
// slice; on this project's 2-core VM that put the report's way (target set → the report of
// the tick that took it) at p99 1.3–2.6 ms where its median is 0.8 ms (docs/studio.md,
// "After both ninth passes"). Asked for, these threads run under SCHED_FIFO at a priority
// below the loop's (80 by default), where the process may, like the loop itself.
//
// Off (0) by default everywhere: a game's I/O thread at a real-time priority is the game's
// decision. The threads it is for only move frames (they never parse a browser's input), so
// at a real-time priority they cannot hold a core for another program.
//
// Not real-time safe (a system call); called once, at the start of the thread it raises.
#pragma once

#include <cstdint>
#include <string>

namespace feel::transport {

// Linux's SCHED_FIFO priorities; 0 in an option means "an ordinary thread".
inline constexpr int32_t kMinFifoPriority = 1;
inline constexpr int32_t kMaxFifoPriority = 99;

// What the calling thread runs under after raise_thread_priority.
struct ThreadPriority {
    bool fifo = false;     // SCHED_FIFO
    int32_t priority = 0;  // its SCHED_FIFO priority, 0 when not fifo
    std::string note;      // one line: "SCHED_FIFO priority 10", or why it stayed ordinary
};

// 0: leaves the calling thread as it is ("not asked for"). 1..99: asks for SCHED_FIFO at
// that priority; a refusal (no privilege) leaves the thread ordinary and says why. Any other
// value changes nothing and the note names the allowed range (options are checked where
// they are given; this is the last guard).
[[nodiscard]] ThreadPriority raise_thread_priority(int32_t priority);

// "" when `priority` is 0 or within 1..99; else what is wrong, naming `field` and the range.
[[nodiscard]] std::string check_fifo_priority(const char* field, int32_t priority);

}  // namespace feel::transport
