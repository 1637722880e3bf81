#include "envelope.hpp"

namespace feel::detail {

double envelope_level(const Envelope& env, double steady, int64_t tau_us,
                      int64_t duration_us) noexcept {
    double level = steady;
    if (env.settle_time_us > 0 && tau_us < env.settle_time_us) {
        const double progress = static_cast<double>(tau_us) / static_cast<double>(env.settle_time_us);
        level = env.impulse_level + (steady - env.impulse_level) * progress;
    }
    if (duration_us != kInfiniteUs && env.fade_time_us > 0) {
        const int64_t fade_start = duration_us - env.fade_time_us;
        if (tau_us > fade_start) {
            const double progress =
                static_cast<double>(tau_us - fade_start) / static_cast<double>(env.fade_time_us);
            level = level + (env.fade_level - level) * progress;
        }
    }
    return level;
}

double shape_by_envelope(const Envelope& env, double value, int64_t tau_us,
                         int64_t duration_us) noexcept {
    if (value < 0) return -envelope_level(env, -value, tau_us, duration_us);
    return envelope_level(env, value, tau_us, duration_us);
}

}  // namespace feel::detail
