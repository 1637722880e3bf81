#include "effect_clock.hpp"

namespace feel::detail {

ClockReading read_clock(const SlotParams& params, int64_t since_start_us) noexcept {
    return read_clock(params, params.iterations, since_start_us);
}

int64_t total_length_us(const SlotParams& params) noexcept {
    if (params.duration_us == kInfiniteUs || params.iterations == kInfiniteIterations) return kInfiniteUs;
    return params.start_delay_us + int64_t{params.duration_us} * params.iterations;
}

}  // namespace feel::detail
