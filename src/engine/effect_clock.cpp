#include "effect_clock.hpp"

namespace feel::detail {

ClockReading read_clock(const EffectParams& params, int64_t since_start_us) noexcept {
    return read_clock(params, params.iterations, since_start_us);
}

int64_t total_length_us(const EffectParams& params) noexcept {
    if (params.duration_us == kInfiniteUs || params.iterations == kInfiniteIterations) return kInfiniteUs;
    return params.start_delay_us + params.duration_us * params.iterations;
}

}  // namespace feel::detail
