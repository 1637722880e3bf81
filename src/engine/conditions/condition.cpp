// Dispatch from a condition type to the family that renders it.
#include "conditions/condition.hpp"

namespace feel::detail {

void render_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept {
    switch (c.params->type) {
        case EffectType::spring:
        case EffectType::angle_spring: spring_condition(c, force); return;
        case EffectType::damper: damper_condition(c, force); return;
        case EffectType::inertia: inertia_condition(c, force); return;
        case EffectType::friction: friction_condition(c, force); return;
        case EffectType::texture: texture_condition(c, force); return;
        case EffectType::axis_wall:
        case EffectType::angle_wall: wall_condition(c, force); return;
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: barrier_condition(c, force); return;
        default: return;  // not a condition: the engine never routes other classes here
    }
}

}  // namespace feel::detail
