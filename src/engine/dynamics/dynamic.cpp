// Dispatch from a dynamic type to the model that renders it.
#include "dynamics/dynamic.hpp"

namespace feel::detail {

void render_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept {
    switch (c.params->type) {
        case EffectType::dynamic_recoil:
        case EffectType::dynamic_impact:
        case EffectType::dynamic_liquid:
        case EffectType::dynamic_inertia:
        case EffectType::dynamic_center_drift:
        case EffectType::dynamic_control_law: control_law_dynamic(c, force, result); return;
        case EffectType::dynamic_sling:
        case EffectType::dynamic_paddle: {
            float ball_force[kMaxAxes] = {};
            if (c.params->type == EffectType::dynamic_sling) {
                sling_dynamic(c, ball_force, result);
            } else {
                paddle_dynamic(c, ball_force, result);
            }
            for (int a = 0; a < kMaxAxes; ++a) force[a] += ball_force[a];
            return;
        }
        default: return;  // not a dynamic: the engine never routes other classes here
    }
}

void render_sling_pair(const DynamicContext& a, const DynamicContext& b, float force_a[kMaxAxes],
                       float force_b[kMaxAxes], DynamicResult& result_a, DynamicResult& result_b) noexcept {
    float ball_force_a[kMaxAxes] = {};
    float ball_force_b[kMaxAxes] = {};
    sling_pair_dynamic(a, b, ball_force_a, ball_force_b, result_a, result_b);
    for (int i = 0; i < kMaxAxes; ++i) {
        force_a[i] += ball_force_a[i];
        force_b[i] += ball_force_b[i];
    }
}

}  // namespace feel::detail
