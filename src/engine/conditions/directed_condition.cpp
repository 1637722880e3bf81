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
// The 1-D law is the family's own code (spring_condition, ...), run on a one-axis view of
// the effect whose axis 0 reads the projections: one law, not a second copy of it. The
// friction bristle of that view is the effect's first (bristle[0]), so the directed
// friction keeps its state across ticks like a one-axis friction. Real-time: a copy of the
// params and a few arrays on the stack, no allocation.
#include "conditions/condition_math.hpp"

namespace feel::detail {

void directed_condition(const ConditionContext& c, void (*law)(const ConditionContext&, double*),
                        double force[kMaxAxes]) noexcept {
    double u[kMaxAxes];
    condition_line(c, u);

    EffectParams line = *c.params;  // axis 0 is the line of the direction
    line.axis_count = 1;
    line.axes[0] = Axis::x;
    line.direction = Direction{};

    const int a0 = axis_index(Axis::x);
    float position[kMaxAxes] = {};
    float velocity[kMaxAxes] = {};
    float acceleration[kMaxAxes] = {};
    float start_position[kMaxAxes] = {};
    position[a0] = static_cast<float>(along(u, c.position));
    velocity[a0] = static_cast<float>(along(u, c.velocity));
    acceleration[a0] = static_cast<float>(along(u, c.acceleration));
    start_position[a0] = static_cast<float>(along(u, c.start_position));

    ConditionContext on_line = c;
    on_line.params = &line;
    on_line.position = position;
    on_line.velocity = velocity;
    on_line.acceleration = acceleration;
    on_line.start_position = start_position;

    double along_line[kMaxAxes] = {};
    law(on_line, along_line);
    for (int a = 0; a < kMaxAxes; ++a) force[a] += along_line[a0] * u[a];
}

}  // namespace feel::detail
