// Periodic waves (§6.6.b) and the Angle Sweep (§4.2.c, §6.6.i).
#include "../envelope.hpp"
#include "../waveform.hpp"
#include "wave.hpp"

namespace feel::detail {

// offset + envelope(|magnitude|) · sign(magnitude) · source(p). The envelope shapes the
// oscillation, not the baseline offset.
float periodic_wave(const SlotParams& p, Waveform waveform, int64_t tau_us) noexcept {
    const SlotPeriodicBlock& b = p.periodic;
    const float source = waveform_value(waveform, cycle_fraction(tau_us, b.period_us, b.phase));
    const float magnitude = static_cast<float>(b.magnitude);
    const float amplitude =
        p.has_envelope ? shape_by_envelope(p.envelope, magnitude, tau_us, p.duration_us) : magnitude;
    return static_cast<float>(b.offset) + amplitude * source;
}

// The direction moves linearly from the start angle to the end angle over the duration,
// the short or the long way round as the sense says: clockwise increases the compass angle.
// Equal start and end angles do not sweep.
float sweep_turns(const SlotParams& p, int64_t tau_us) noexcept {
    const SlotPeriodicBlock& b = p.periodic;
    const float progress = static_cast<float>(finite_tau(tau_us)) / static_cast<float>(p.duration_us);
    constexpr float kTurnsPerCentideg = 1.0f / 36000.0f;
    const float start = static_cast<float>(b.sweep_start_angle) * kTurnsPerCentideg;
    if (b.sweep_sense == SweepSense::clockwise) {
        const int32_t span = ((b.sweep_end_angle - b.sweep_start_angle) % 36000 + 36000) % 36000;
        return start + static_cast<float>(span) * kTurnsPerCentideg * progress;
    }
    const int32_t span = ((b.sweep_start_angle - b.sweep_end_angle) % 36000 + 36000) % 36000;
    return start - static_cast<float>(span) * kTurnsPerCentideg * progress;
}

}  // namespace feel::detail
