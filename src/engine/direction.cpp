#include "direction.hpp"

#include <cmath>
#include <numbers>

namespace feel::detail {
namespace {

constexpr double kRadPerCentideg = std::numbers::pi / 18000.0;

void clear(float factors[kMaxAxes]) noexcept {
    for (int i = 0; i < kMaxAxes; ++i) factors[i] = 0.0f;
}

// The force is opposite to the "from" vector, spread over the effect's axes in order.
void from_vector(const EffectParams& params, const double* from, int n, float factors[kMaxAxes]) noexcept {
    double norm = 0;
    for (int i = 0; i < n; ++i) norm += from[i] * from[i];
    norm = std::sqrt(norm);
    if (!(norm > 0)) return;  // the validator rejects a zero vector; stay silent, never NaN
    for (int i = 0; i < n && i < params.axis_count; ++i) {
        factors[axis_index(params.axes[i])] = static_cast<float>(-from[i] / norm);
    }
}

}  // namespace

void polar_factors(double angle_centideg, float factors[kMaxAxes]) noexcept {
    clear(factors);
    const double a = angle_centideg * kRadPerCentideg;
    factors[axis_index(Axis::x)] = static_cast<float>(-std::sin(a));
    factors[axis_index(Axis::y)] = static_cast<float>(-std::cos(a));
}

void direction_factors(const EffectParams& params, float factors[kMaxAxes]) noexcept {
    clear(factors);
    const Direction& d = params.direction;
    switch (d.kind) {
        case DirectionKind::none:
            factors[axis_index(params.axes[0])] = 1.0f;
            return;
        case DirectionKind::polar:
            polar_factors(d.value[0], factors);
            return;
        case DirectionKind::cartesian:
        case DirectionKind::moments: {
            const double from[3] = {static_cast<double>(d.value[0]), static_cast<double>(d.value[1]),
                                    static_cast<double>(d.value[2])};
            from_vector(params, from, params.axis_count < 3 ? params.axis_count : 3, factors);
            return;
        }
        case DirectionKind::spherical: {
            const double azimuth = d.value[0] * kRadPerCentideg;
            const double elevation = d.value[1] * kRadPerCentideg;
            const double from[3] = {std::sin(elevation) * std::cos(azimuth),
                                    std::sin(elevation) * std::sin(azimuth), std::cos(elevation)};
            // Spherical directions are over x, y, z by definition, whatever the axis order.
            factors[axis_index(Axis::x)] = static_cast<float>(-from[0]);
            factors[axis_index(Axis::y)] = static_cast<float>(-from[1]);
            factors[axis_index(Axis::z)] = static_cast<float>(-from[2]);
            return;
        }
    }
}

}  // namespace feel::detail
