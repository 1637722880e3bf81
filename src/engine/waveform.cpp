#include "waveform.hpp"

#include "turn_trig.hpp"

namespace feel::detail {

float waveform_value(Waveform w, float p) noexcept {
    switch (w) {
        case Waveform::sine: return sin_turns(p);
        case Waveform::square: return p < 0.5f ? 1.0f : -1.0f;
        case Waveform::triangle:
            if (p < 0.25f) return 4.0f * p;
            if (p < 0.75f) return 2.0f - 4.0f * p;
            return 4.0f * p - 4.0f;
        case Waveform::saw_up: return 2.0f * p - 1.0f;
        case Waveform::saw_down: return 1.0f - 2.0f * p;
    }
    return 0.0f;
}

float cycle_fraction(int64_t tau_us, int64_t period_us, int32_t phase) noexcept {
    const int64_t into_cycle = tau_us % period_us;
    float p = static_cast<float>(into_cycle) / static_cast<float>(period_us) +
              static_cast<float>(phase) * (1.0f / 36000.0f);
    // Rounding may land a hair's breadth below the period on 1 itself: that is the cycle's start.
    if (p >= 1.0f) p -= 1.0f;
    if (p >= 1.0f) p = 0.0f;
    return p;
}

}  // namespace feel::detail
