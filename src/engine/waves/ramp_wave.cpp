// Ramp (§4.2, §6.6.e): a straight line from start to end over the duration.
#include "../envelope.hpp"
#include "wave.hpp"

namespace feel::detail {

float ramp_wave(const SlotParams& p, int64_t tau_us) noexcept {
    const float progress = static_cast<float>(finite_tau(tau_us)) / static_cast<float>(p.duration_us);
    const float value = static_cast<float>(p.ramp.start) + static_cast<float>(p.ramp.end - p.ramp.start) * progress;
    return shape_outside_steady(p, p.ramp.steady, value, tau_us);
}

}  // namespace feel::detail
