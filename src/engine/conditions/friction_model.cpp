// The Dahl bristle and the texture bump; friction_model.hpp has the reasoning. Single
// precision (issue 14).
#include "conditions/friction_model.hpp"

#include <cmath>
#include <numbers>

#include "float_round.hpp"

namespace feel::detail {

namespace {

// cos θ for |θ| <= π/2 by its Taylor polynomial to θ¹² (the next term is below
// (π/2)¹⁴/14! = 6.4e-9, a tenth of a float ulp of 1/2), in θ² by Horner's rule.
float cos_within_half_pi(float theta) noexcept {
    const float t = theta * theta;
    constexpr float c2 = -1.0f / 2, c4 = 1.0f / 24, c6 = -1.0f / 720, c8 = 1.0f / 40320;
    constexpr float c10 = -1.0f / 3628800, c12 = 1.0f / 479001600;
    return 1.0f + t * (c2 + t * (c4 + t * (c6 + t * (c8 + t * (c10 + t * c12)))));
}

}  // namespace

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
    return grating_bump(s, static_cast<float>(spacing), width);
}

float grating_bump(float s, float step, float width) noexcept {
    // (Exact: step·round(s/step) is an integer below 2^24 and s a multiple of its ulp there.)
    const float r = s - step * round_half_away(s / step);
    const float half = width / 2.0f;
    if (r > half || r < -half) return 0.0f;
    const float c = cos_within_half_pi(std::numbers::pi_v<float> * r / width);
    return c * c;  // (1 + cos 2θ)/2
}

}  // namespace feel::detail
