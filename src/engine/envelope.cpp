#include "envelope.hpp"

namespace feel::detail {

float envelope_level(const Envelope& env, float steady, int64_t tau_us, int64_t duration_us) noexcept {
    float level = steady;
    if (env.settle_time_us > 0 && tau_us < env.settle_time_us) {
        const float progress = static_cast<float>(tau_us) / static_cast<float>(env.settle_time_us);
        const float impulse = static_cast<float>(env.impulse_level);
        level = impulse + (steady - impulse) * progress;
    }
    if (duration_us != kInfiniteUs && env.fade_time_us > 0) {
        const int64_t fade_start = duration_us - env.fade_time_us;
        if (tau_us > fade_start) {
            const float progress =
                static_cast<float>(tau_us - fade_start) / static_cast<float>(env.fade_time_us);
            level = level + (static_cast<float>(env.fade_level) - level) * progress;
        }
    }
    return level;
}

float shape_by_envelope(const Envelope& env, float value, int64_t tau_us, int64_t duration_us) noexcept {
    if (value < 0) return -envelope_level(env, -value, tau_us, duration_us);
    return envelope_level(env, value, tau_us, duration_us);
}

}  // namespace feel::detail
