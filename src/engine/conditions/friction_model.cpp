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

float advance(Bristle& b, float position, float slip, float presliding) noexcept {
    if (!b.primed || !std::isfinite(position)) {
        if (std::isfinite(position)) {
            b.anchor = position;
            b.primed = true;
        }
        return b.deflection;
    }
    const float dx = position - b.anchor - slip;
    b.anchor = position;
    float z = b.deflection;
    // Fully slid in the direction of travel: the exact update leaves z at ±1 (the common
    // case while sliding), so skip its exponential.
    if ((z == 1.0f && dx >= 0) || (z == -1.0f && dx <= 0)) return z;
    if (!(presliding > 0)) {
        if (dx > 0) z = 1.0f;
        if (dx < 0) z = -1.0f;
    } else if (dx > 0) {
        z = 1.0f + (z - 1.0f) * std::exp(-dx / presliding);
    } else if (dx < 0) {
        z = -1.0f + (z + 1.0f) * std::exp(dx / presliding);
    }
    if (!std::isfinite(z)) z = 0.0f;  // a non-finite slip: forget rather than output NaN
    b.deflection = z;
    return z;
}

double bristle_damping(const EngineConfig& config, double stiffness, double z, double velocity) noexcept {
    return bristle_damping(static_cast<float>(stiffness), static_cast<float>(z), static_cast<float>(velocity),
                           1.0f / (static_cast<float>(kBristleDampingFade) * config.velocity_ref));
}

float bristle_damping(float stiffness, float z, float velocity, float inverse_fade_speed) noexcept {
    if (!(stiffness > 0) || velocity == 0 || !std::isfinite(velocity)) return 0.0f;
    const float rate = velocity * (1.0f - z * (velocity > 0 ? 1.0f : -1.0f));
    if (rate == 0) return 0.0f;  // fully slid along the motion: no bristle rate to damp
    const float r = velocity * inverse_fade_speed;
    const float r2 = r * r;
    // Beyond 6 fade speeds the fade is below 2.4e-16: nothing a force can show.
    if (r2 > static_cast<float>(kDampingFadeCutoff)) return 0.0f;
    return -stiffness * static_cast<float>(kBristleDampingTime) * rate * std::exp(-r2);
}

double texture_bump(double s, double spacing, double width) noexcept {
    if (!(spacing > 0) || !(width > 0)) return 0.0;
    const double r = s - spacing * std::round(s / spacing);
    const double half = width / 2.0;
    if (r > half || r < -half) return 0.0;
    return 0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * r / width));
}

}  // namespace feel::detail
