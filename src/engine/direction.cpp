#include "direction.hpp"

#include <cmath>

#include "turn_trig.hpp"

namespace feel::detail {
namespace {

// sin and cos of an angle in hundredths of a degree, in float (issue 14: no double on the
// Cortex-M4F), exact at the four cardinal points so that a force from due east has no
// stray rounding on the y axis. The angle is reduced in integers to [0, 36000) (every
// angle is an int32 field), then taken in turns by turn_trig.hpp's polynomial: the
// quarter turns are exact in float (9000/36000 = 0.25), where it gives exactly 0 and ±1,
// and elsewhere it is within about 1.2e-7 of sin and cos, with the turn's rounding (2^-24
// relative) on top: the factors are float either way.
void sin_cos(int32_t centideg, float& s, float& c) noexcept {
    int32_t whole_turns_off = centideg % 36000;
    if (whole_turns_off < 0) whole_turns_off += 36000;
    const float turns = static_cast<float>(whole_turns_off) / 36000.0f;
    s = sin_turns(turns);
    c = cos_turns(turns);
}

void clear(float factors[kMaxAxes]) noexcept {
    for (int i = 0; i < kMaxAxes; ++i) factors[i] = 0.0f;
}

// The force is opposite to the "from" vector, spread over the effect's axes in order.
void from_vector(const SlotParams& params, const float* from, int n, float factors[kMaxAxes]) noexcept {
    float norm = 0;
    for (int i = 0; i < n; ++i) norm += from[i] * from[i];
    norm = std::sqrt(norm);
    if (!(norm > 0)) return;  // the validator rejects a zero vector; stay silent, never NaN
    for (int i = 0; i < n && i < params.axis_count; ++i) {
        factors[axis_index(params.axes[i])] = -from[i] / norm;
    }
}

}  // namespace

void polar_factors(int32_t angle_centideg, float factors[kMaxAxes]) noexcept {
    clear(factors);
    float s = 0, c = 0;
    sin_cos(angle_centideg, s, c);
    factors[axis_index(Axis::x)] = -s;
    factors[axis_index(Axis::y)] = -c;
}

void polar_factors_turns(float turns, float factors[kMaxAxes]) noexcept {
    clear(factors);
    factors[axis_index(Axis::x)] = -sin_turns(turns);
    factors[axis_index(Axis::y)] = -cos_turns(turns);
}

void direction_factors(const SlotParams& params, float factors[kMaxAxes]) noexcept {
    clear(factors);
    const SlotDirection& d = params.direction;
    switch (d.kind) {
        case DirectionKind::none:
            factors[axis_index(params.axes[0])] = 1.0f;
            return;
        case DirectionKind::polar:
            polar_factors(d.value(0), factors);
            return;
        case DirectionKind::cartesian:
        case DirectionKind::moments: {
            // Components up to 10000: their squares' sum is within float's 24 bits' rounding.
            const float from[3] = {static_cast<float>(d.value(0)), static_cast<float>(d.value(1)),
                                   static_cast<float>(d.value(2))};
            from_vector(params, from, params.axis_count < 3 ? params.axis_count : 3, factors);
            return;
        }
        case DirectionKind::spherical: {
            float sin_az = 0, cos_az = 0, sin_el = 0, cos_el = 0;
            sin_cos(d.value(0), sin_az, cos_az);
            sin_cos(d.value(1), sin_el, cos_el);
            const float from[3] = {sin_el * cos_az, sin_el * sin_az, cos_el};
            // Spherical directions are over x, y, z by definition, whatever the axis order.
            factors[axis_index(Axis::x)] = -from[0];
            factors[axis_index(Axis::y)] = -from[1];
            factors[axis_index(Axis::z)] = -from[2];
            return;
        }
    }
}

}  // namespace feel::detail
