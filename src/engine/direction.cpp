#include "direction.hpp"

#include <cmath>
#include <numbers>

#include "turn_trig.hpp"

namespace feel::detail {
namespace {

constexpr double kRadPerCentideg = std::numbers::pi / 18000.0;

// sin and cos of an angle in hundredths of a degree, exact at the four cardinal points so
// that a force from due east has no stray 1e-12 on the y axis. The angle is reduced in
// integers: the same value fmod gives an integer (every angle is an int32 field), without
// linking libm's fmod into the firmware (issue 14: flash).
void sin_cos(int32_t centideg, double& s, double& c) noexcept {
    int32_t whole_turns_off = centideg % 36000;
    if (whole_turns_off < 0) whole_turns_off += 36000;
    const double a = whole_turns_off;
    if (a == 0.0) { s = 0; c = 1; return; }
    if (a == 9000.0) { s = 1; c = 0; return; }
    if (a == 18000.0) { s = 0; c = -1; return; }
    if (a == 27000.0) { s = -1; c = 0; return; }
    s = std::sin(a * kRadPerCentideg);
    c = std::cos(a * kRadPerCentideg);
}

void clear(float factors[kMaxAxes]) noexcept {
    for (int i = 0; i < kMaxAxes; ++i) factors[i] = 0.0f;
}

// The force is opposite to the "from" vector, spread over the effect's axes in order.
void from_vector(const SlotParams& params, const double* from, int n, float factors[kMaxAxes]) noexcept {
    double norm = 0;
    for (int i = 0; i < n; ++i) norm += from[i] * from[i];
    norm = std::sqrt(norm);
    if (!(norm > 0)) return;  // the validator rejects a zero vector; stay silent, never NaN
    for (int i = 0; i < n && i < params.axis_count; ++i) {
        factors[axis_index(params.axes[i])] = static_cast<float>(-from[i] / norm);
    }
}

}  // namespace

void polar_factors(int32_t angle_centideg, float factors[kMaxAxes]) noexcept {
    clear(factors);
    double s = 0, c = 0;
    sin_cos(angle_centideg, s, c);
    factors[axis_index(Axis::x)] = static_cast<float>(-s);
    factors[axis_index(Axis::y)] = static_cast<float>(-c);
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
            const double from[3] = {static_cast<double>(d.value(0)), static_cast<double>(d.value(1)),
                                    static_cast<double>(d.value(2))};
            from_vector(params, from, params.axis_count < 3 ? params.axis_count : 3, factors);
            return;
        }
        case DirectionKind::spherical: {
            double sin_az = 0, cos_az = 0, sin_el = 0, cos_el = 0;
            sin_cos(d.value(0), sin_az, cos_az);
            sin_cos(d.value(1), sin_el, cos_el);
            const double from[3] = {sin_el * cos_az, sin_el * sin_az, cos_el};
            // Spherical directions are over x, y, z by definition, whatever the axis order.
            factors[axis_index(Axis::x)] = static_cast<float>(-from[0]);
            factors[axis_index(Axis::y)] = static_cast<float>(-from[1]);
            factors[axis_index(Axis::z)] = static_cast<float>(-from[2]);
            return;
        }
    }
}

}  // namespace feel::detail
