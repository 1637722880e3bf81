// Dispatch from a condition type to the family that renders it.
#include "conditions/condition.hpp"

namespace feel::detail {

namespace {

// The 1-D law of each condition family that can take a direction.
using Law = void (*)(const ConditionContext&, double*);
Law directed_law(EffectType type) noexcept {
    switch (type) {
        case EffectType::spring: return spring_condition;
        case EffectType::damper: return damper_condition;
        case EffectType::inertia: return inertia_condition;
        default: return friction_condition;  // is_directed_condition: the four above
    }
}

}  // namespace

void render_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept {
    if (is_directed_condition(*c.params)) {
        directed_condition(c, directed_law(c.params->type), force);
        return;
    }
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
