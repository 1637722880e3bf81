// feel::runtime — force streaming: the host closes the loop (§2.4).
//
// "By continually updating the magnitude and direction from the host in real time based on
// sensor readings reported from the hardware, the host can create its own complex force
// sensations." The host sends one force sample per axis (CommandKind::stream_force) at any
// rate up to 1 kHz; the device adds a force reconstructed from the samples to its effects'
// every tick of its own ~1 kHz loop.
//
// The problem. The local loop ticks ~17 times per sample of a 60 Hz game. Playing each
// sample as it arrives (a zero-order hold) gives a staircase: a 60 Hz buzz of force steps
// the hand feels as a rough texture that is not in the game. The device must fill in the
// ticks between samples, and it does not know the host's rate: hosts stream at 60, 100,
// 500 or 1000 Hz, and a game's frame time jitters.
//
// The choice: linear interpolation one sample interval behind, from where the output is.
// When a sample arrives the output ramps in a straight line from its present value to the
// sample over one estimated sample interval T, then holds the sample. Its properties:
//   * No overshoot, by construction: every output lies between the value the output had
//     when the newest sample came and that sample. The output never leaves the range of
//     the samples the host sent (a sine of amplitude A never feels larger than A).
//   * No steps: at 60 Hz on a 1 kHz loop a change of Δ between samples is spread over ~17
//     ticks, steps of Δ/17. A sample that comes early (jitter) starts its ramp from where
//     the output is, not from the previous sample, so it cannot step either.
//   * Latency: one interval T, the least a causal interpolator that never overshoots can
//     have (to draw the line from s[k-1] to s[k] it must have s[k]). 16.7 ms at 60 Hz, within
//     the primer's budget for host commands; at 1 kHz T is one tick and the ramp ends in the
//     tick the sample arrives: a 1 kHz stream passes through unchanged, with no delay.
// The alternatives lose on one side or the other. Extrapolating (a predictive first-order
// hold) has no latency but overshoots at every turn of the signal. A critically damped
// second-order filter is smoother (no corners) but only approaches the sample (an
// exponential tail, more latency for the same smoothness) and must be tuned to a rate the
// device does not know. Higher-order splines overshoot. Streams that must feel crisp are
// streamed faster; the filter adapts to the rate by itself.
//
// The interval estimate. T is the median of the last kIntervalHistory intervals between
// arrivals, in ticks, clamped to 1..max_interval_ticks (100 ms). A median ignores one late
// frame and a burst of two samples drained in consecutive ticks (which an average would let
// collapse T and step the output), yet follows a host that changes its rate within a few
// samples. Samples drained in the same tick count as one arrival: the newest wins. A gap
// longer than 100 ms is the stream pausing, not its rate, and is not recorded. Before the
// first interval is known T is a 60 Hz game frame, the slowest common rate.
//
// Holding. When the stream stops the output holds the last sample, for ever: the device
// cannot tell a host that stopped from one whose next frame is late, and a force that fades
// by itself would be a force the host did not command. What ends the stream: clear()
// (DISFFC_STOPALL, DISFFC_RESET) and the host-link watchdog (the safety monitor cuts every
// force while the host is silent and the pipeline clears the stream when it trips).
//
// Pause, gain, actuators and the motor limit are the pipeline's (add_streamed_force): the
// stream keeps its state while paused and its output is 0, the device gain scales it like
// an effect's, and the sum with the effects is clamped to ±10000 before the safety monitor.
//
// Time is the tick index; nothing here reads a clock, allocates, locks or throws.
#pragma once

#include <cstdint>

#include "feel/axis.hpp"

namespace feel::runtime {

class ForceStream {
public:
    // Arrival intervals the estimate remembers (odd: the median is one of them).
    static constexpr int kIntervalHistory = 7;
    // The slowest stream the filter spreads over its interval, µs: longer gaps are the
    // stream pausing. The longest ramp is this long.
    static constexpr int64_t kMaxIntervalUs = 100'000;
    // The interval assumed before one is measured, µs: a 60 Hz game frame.
    static constexpr int64_t kInitialIntervalUs = 16'667;

    // axis_count 1..kMaxAxes, loop_rate_hz > 0 (the ticks' rate; out-of-range values are
    // clamped: the pipeline passes its checked configuration).
    ForceStream(int32_t axis_count, int32_t loop_rate_hz) noexcept;

    // A sample arrived in tick `tick` (non-decreasing from push to push): force on each of
    // the axis_count axes, ±10000 (the pipeline validates the command; values are clamped
    // here all the same).
    void push(int64_t tick, const int16_t* force) noexcept;
    // The reconstructed force of tick `tick` (>= the last push's tick) on each axis, into
    // out[0..kMaxAxes) (0 beyond axis_count and before any sample).
    void output(int64_t tick, float out[kMaxAxes]) const noexcept;
    // No stream: the output is 0 from now on and the interval history is forgotten.
    void clear() noexcept;

    // True from a push until clear().
    [[nodiscard]] bool active() const noexcept { return active_; }
    // The sample interval the next ramp will use, ticks, 1..max_interval_ticks().
    [[nodiscard]] int32_t interval_ticks() const noexcept;
    [[nodiscard]] int32_t max_interval_ticks() const noexcept { return max_interval_ticks_; }
    // Samples pushed since construction (clear() keeps counting).
    [[nodiscard]] int64_t samples() const noexcept { return samples_; }
    [[nodiscard]] int32_t axis_count() const noexcept { return axis_count_; }

private:
    // The ramp's value on axis a at tick t: start + (target − start)·min(1, (t − ramp_tick
    // + 1)/ramp_ticks), exactly target once the ramp is done, start before it began.
    [[nodiscard]] double value_at(int axis, int64_t tick) const noexcept;

    int32_t axis_count_;
    int32_t max_interval_ticks_;
    int32_t initial_interval_ticks_;
    bool active_ = false;
    int64_t samples_ = 0;
    // The current ramp.
    int64_t ramp_tick_ = 0;     // the tick its sample arrived: its first tick
    int32_t ramp_ticks_ = 1;    // its length, ticks, >= 1
    double start_[kMaxAxes] = {};   // the output in the tick before ramp_tick_
    double target_[kMaxAxes] = {};  // the newest sample
    // Arrival intervals, ticks, a ring of the last `interval_count_` (<= kIntervalHistory).
    int32_t intervals_[kIntervalHistory] = {};
    int32_t interval_count_ = 0;
    int32_t interval_next_ = 0;
};

// Adds the streamed force to the effects' (`force`, the engine's output) in place, the way
// the engine treats an effect: scaled by the device gain (0..10000), 0 while `output_on` is
// false (paused, actuators off), the sum clamped to ±10000 on each of the first axis_count
// axes, and never NaN or infinite (a non-finite sum becomes 0).
void add_streamed_force(const float streamed[kMaxAxes], int32_t axis_count, int32_t gain, bool output_on,
                        float force[kMaxAxes]) noexcept;

}  // namespace feel::runtime
