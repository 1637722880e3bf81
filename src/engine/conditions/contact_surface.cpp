// Frames and pressure-mode rubbing of walls and barriers; see contact_surface.hpp.
#include "conditions/contact_surface.hpp"

#include <cmath>
#include <numbers>

#include "feel/units.hpp"

namespace feel::detail {
namespace {

// sin and cos of a compass angle, exact at the four axis angles so that horizontal and
// vertical angle walls clip and push along one axis only.
void compass(int32_t angle, double& sin_a, double& cos_a) noexcept {
    switch (angle) {
        case 0: sin_a = 0; cos_a = 1; return;
        case 9000: sin_a = 1; cos_a = 0; return;
        case 18000: sin_a = 0; cos_a = -1; return;
        case 27000: sin_a = -1; cos_a = 0; return;
        default: {
            const double radians = angle * (std::numbers::pi / 18000.0);
            sin_a = std::sin(radians);
            cos_a = std::cos(radians);
        }
    }
}

}  // namespace

ContactFrame axis_contact_frame(int axis, int device_axes) noexcept {
    ContactFrame f;
    f.u[axis] = 1.0;
    for (int a = 0; a < device_axes && a < kMaxAxes; ++a) {
        if (a == axis) continue;
        f.tangent[f.tangent_count++][a] = 1.0;
    }
    return f;
}

ContactFrame angle_contact_frame(int32_t angle, int device_axes) noexcept {
    ContactFrame f;
    double sin_a = 0, cos_a = 1;
    compass(angle, sin_a, cos_a);
    f.u[0] = sin_a;
    f.u[1] = cos_a;
    f.tangent[0][0] = cos_a;
    f.tangent[0][1] = -sin_a;
    f.tangent_count = 1;
    for (int a = 2; a < device_axes && a < kMaxAxes; ++a) f.tangent[f.tangent_count++][a] = 1.0;
    return f;
}

ContactFrame element_contact_frame(const ConditionContext& c, int32_t angle) noexcept {
    const EffectType type = c.params->type;
    const int device_axes = c.config->axis_count;
    if (type == EffectType::angle_wall || type == EffectType::angle_barrier) {
        return angle_contact_frame(angle, device_axes);
    }
    return axis_contact_frame(axis_index(c.params->axes[0]), device_axes);
}

double element_stiffness(const EngineConfig& config, int32_t hardness) noexcept {
    return hardness / static_cast<double>(kFullScale) * static_cast<double>(config.wall_stiffness);
}

double dot(const double a[kMaxAxes], const float b[kMaxAxes]) noexcept {
    double sum = 0;
    for (int i = 0; i < kMaxAxes; ++i) sum += a[i] * b[i];
    return sum;
}

double surface_bump(double r) noexcept {
    const double nearest_ridge = std::round(r / kSurfaceBumpSpacing) * kSurfaceBumpSpacing;
    const double d = std::fabs(r - nearest_ridge);
    if (d >= 0.5 * kSurfaceBumpWidth) return 0.0;
    return 0.5 * (1.0 + std::cos(2.0 * std::numbers::pi * d / kSurfaceBumpWidth));
}

void add_rubbing_force(const ContactFrame& frame, const ConditionContext& c, double pressure,
                       int32_t friction, int32_t texture, double force[kMaxAxes]) noexcept {
    if (!(pressure > 0) || (friction == 0 && texture == 0) || frame.tangent_count == 0) return;

    // The velocity along the surface and the largest ridge under the handle.
    double v_t[kMaxAxes] = {};
    double bump = 0.0;
    for (int j = 0; j < frame.tangent_count; ++j) {
        const double along = dot(frame.tangent[j], c.velocity);
        for (int a = 0; a < kMaxAxes; ++a) v_t[a] += along * frame.tangent[j][a];
        if (texture != 0) {
            const double b = surface_bump(dot(frame.tangent[j], c.position));
            if (b > bump) bump = b;
        }
    }
    double speed_sq = 0;
    for (double v : v_t) speed_sq += v * v;
    const double speed = std::sqrt(speed_sq);
    if (!(speed > 0)) return;

    const double mu = friction / static_cast<double>(kFullScale);
    const double tau = texture / static_cast<double>(kFullScale);
    const double slip_speed = kSurfaceSlipSpeed * c.config->velocity_ref;
    const double magnitude = pressure * (mu + tau * bump) * std::tanh(speed / slip_speed);
    for (int a = 0; a < kMaxAxes; ++a) force[a] -= magnitude * v_t[a] / speed;
}

}  // namespace feel::detail
