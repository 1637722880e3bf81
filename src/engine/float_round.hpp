// std::round and std::nextafter for float, bit for bit, without libm (issue 14's flash).
//
// On the Cortex-M4F (no rounding instruction) both are newlib calls, 204 bytes of flash
// that were the engine's last libm routines (docs/firmware.md). These give the same float
// as the library for every argument, ±0, infinities and NaN included
// (tests/engine/float_round_test.cpp compares them with std::round and std::nextafter).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "float_select.hpp"

namespace feel::detail {

// std::round(x): to the nearest whole number, halves away from zero, the sign of x kept
// (round(-0.3) is -0).
[[nodiscard]] inline float round_half_away(float x) noexcept {
    const float a = std::fabs(x);
    if (!(a < 0x1p23f)) return x;  // whole already (from 2^23 on), ±inf or NaN
    float whole = static_cast<float>(static_cast<int32_t>(a));  // truncation, exact
    // a − whole: exact (a's fraction). Adding 0 or 1 rather than jumping over the addition
    // (whole + 0 is whole, whole being >= +0): the conditions' bumps round a coordinate
    // that moves a good part of the spacing a tick, so their fraction is above or below ½
    // at random, and a jump on it was mispredicted about one call in four (issue 14, twelfth
    // pass, "The conditions' branches"). The Cortex-M4F predicts no branch: the build for
    // size keeps the jump, shorter there.
#if defined(__OPTIMIZE_SIZE__)
    if (a - whole >= 0.5f) whole += 1.0f;
#else
    whole += select_if_at_least(a - whole, 0.5f, 1.0f, 0.0f);  // (a plain ?: became a jump again next to the bump's cosine)
#endif
    return std::copysign(whole, x);
}

// round_half_away(x / step) for a step > 0 given inverse_step = 1/step (rounded to float),
// but for the sign of a zero result: a grating's index of the ridge
// nearest x, whose sign its caller does not read (step·(±0) only moves x's own zero). On
// x86 it skips the division and round_half_away's conversions, the head of the bumps'
// chains (issue 14, thirteenth pass): q = x·inverse_step is within |x/step|·2^-23 of x/step
// (two roundings of 2^-24) and fl(x/step) within half of that, so where q lies further than
// |q|·2^-21 from every half, both round to the same whole number, which adding and taking
// off 1.5·2^23 gives (to even at a half, but q is no half). Elsewhere (near a half, |q| from
// 2^20 on, NaN, infinities) the division and round_half_away, as before.
[[nodiscard, gnu::always_inline]] inline float nearest_multiple_index(float x, float step, float inverse_step) noexcept {
#if !defined(__OPTIMIZE_SIZE__)
    constexpr float kRound = 0x1.8p23f;
    const float q = x * inverse_step;
    const float whole = (q + kRound) - kRound;
    // (|q − whole| is exact: whole is within 1 of q and a whole number. The bound's rounding,
    // at most 2^-26, is within the factor 2 it keeps over the roundings' 2^-22.)
    if (std::fabs(q - whole) < 0.5f - std::fabs(q) * 0x1p-21f) return whole;
#else
    (void)inverse_step;
#endif
    return round_half_away(x / step);
}

// std::nextafter(x, up ? +inf : -inf): the next float above or below x.
[[nodiscard]] inline float next_float(float x, bool up) noexcept {
    constexpr float kInf = std::numeric_limits<float>::infinity();
    if (x != x || x == (up ? kInf : -kInf)) return x;
    if (x == 0) return up ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
    // Away from zero the magnitude's bits count up, toward it down (-FLT_MAX from -inf too).
    const uint32_t bits = std::bit_cast<uint32_t>(x);
    return std::bit_cast<float>((x > 0) == up ? bits + 1 : bits - 1);
}

}  // namespace feel::detail
