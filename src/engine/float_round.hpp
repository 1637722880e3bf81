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
