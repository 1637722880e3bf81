#include "effect_clock.hpp"

namespace feel::detail {

ClockReading read_clock(const EffectParams& params, int64_t since_start_us) noexcept {
    return read_clock(params, params.iterations, since_start_us);
}

ClockReading read_clock(const EffectParams& params, int32_t iterations, int64_t since_start_us) noexcept {
    ClockReading r;
    const int64_t t = since_start_us - params.start_delay_us;
    if (t < 0) return r;
    if (params.duration_us == kInfiniteUs) {
        r.phase = ClockPhase::playing;
        r.tau_us = t;
        return r;
    }
    const int64_t iteration = t / params.duration_us;
    if (iterations != kInfiniteIterations && iteration >= iterations) {
        r.phase = ClockPhase::finished;
        return r;
    }
    r.phase = ClockPhase::playing;
    r.iteration = static_cast<int32_t>(iteration);
    r.tau_us = t - iteration * params.duration_us;
    return r;
}

int64_t total_length_us(const EffectParams& params) noexcept {
    if (params.duration_us == kInfiniteUs || params.iterations == kInfiniteIterations) return kInfiniteUs;
    return params.start_delay_us + params.duration_us * params.iterations;
}

}  // namespace feel::detail
