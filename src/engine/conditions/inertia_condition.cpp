// Inertia (§3.4): F = -m·a, the feel of moving a heavier handle.
//
//   F_a = response(block_i, a_s - offset),   a_s = acc_a · 10000 / acceleration_ref
//
// acc_a is the engine's acceleration estimate of device axis a (a parabola fitted over an
// adaptive window, motion_estimator.hpp). The coefficient is the added mass: 10000 adds
// the mass that full force accelerates at acceleration_ref (on the joystick profile,
// 4.45 N at 10 m/s², 0.45 kg, three times the bare stick). Most hardware allows only
// positive masses (§6.6.a); a negative one makes the handle feel lighter, and is kept
// here because the primer's range allows it. The offset (an acceleration), deadband and
// saturations follow the Condition Struct (condition_math.hpp); §8.2's Inertia(Mass,
// Saturation) is the block with both coefficients = Mass and both saturations =
// Saturation.
#include "conditions/condition_math.hpp"

namespace feel::detail {

void inertia_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = device_axis(c, i);
        const ConditionCurve& b = c.curves[i];
        force[a] += condition_response(b, c.acceleration[a] * c.acceleration_scale - b.offset);
    }
}

}  // namespace feel::detail
