#include "waveform.hpp"

#include <cmath>
#include <numbers>

namespace feel::detail {

double waveform_value(Waveform w, double p) noexcept {
    switch (w) {
        case Waveform::sine: return std::sin(2.0 * std::numbers::pi * p);
        case Waveform::square: return p < 0.5 ? 1.0 : -1.0;
        case Waveform::triangle:
            if (p < 0.25) return 4.0 * p;
            if (p < 0.75) return 2.0 - 4.0 * p;
            return 4.0 * p - 4.0;
        case Waveform::saw_up: return 2.0 * p - 1.0;
        case Waveform::saw_down: return 1.0 - 2.0 * p;
    }
    return 0.0;
}

double cycle_fraction(int64_t tau_us, int64_t period_us, int32_t phase) noexcept {
    const int64_t into_cycle = tau_us % period_us;
    double p = static_cast<double>(into_cycle) / static_cast<double>(period_us) +
               static_cast<double>(phase) / 36000.0;
    if (p >= 1.0) p -= 1.0;
    return p;
}

}  // namespace feel::detail
