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

template <ConditionLaw kLaw>
void directed(const ConditionContext& c, float force[kMaxAxes]) noexcept {
    directed_condition(c, kLaw, force);
}

void no_condition(const ConditionContext&, float*) noexcept {}

}  // namespace

ConditionLaw condition_renderer(const SlotParams& params) noexcept {
    if (is_directed_condition(params)) {
        switch (params.type) {
            case EffectType::spring: return directed<spring_condition>;
            case EffectType::damper: return directed<damper_condition>;
            case EffectType::inertia: return directed<inertia_condition>;
            default: return directed<friction_condition>;  // is_directed_condition: the four
        }
    }
    switch (params.type) {
        case EffectType::spring:
        case EffectType::angle_spring: return spring_condition;
        case EffectType::damper: return damper_condition;
        case EffectType::inertia: return inertia_condition;
        case EffectType::friction: return friction_condition;
        case EffectType::texture: return texture_condition;
        case EffectType::axis_wall:
        case EffectType::angle_wall: return wall_condition;
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: return barrier_condition;
        default: return no_condition;  // not a condition: the engine never routes other classes here
    }
}

}  // namespace feel::detail
