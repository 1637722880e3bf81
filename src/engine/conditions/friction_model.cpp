// The Dahl bristle and the texture bump; friction_model.hpp has the reasoning. Single
// precision (issue 14).
#include "conditions/friction_model.hpp"

#include <cmath>

namespace feel::detail {

PreslidingRule presliding_rule(const EngineConfig& config, float dt_s) noexcept {
    PreslidingRule rule;
    if (dt_s > 0) rule.passive = 2.0f * config.device_damping / dt_s;
    rule.cap = kMaxForcePerCount / (2.0f * config.sensor_step);
    return rule;
}

float presliding_distance(const EngineConfig& config, float dt_s, float f) noexcept {
    if (!(f > 0)) return 0.0f;
    return f / presliding_stiffness(presliding_rule(config, dt_s), f);
}

float texture_bump(float s, int32_t spacing, float width) noexcept {
    if (!(spacing > 0) || !(width > 0)) return 0.0f;
    const float step = static_cast<float>(spacing);
    return grating_bump(s, step, 1.0f / step, width);
}

}  // namespace feel::detail
