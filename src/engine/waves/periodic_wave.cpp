// Periodic waves (§6.6.b) and the Angle Sweep (§4.2.c, §6.6.i).
//
// What depends only on the command (the phase, the sweep's start and its travel in turns)
// is worked out once per command (prepare_periodic_block; the envelope's steady window by
// slot_params, as for every enveloped wave), not every tick, with the operations the tick used to do: the same floats, so the same
// forces.
#include "../envelope.hpp"
#include "../waveform.hpp"
#include "wave.hpp"

namespace feel::detail {

namespace {
constexpr float kTurnsPerCentideg = 1.0f / 36000.0f;
}  // namespace

void prepare_periodic_block(SlotParams& s) noexcept {
    SlotPeriodicBlock& b = s.periodic;
    b.phase_turns = static_cast<float>(b.phase) * kTurnsPerCentideg;
    b.sweep_start_turns = static_cast<float>(b.sweep_start_angle) * kTurnsPerCentideg;
    // The short or the long way round as the sense says: clockwise increases the compass
    // angle. Negating the travel is exact, so start + (−travel)·progress is start −
    // travel·progress to the bit.
    const bool clockwise = b.sweep_sense == SweepSense::clockwise;
    const int32_t from = clockwise ? b.sweep_start_angle : b.sweep_end_angle;
    const int32_t to = clockwise ? b.sweep_end_angle : b.sweep_start_angle;
    int32_t travel_centideg = (to - from) % 36000;  // in (−36000, 36000)
    if (travel_centideg < 0) travel_centideg += 36000;
    const float travel = static_cast<float>(travel_centideg) * kTurnsPerCentideg;
    b.sweep_span_turns = clockwise ? travel : -travel;
}

namespace {

// τ mod period (waveform.hpp's time_into_cycle); on x86 advanced from the last tick's when τ
// moved on by less than a period since (SlotPeriodicBlock::remainder_us), the division
// otherwise (the first tick, a restart, time gone back, a jump of a period or more).
[[gnu::always_inline]] inline int32_t advance_time_into_cycle(const SlotPeriodicBlock& b, int64_t tau_us) noexcept {
#if FEEL_KEEPS_CYCLE_REMAINDER
    if (tau_us > INT32_MAX) return time_into_cycle(tau_us, b.period_us);
    // In unsigned 32 bits: a τ before the kept one wraps to at least 2^31 (τ and the kept τ
    // are below 2^31), and so does INT32_MIN's, both beyond every period.
    const uint32_t step = static_cast<uint32_t>(tau_us) - static_cast<uint32_t>(b.remainder_at_tau_us);
    const auto period = static_cast<uint32_t>(b.period_us);
    uint32_t into = 0;
    if (step < period) {
        into = static_cast<uint32_t>(b.remainder_us) + step;  // below 2·period < 2^32
        if (into >= period) into -= period;
    } else {
        into = static_cast<uint32_t>(static_cast<int32_t>(tau_us) % b.period_us);
    }
    b.remainder_at_tau_us = static_cast<int32_t>(tau_us);
    b.remainder_us = static_cast<int32_t>(into);
    return static_cast<int32_t>(into);
#else
    return time_into_cycle(tau_us, b.period_us);
#endif
}

}  // namespace

// offset + envelope(|magnitude|) · sign(magnitude) · source(p). The envelope shapes the
// oscillation, not the baseline offset.
float periodic_wave(const SlotParams& p, Waveform waveform, int64_t tau_us) noexcept {
    const SlotPeriodicBlock& b = p.periodic;
    const float source = waveform_value(waveform, fraction_of_cycle(advance_time_into_cycle(b, tau_us), b.period_us, b.phase_turns));
    const float magnitude = static_cast<float>(b.magnitude);
    // Outside the attack and the fade the envelope gives the magnitude back (its sign kept):
    // the window was worked out with the command.
    const float amplitude = shape_outside_steady(p, b.steady, magnitude, tau_us);
    return static_cast<float>(b.offset) + amplitude * source;
}

// The direction moves linearly from the start angle to the end angle over the duration
// (prepare_periodic_block's travel). Equal start and end angles do not sweep.
float sweep_turns(const SlotParams& p, int64_t tau_us) noexcept {
    const SlotPeriodicBlock& b = p.periodic;
    const float progress = static_cast<float>(finite_tau(tau_us)) / static_cast<float>(p.duration_us);
    return b.sweep_start_turns + b.sweep_span_turns * progress;
}

}  // namespace feel::detail
