// Spring (§3.2) and Angle Spring: Hooke's law with the Condition Struct's response curve.
//
//   spring, one block per axis i of the effect, on device axis a:
//       F_a = response(block_i, x_a - center_i)
//   angle_spring, one block along the unit vector u of its polar angle (u = (sin a, cos a)):
//       s = x·u,  F = response(block, s - center)·u
//
// center = offset (absolute), or offset measured from where the handle was when the
// effect began playing (relative). Relative is the primer's SpringAtCurrentLocation
// (§8.2): a spring that holds the handle where it is. CenterSpring is an absolute spring on
// x and y with offset 0. The positive side of an angle spring is the side its compass
// angle points to: at 9000 the + side is +x.
#include "conditions/condition_math.hpp"

namespace feel::detail {

namespace {

float spring_center(OffsetMode mode, const ConditionCurve& b, float start) noexcept {
    return mode == OffsetMode::relative ? start + b.offset : b.offset;
}

}  // namespace

void spring_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    if (p.type == EffectType::angle_spring) {
        float u[kMaxAxes];
        condition_line(c, u);
        const ConditionCurve& b = c.curves[0];
        const float s = along(c, u, c.position);
        const float center = spring_center(p.curved.offset_modes[0], b, along(c, u, c.start_position));
        const float f = condition_response(b, s - center);
        add_force_along(c, u, f, force);
        return;
    }
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = device_axis(c, i);
        const ConditionCurve& b = c.curves[i];
        const float center = spring_center(p.curved.offset_modes[i], b, c.start_position[a]);
        force[a] += condition_response(b, c.position[a] - center);
    }
}

}  // namespace feel::detail
