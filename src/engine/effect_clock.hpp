// Where an effect is in its life, from the time since it was started.
//
//   started                                   finished
//   |<- start delay ->|<- duration ->|<- duration ->| ... (iterations plays)
//                     τ=0           τ=0            (τ restarts each iteration)
//
// The start delay is waited once, before the first iteration. An endless duration or
// endless iterations never finish.
#pragma once

#include <cstdint>

#include "feel/effect.hpp"
#include "int64_to_float.hpp"
#include "slot_params.hpp"
#include "time_division.hpp"

namespace feel::detail {

// A tick's length in seconds, as the conditions' and dynamics' contexts take it: µs / 10⁶ in
// float, the correctly rounded quotient (10⁶ is exact in float, and so is a length up to
// 2²⁴ µs, 16.7 s). For every such length it is the float that (float)(µs · 1e-6) in double
// gave, which is what every reader used when the contexts carried double, so no force moved
// by a bit (tests/engine/effect_clock_test.cpp checks each of 0..2²⁴ µs; µs · 1e-6f differs from it
// for 3% of them). A longer tick rounds its µs first and may differ from that in its last bit.
[[nodiscard]] inline float tick_seconds_of(int64_t dt_us) noexcept { return float_of_int64(dt_us) / 1e6f; }

// Whether a slot keeps where its current iteration began (Slot::iteration_start_us), so
// that the tick reads most clocks with one comparison (Slot::clock): on x86, not in the
// board's build for size, where the 8 bytes a slot are RAM (issue 14) and the second path
// flash; both read the same clocks.
#if !defined(__OPTIMIZE_SIZE__)
#define FEEL_KEEPS_ITERATION_START 1
#else
#define FEEL_KEEPS_ITERATION_START 0
#endif

enum class ClockPhase : uint8_t { delayed, playing, finished };

struct ClockReading {
    ClockPhase phase = ClockPhase::delayed;
    int64_t tau_us = 0;      // time into the current iteration (playing only)
    int32_t iteration = 0;   // 0-based iteration (playing only)
};

[[nodiscard]] ClockReading read_clock(const SlotParams& params, int64_t since_start_us) noexcept;
// The same with the iteration count of this play (Engine::start may override the effect's)
// and a guess at the iteration (the one the last tick found: Slot::completed_iterations).
// Inline: the tick reads every playing effect's clock (always: with the call to
// time_quotient inside, the M4 build's -Os stopped inlining it, 700 instructions a tick
// more for the 40-effect mix, for 72 bytes of flash). The iteration is t / duration, a
// 64-bit division (20 to 90 cycles on x86; time_division.hpp on a Cortex-M4); from one tick
// to the next it rarely changes, so the guess is tried first with a multiplication. When
// t - guess · duration lies in [0, duration) the guess is the floor of t / duration, the
// one integer the division gives (t ≥ 0 here), whatever the guess was: the reading is the
// same bits as without it, and a wrong guess only costs the division.
[[nodiscard, gnu::always_inline]] inline ClockReading read_clock(const SlotParams& params, int32_t iterations,
                                                                 int64_t since_start_us,
                                                                 int32_t iteration_guess = 0) noexcept {
    ClockReading r;
    const int64_t t = since_start_us - params.start_delay_us;
    if (t < 0) return r;
    if (params.duration_us == kInfiniteUs) {
        r.phase = ClockPhase::playing;
        r.tau_us = t;
        return r;
    }
    const int64_t guess = iteration_guess > 0 ? iteration_guess : 0;
    int64_t iteration = guess;
    int64_t tau = t - guess * params.duration_us;
    if (tau < 0 || tau >= params.duration_us) {
        iteration = time_quotient(t, params.duration_us);  // t ≥ 0, a duration > 0
        tau = t - iteration * params.duration_us;
    }
    if (iterations != kInfiniteIterations && iteration >= iterations) {
        r.phase = ClockPhase::finished;
        return r;
    }
    r.phase = ClockPhase::playing;
    r.iteration = static_cast<int32_t>(iteration);
    r.tau_us = tau;
    return r;
}

// The total time from start to finish, or kInfiniteUs.
[[nodiscard]] int64_t total_length_us(const SlotParams& params) noexcept;

}  // namespace feel::detail
