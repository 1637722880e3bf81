// Periodic waves (§6.6.b) and the Angle Sweep (§4.2.c, §6.6.i).
#include "../envelope.hpp"
#include "../waveform.hpp"
#include "wave.hpp"

namespace feel::detail {

// offset + envelope(|magnitude|) · sign(magnitude) · source(p). The envelope shapes the
// oscillation, not the baseline offset.
double periodic_wave(const EffectParams& p, int64_t tau_us) noexcept {
    const PeriodicBlock& b = p.periodic;
    const double source = waveform_value(waveform_of(p.type), cycle_fraction(tau_us, b.period_us, b.phase));
    const double amplitude =
        p.has_envelope ? shape_by_envelope(p.envelope, b.magnitude, tau_us, p.duration_us) : b.magnitude;
    return b.offset + amplitude * source;
}

// The direction moves linearly from the start angle to the end angle over the duration,
// the short or the long way round as the sense says: clockwise increases the compass angle.
// Equal start and end angles do not sweep.
double sweep_angle(const EffectParams& p, int64_t tau_us) noexcept {
    const PeriodicBlock& b = p.periodic;
    const double progress = static_cast<double>(tau_us) / static_cast<double>(p.duration_us);
    if (b.sweep_sense == SweepSense::clockwise) {
        const int32_t span = ((b.sweep_end_angle - b.sweep_start_angle) % 36000 + 36000) % 36000;
        return b.sweep_start_angle + span * progress;
    }
    const int32_t span = ((b.sweep_start_angle - b.sweep_end_angle) % 36000 + 36000) % 36000;
    return b.sweep_start_angle - span * progress;
}

}  // namespace feel::detail
