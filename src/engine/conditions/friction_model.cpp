// The Dahl bristle and the texture bump; friction_model.hpp has the reasoning.
#include "conditions/friction_model.hpp"

#include <cmath>
#include <numbers>

namespace feel::detail {

PreslidingRule presliding_rule(const EngineConfig& config, double dt_s) noexcept {
    PreslidingRule rule;
    if (dt_s > 0) rule.passive = 2.0 * static_cast<double>(config.device_damping) / dt_s;
    rule.cap = kMaxForcePerCount / (2.0 * static_cast<double>(config.sensor_step));
    return rule;
}

double presliding_distance(const EngineConfig& config, double dt_s, double f) noexcept {
    if (!(f > 0)) return 0.0;
    return f / presliding_stiffness(presliding_rule(config, dt_s), f);
}

double bristle_damping(const EngineConfig& config, double stiffness, double z, double velocity) noexcept {
    return bristle_damping(static_cast<float>(stiffness), static_cast<float>(z), static_cast<float>(velocity),
                           1.0f / (static_cast<float>(kBristleDampingFade) * config.velocity_ref));
}

double texture_bump(double s, double spacing, double width) noexcept {
    if (!(spacing > 0) || !(width > 0)) return 0.0;
    const double r = s - spacing * std::round(s / spacing);
    const double half = width / 2.0;
    if (r > half || r < -half) return 0.0;
    return 0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * r / width));
}

}  // namespace feel::detail
