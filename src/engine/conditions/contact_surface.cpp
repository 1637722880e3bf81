// Directions and pressure-mode rubbing of walls and barriers; see contact_surface.hpp.
#include "conditions/contact_surface.hpp"

#include <cmath>
#include <numbers>

#include "feel/units.hpp"
#include "turn_trig.hpp"

namespace feel::detail {
namespace {

bool is_angle_element(EffectType type) noexcept {
    return type == EffectType::angle_wall || type == EffectType::angle_barrier;
}

}  // namespace

void element_direction(const SlotParams& params, float u[kMaxAxes]) noexcept {
    const EffectType type = params.type;
    if (type != EffectType::axis_wall && type != EffectType::axis_barrier && !is_angle_element(type)) return;
    for (int a = 0; a < kMaxAxes; ++a) u[a] = 0.0f;
    if (!is_angle_element(type)) {
        u[axis_index(params.axes[0])] = 1.0f;
        return;
    }
    // sin and cos of the compass angle, rounded once to float (per command, so libm's
    // double sin and cos cost the tick nothing: a handle 7000 units along an oblique wall
    // needs u to float's last bit for its clipped report to sit on the line; float's own
    // turn_trig.hpp, within 2 ulps, put it 1.3e-3 units off, past the clipping test's
    // 1e-3, so this stays double: issue 14, docs/firmware.md), exact at
    // the four axis angles so that horizontal and vertical angle walls clip and push along
    // one axis only.
    const int32_t angle = type == EffectType::angle_wall ? params.wall.angle : params.barrier.angle;
    float sin_a = 0, cos_a = 1;
    switch (angle) {
        case 0: break;
        case 9000: sin_a = 1; cos_a = 0; break;
        case 18000: cos_a = -1; break;
        case 27000: sin_a = -1; cos_a = 0; break;
        default: {
            const double radians = angle * (std::numbers::pi / 18000.0);
            sin_a = static_cast<float>(std::sin(radians));
            cos_a = static_cast<float>(std::cos(radians));
        }
    }
    u[axis_index(Axis::x)] = sin_a;
    u[axis_index(Axis::y)] = cos_a;
}

float element_stiffness(const EngineConfig& config, int32_t hardness) noexcept {
    return static_cast<float>(hardness) * (1.0f / static_cast<float>(kFullScale)) * config.wall_stiffness;
}

float surface_bump(float r) noexcept {
    const float nearest_ridge = std::round(r / kSurfaceBumpSpacing) * kSurfaceBumpSpacing;
    const float d = std::fabs(r - nearest_ridge);
    if (d >= 0.5f * kSurfaceBumpWidth) return 0.0f;
    // cos(2π·d/w) as a fraction of a turn (turn_trig.hpp: the same bits on every target).
    return 0.5f * (1.0f + cos_turns(d / kSurfaceBumpWidth));
}

void add_rubbing_force(const ConditionContext& c, float pressure, int32_t friction, int32_t texture,
                       float force[kMaxAxes]) noexcept {
    if (!(pressure > 0) || (friction == 0 && texture == 0)) return;
    const float* u = c.direction;

    // The velocity along the surface: v without its part across it.
    const float across = dot(c, u, c.velocity);
    float v_t[kMaxAxes] = {};
    float speed_sq = 0;
    for (int a = 0; a < c.axes; ++a) {
        v_t[a] = c.velocity[a] - across * u[a];
        speed_sq += v_t[a] * v_t[a];
    }
    const float speed = std::sqrt(speed_sq);
    if (!(speed > 0)) return;

    // The largest ridge under the handle, along each tangent direction.
    float bump = 0.0f;
    if (texture != 0) {
        const bool angle = is_angle_element(c.params->type);
        const int axis = axis_index(c.params->axes[0]);
        if (angle) bump = surface_bump(u[1] * c.position[0] - u[0] * c.position[1]);  // t = (cos a, −sin a)
        for (int a = angle ? 2 : 0; a < c.axes; ++a) {
            if (a == axis && !angle) continue;
            const float b = surface_bump(c.position[a]);
            if (b > bump) bump = b;
        }
    }

    constexpr float kPerFullScale = 1.0f / static_cast<float>(kFullScale);
    const float mu = static_cast<float>(friction) * kPerFullScale;
    const float tau = static_cast<float>(texture) * kPerFullScale;
    const float slip_speed = kSurfaceSlipSpeed * c.config->velocity_ref;
    const float magnitude = pressure * (mu + tau * bump) * std::tanh(speed / slip_speed);
    const float per_speed = magnitude / speed;
    for (int a = 0; a < c.axes; ++a) force[a] -= per_speed * v_t[a];
}

}  // namespace feel::detail
