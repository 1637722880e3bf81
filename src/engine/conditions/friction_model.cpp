// The Dahl bristle and the texture bump; friction_model.hpp has the reasoning.
#include "conditions/friction_model.hpp"

#include <cmath>
#include <numbers>

namespace feel::detail {

double presliding_distance(const EngineConfig& config, double dt_s, double f) noexcept {
    if (!(f > 0)) return 0.0;
    double stiffness = f / kMaxPresliding;
    if (dt_s > 0) {
        const double passive = 2.0 * static_cast<double>(config.device_damping) / dt_s;
        if (passive > stiffness) stiffness = passive;
    }
    const double resolution_cap = kMaxForcePerCount / (2.0 * static_cast<double>(config.sensor_step));
    if (stiffness > resolution_cap) stiffness = resolution_cap;
    return f / stiffness;
}

float advance(Bristle& b, double position, double slip, double presliding) noexcept {
    if (!b.primed || !std::isfinite(position)) {
        if (std::isfinite(position)) {
            b.anchor = static_cast<float>(position);
            b.primed = true;
        }
        return b.deflection;
    }
    const double dx = position - static_cast<double>(b.anchor) - slip;
    b.anchor = static_cast<float>(position);
    double z = b.deflection;
    if (!(presliding > 0)) {
        if (dx > 0) z = 1.0;
        if (dx < 0) z = -1.0;
    } else if (dx > 0) {
        z = 1.0 + (z - 1.0) * std::exp(-dx / presliding);
    } else if (dx < 0) {
        z = -1.0 + (z + 1.0) * std::exp(dx / presliding);
    }
    if (!std::isfinite(z)) z = 0.0;  // a non-finite slip: forget rather than output NaN
    b.deflection = static_cast<float>(z);
    return b.deflection;
}

double bristle_damping(const EngineConfig& config, double stiffness, double z, double velocity) noexcept {
    if (!(stiffness > 0) || velocity == 0 || !std::isfinite(velocity)) return 0.0;
    const double rate = velocity * (1.0 - z * (velocity > 0 ? 1.0 : -1.0));
    const double fade_speed = kBristleDampingFade * static_cast<double>(config.velocity_ref);
    const double r = velocity / fade_speed;
    return -stiffness * kBristleDampingTime * rate * std::exp(-r * r);
}

double texture_bump(double s, double spacing, double width) noexcept {
    if (!(spacing > 0) || !(width > 0)) return 0.0;
    const double r = s - spacing * std::round(s / spacing);
    const double half = width / 2.0;
    if (r > half || r < -half) return 0.0;
    return 0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * r / width));
}

}  // namespace feel::detail
