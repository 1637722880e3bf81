// Dispatch from a condition type to the family that renders it.
#include "conditions/condition.hpp"

namespace feel::detail {

ConditionCurve curve_of(const ConditionBlock& b) noexcept {
    constexpr float kPerFullScale = 1.0f / static_cast<float>(kFullScale);
    ConditionCurve curve;
    curve.pos_slope = -static_cast<float>(b.pos_coefficient) * kPerFullScale;
    curve.neg_slope = -static_cast<float>(b.neg_coefficient) * kPerFullScale;
    curve.pos_cap = static_cast<float>(b.pos_saturation);
    curve.neg_cap = static_cast<float>(b.neg_saturation);
    curve.band = static_cast<float>(b.deadband);
    curve.offset = static_cast<float>(b.offset);
    return curve;
}

namespace {

// A family that still renders in double precision, seen as a single-precision one: its
// forces are summed in double and converted once.
template <DoubleConditionLaw kLaw>
void in_double(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    double wide[kMaxAxes] = {};
    kLaw(c, wide);
    for (int a = 0; a < c.axes; ++a) force[a] += static_cast<float>(wide[a]);
}

// The 1-D law of each condition family that can take a direction.
ConditionLaw directed_law(EffectType type) noexcept {
    switch (type) {
        case EffectType::spring: return spring_condition;
        case EffectType::damper: return damper_condition;
        case EffectType::inertia: return inertia_condition;
        default: return in_double<friction_condition>;  // is_directed_condition: the four above
    }
}

}  // namespace

void render_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    if (is_directed_condition(*c.params)) {
        directed_condition(c, directed_law(c.params->type), force);
        return;
    }
    switch (c.params->type) {
        case EffectType::spring:
        case EffectType::angle_spring: spring_condition(c, force); return;
        case EffectType::damper: damper_condition(c, force); return;
        case EffectType::inertia: inertia_condition(c, force); return;
        case EffectType::friction: in_double<friction_condition>(c, force); return;
        case EffectType::texture: in_double<texture_condition>(c, force); return;
        case EffectType::axis_wall:
        case EffectType::angle_wall: in_double<wall_condition>(c, force); return;
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: in_double<barrier_condition>(c, force); return;
        default: return;  // not a condition: the engine never routes other classes here
    }
}

}  // namespace feel::detail
