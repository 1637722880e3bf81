// Ramp (§4.2, §6.6.e): a straight line from start to end over the duration.
#include "../envelope.hpp"
#include "wave.hpp"

namespace feel::detail {

double ramp_wave(const EffectParams& p, int64_t tau_us) noexcept {
    const double progress = static_cast<double>(tau_us) / static_cast<double>(p.duration_us);
    const double value = p.ramp.start + (p.ramp.end - p.ramp.start) * progress;
    return p.has_envelope ? shape_by_envelope(p.envelope, value, tau_us, p.duration_us) : value;
}

}  // namespace feel::detail
