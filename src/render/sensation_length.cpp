// How long a sensation lasts, and how long to render it by default.
#include <algorithm>

#include "feel/render/render.hpp"

namespace feel::render {
namespace {

// Long enough to see the sensation end and the handle settle, short enough not to bury
// a short sensation in silence.
constexpr double kTailFraction = 0.10;
constexpr double kMinTailS = 0.100;
constexpr double kEndlessRenderS = 2.0;

}  // namespace

std::optional<int64_t> sensation_length_us(const format::Sensation& sensation) noexcept {
    int64_t length = 0;
    for (const format::EffectSpec& effect : sensation.effects) {
        const EffectParams& p = effect.params;
        if (p.duration_us == kInfiniteUs || p.iterations == kInfiniteIterations) return std::nullopt;
        // Both factors are validated (≤ 65e6 µs and ≤ 255), so the product fits easily.
        const int64_t end = p.start_delay_us + p.duration_us * std::max<int64_t>(p.iterations, 1);
        length = std::max(length, end);
    }
    return length;
}

double default_duration_s(const format::Sensation& sensation) noexcept {
    const std::optional<int64_t> length_us = sensation_length_us(sensation);
    if (!length_us) return kEndlessRenderS;
    const double length_s = static_cast<double>(*length_us) * 1e-6;
    return length_s + std::max(kMinTailS, kTailFraction * length_s);
}

}  // namespace feel::render
