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

// offset + envelope(|magnitude|) · sign(magnitude) · source(p). The envelope shapes the
// oscillation, not the baseline offset.
float periodic_wave(const SlotParams& p, Waveform waveform, int64_t tau_us) noexcept {
    const SlotPeriodicBlock& b = p.periodic;
    const float source = waveform_value(waveform, cycle_fraction(tau_us, b.period_us, b.phase_turns));
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
