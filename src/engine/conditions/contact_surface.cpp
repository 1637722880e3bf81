// Directions and pressure-mode rubbing of walls and barriers; see contact_surface.hpp.
#include "conditions/contact_surface.hpp"

#include <cmath>
#include <cstdint>
#include <utility>

#include "feel/units.hpp"
#include "float_exp.hpp"
#include "float_round.hpp"
#include "turn_trig.hpp"

namespace feel::detail {
namespace {

bool is_angle_element(EffectType type) noexcept {
    return type == EffectType::angle_wall || type == EffectType::angle_barrier;
}

// Sine and cosine of a compass angle in float, from integers. A wall's clipping needs u to
// float's last bit: a handle 7000 units along an oblique wall is reported onto the line to
// 1e-3 units, and float's own turn_trig.hpp (within 2 ulps) put it 1.3e-3 off. Double's
// sin and cos were the M4's only double here (a software routine each); this is 64-bit
// integer multiplication, which both targets do in hardware, with the same bits on both.
//
// Fixed point Q31 (2^31 is 1): the angle's octant is taken exactly in hundredths of a
// degree, so the series below runs on θ ≤ π/4, where sin to θ¹¹ and cos to θ¹² are within
// 1e-11; each product rounds by 2^-32, so each value is within about 2e-9 of the truth
// before it is rounded once to float (from an int32, then an exact scaling). For the
// larger component (0.7 to 1) that is 0.03 of float's ulp: it is the correctly rounded
// float but for a value that close to a tie; the smaller is within half its ulp + 2e-9.
constexpr int kQ = 31;
constexpr int64_t kHalf = int64_t{1} << (kQ - 1);
constexpr int64_t q31(double x) { return static_cast<int64_t>(x * 0x1p31 + (x < 0 ? -0.5 : 0.5)); }
int64_t mul_q31(int64_t a, int64_t b) noexcept { return (a * b + kHalf) >> kQ; }

// θ = m·π/18000 for m hundredths of a degree: the constant in Q52 (m < 2^13, so the
// product stays below 2^53).
constexpr int64_t kRadiansPerHundredthQ52 = static_cast<int64_t>(3.14159265358979323846 / 18000.0 * 0x1p52 + 0.5);
// The series' coefficients, Q31, from the highest power down: sin θ = θ·(1 + θ²·S(θ²)),
// S's −1/3!, 1/5!, ..., −1/11!; cos θ = 1 + θ²·C(θ²), C's −1/2!, 1/4!, ..., 1/12!.
constexpr int64_t kSinSeries[] = {q31(-1.0 / 39916800), q31(1.0 / 362880), q31(-1.0 / 5040), q31(1.0 / 120),
                                  q31(-1.0 / 6)};
constexpr int64_t kCosSeries[] = {q31(1.0 / 479001600), q31(-1.0 / 3628800), q31(1.0 / 40320), q31(-1.0 / 720),
                                  q31(1.0 / 24), q31(-0.5)};

struct SinCos {
    float sin, cos;
};

// sin and cos of m hundredths of a degree, 0 < m <= 4500, as Q31 (both below 1).
void octant_sin_cos(int32_t m, int64_t& sin_q, int64_t& cos_q) noexcept {
    const int64_t theta = (m * kRadiansPerHundredthQ52 + (int64_t{1} << 20)) >> 21;
    const int64_t t2 = mul_q31(theta, theta);
    int64_t s = 0;
    for (const int64_t k : kSinSeries) s = k + mul_q31(t2, s);
    sin_q = theta + mul_q31(theta, mul_q31(t2, s));
    int64_t c = 0;
    for (const int64_t k : kCosSeries) c = k + mul_q31(t2, c);
    cos_q = (int64_t{1} << kQ) + mul_q31(t2, c);
}

// A Q31 value below 1 in magnitude to float: one rounding (int32 to float), then an exact
// scaling by a power of two.
float float_of_q31(int64_t v) noexcept { return static_cast<float>(static_cast<int32_t>(v)) * 0x1p-31f; }

// Exact at the four axis angles (0, 9000, 18000, 27000), so that horizontal and vertical
// angle walls clip and push along one axis only.
SinCos compass_sin_cos(int32_t angle) noexcept {
    angle %= 36000;
    if (angle < 0) angle += 36000;
    const int32_t quadrant = angle / 9000;
    const int32_t within = angle % 9000;
    float s = 0, c = 1;  // of `within`
    if (within != 0) {
        int64_t sin_q = 0, cos_q = 0;
        octant_sin_cos(within <= 4500 ? within : 9000 - within, sin_q, cos_q);
        if (within > 4500) std::swap(sin_q, cos_q);  // sin(90° − x) = cos x
        s = float_of_q31(sin_q);
        c = float_of_q31(cos_q);
    }
    switch (quadrant) {
        case 0: return {s, c};
        case 1: return {c, -s};   // +90°
        case 2: return {-s, -c};  // +180°
        default: return {-c, s};  // +270°
    }
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
    // u to float's last bit (compass_sin_cos), per command.
    const int32_t angle = type == EffectType::angle_wall ? params.wall.angle : params.barrier.angle;
    const SinCos u_angle = compass_sin_cos(angle);
    u[axis_index(Axis::x)] = u_angle.sin;
    u[axis_index(Axis::y)] = u_angle.cos;
}

float element_stiffness(const EngineConfig& config, int32_t hardness) noexcept {
    return static_cast<float>(hardness) * (1.0f / static_cast<float>(kFullScale)) * config.wall_stiffness;
}

namespace {

// surface_bump's body: the rubbing's x86 build takes it inline (below).
[[gnu::always_inline]] inline float surface_bump_inline(float r) noexcept {
    // (The index's zero may have either sign: the ridge's then does too, which d's |·| drops.)
    const float nearest_ridge =
        nearest_multiple_index(r, kSurfaceBumpSpacing, 1.0f / kSurfaceBumpSpacing) * kSurfaceBumpSpacing;
    const float d = std::fabs(r - nearest_ridge);
    // cos(2π·d/w) as a fraction of a turn (turn_trig.hpp: the same bits on every target).
#if defined(__OPTIMIZE_SIZE__)
    if (d >= 0.5f * kSurfaceBumpWidth) return 0.0f;
    return 0.5f * (1.0f + cos_turns(d / kSurfaceBumpWidth));
#else
    // The handle crosses a ridge's edge every tick or two and the cosine's eighth changes as
    // often, so both choices were mispredicted jumps at the end of the division's chain: here
    // the cosine is worked out whatever d and selected (sin_turns_without_jumps(q + ¼) is
    // cos_turns(q), the same float; issue 14, twelfth pass, "The bumps without jumps").
    const float on_ridge = 0.5f * (1.0f + sin_turns_without_jumps(d / kSurfaceBumpWidth + 0.25f));
    return select_if_at_least(d, 0.5f * kSurfaceBumpWidth, 0.0f, on_ridge);
#endif
}

// The rubbing's bump and tanh inline on x86: as calls, each spilled the rubbing's floats
// around it (issue 14, thirteenth pass); the board calls one copy of each (its flash).
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool kInlineRubbing = false;
#else
inline constexpr bool kInlineRubbing = true;
#endif

float rubbing_bump(float r) noexcept {
    if constexpr (kInlineRubbing) {
        return surface_bump_inline(r);
    } else {
        return surface_bump(r);
    }
}

}  // namespace

float surface_bump(float r) noexcept { return surface_bump_inline(r); }

void add_rubbing_force(const ConditionContext& c, float pressure, int32_t friction, int32_t texture,
                       float force[kMaxAxes]) noexcept {
    if (!(pressure > 0) || (friction == 0 && texture == 0)) return;
    const float* u = c.direction;

    // The velocity along the surface: v without its part across it.
    const float across = along(c, u, c.velocity);
    float v_t[kMaxAxes];  // on the device's axes
    for (int a = 0; a < condition_lanes(c); ++a) v_t[a] = c.velocity[a] - across * u[a];
    const float speed = std::sqrt(along(c, v_t, v_t));
    if (!(speed > 0)) return;

    // The largest ridge under the handle, along each tangent direction.
    float bump = 0.0f;
    if (texture != 0) {
        const bool angle = is_angle_element(c.params->type);
        const int axis = axis_index(c.params->axes[0]);
        if (angle) bump = rubbing_bump(u[1] * c.position[0] - u[0] * c.position[1]);  // t = (cos a, −sin a)
        for (int a = angle ? 2 : 0; a < c.axes; ++a) {
            if (a == axis && !angle) continue;
            const float b = rubbing_bump(c.position[a]);
            if (b > bump) bump = b;
        }
    }

    constexpr float kPerFullScale = 1.0f / static_cast<float>(kFullScale);
    const float mu = static_cast<float>(friction) * kPerFullScale;
    const float tau = static_cast<float>(texture) * kPerFullScale;
    const float slip_speed = kSurfaceSlipSpeed * c.config->velocity_ref;
    const float slip = speed / slip_speed;
    const float magnitude = pressure * (mu + tau * bump) * (kInlineRubbing ? float_tanh_inline(slip) : float_tanh(slip));
    const float per_speed = magnitude / speed;
    add_force_along(c, v_t, -per_speed, force);  // (x + (−p)·v is x − p·v, bit for bit)
}

}  // namespace feel::detail
