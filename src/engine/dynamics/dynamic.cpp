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
            double ball_force[kMaxAxes] = {};
            if (c.params->type == EffectType::dynamic_sling) {
                sling_dynamic(c, ball_force, result);
            } else {
                paddle_dynamic(c, ball_force, result);
            }
            for (int a = 0; a < kMaxAxes; ++a) force[a] += static_cast<float>(ball_force[a]);
            return;
        }
        default: return;  // not a dynamic: the engine never routes other classes here
    }
}

}  // namespace feel::detail
