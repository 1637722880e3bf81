// Conditions with a direction (§3.1): a spring, damper, inertia or friction on 2 or more
// axes given a direction renders one condition block along it.
//
// The primer: "for multi-axis conditions, you can define a direction". DirectInput gives
// the meaning: a multi-axis condition takes either one DICONDITION per axis, or "a single
// structure that defines the condition in the specified direction". feel renders the
// single block as a 1-D condition on the line of the direction:
//
//     u = the unit vector of the direction (where it points FROM, condition_line)
//     s = x·u,  v_s = v·u,  a_s = acc·u,  s_0 = start_position·u      (projections)
//     f = the family's 1-D law of block 0 on (s, v_s, a_s, s_0)
//     F = f·u                                                          (applied along u)
//
// so the force has no component across the line, and along it it is exactly the 1-D
// condition: the handle feels a spring (damper, ...) in that direction only and moves
// freely across it. The positive side of the block is the side u points to: a spring with
// {"polar": 9000} is a spring on x, the same as an angle_spring at 9000.
//
// The 1-D law is the family's own code (spring_condition, ...), run on a view of the
// handle in which the effect's first axis reads the projections and its other axes read 0:
// one law, not a second copy of it. Only the force on the first axis is taken. The other
// blocks are left at their defaults (the validator requires it) and their forces, zero
// anyway, are dropped. The friction bristle of the first block (bristle[0]) keeps the
// state across ticks, like a one-axis friction. Real-time: a few arrays on the stack (no
// copy of the params, which would cost the M4's tick stack 784 bytes), no allocation.
#include "conditions/condition_math.hpp"

namespace feel::detail {

void directed_condition(const ConditionContext& c, ConditionLaw law, float force[kMaxAxes]) noexcept {
    float u[kMaxAxes];
    condition_line(c, u);

    const int line = axis_index(c.params->axes[0]);  // the first axis carries the line
    float position[kMaxAxes] = {};
    float velocity[kMaxAxes] = {};
    float acceleration[kMaxAxes] = {};
    float start_position[kMaxAxes] = {};
    position[line] = along(c, u, c.position);
    velocity[line] = along(c, u, c.velocity);
    acceleration[line] = along(c, u, c.acceleration);
    start_position[line] = along(c, u, c.start_position);
    float applied[kMaxAxes] = {};
    if (c.applied_force != nullptr) applied[line] = along(c, u, c.applied_force);
    float others[kMaxAxes] = {};
    if (c.others_force != nullptr) others[line] = along(c, u, c.others_force);

    ConditionContext on_line = c;
    on_line.position = position;
    on_line.velocity = velocity;
    on_line.acceleration = acceleration;
    on_line.start_position = start_position;
    on_line.applied_force = applied;
    on_line.others_force = c.others_force != nullptr ? others : nullptr;
    on_line.observers = nullptr;  // the line is not a device axis: friction observes it itself

    float per_axis[kMaxAxes] = {};
    law(on_line, per_axis);
    add_force_along(c, u, per_axis[line], force);
}

}  // namespace feel::detail
