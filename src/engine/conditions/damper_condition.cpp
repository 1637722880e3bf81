// Damper (§3.3): viscosity, a force against the velocity.
//
//   F_a = response(block_i, v_s - offset),   v_s = v_a · 10000 / velocity_ref
//
// v_a is the engine's velocity estimate of device axis a (motion_estimator.hpp): the
// adaptive window keeps it accurate at a fraction of a count per tick, so a slow drag
// meets a steady resistance instead of a force that is zero on most ticks and a spike on
// the others. The offset is a velocity (same scale): the damper pulls the handle toward
// moving at that speed, like a current in the fluid. Deadband and saturations as for the
// spring (condition_math.hpp).
#include "conditions/condition_math.hpp"

namespace feel::detail {

void damper_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    const SlotParams& p = *c.params;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = device_axis(c, i);
        const ConditionCurve& b = c.curves[i];
        force[a] += condition_response(b, c.velocity[a] * c.velocity_scale - b.offset);
    }
}

}  // namespace feel::detail
