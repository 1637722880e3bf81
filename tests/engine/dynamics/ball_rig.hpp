// A rig for the sling and paddle models (src/engine/dynamics): calls one model directly,
// tick by tick, with a handle the test moves, and keeps the model's state in view.
//
// The physical constants a test compares against come from the same EngineConfig the
// model reads (what 10000 of mass, stiffness, damping, gravity and velocity is), so the
// tests hold whatever scales a device profile chooses.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynamics/dynamic.hpp"
#include "feel/effect.hpp"
#include "feel/engine.hpp"
#include "feel/units.hpp"

namespace feel::test {

inline constexpr double kBallPi = std::numbers::pi;
// The engine's 1 kHz tick, in seconds: the step the ball tests advance by.
inline constexpr double kBallTickS = 1e-3;

// The value of a Dynamic Struct integer whose 10000 means `reference`.
inline double scaled(int32_t value, float reference) { return value / 10000.0 * reference; }

inline EffectParams sling_params(int32_t ball_mass, int32_t string_length, int32_t string_compliance,
                                 int32_t ball_damping, bool interim_reporting = false) {
    EffectParams p;
    p.type = EffectType::dynamic_sling;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.dynamic.ball_mass = ball_mass;
    p.dynamic.string_length = string_length;
    p.dynamic.string_compliance = string_compliance;
    p.dynamic.ball_damping = ball_damping;
    p.dynamic.interim_reporting = interim_reporting;
    return p;
}

inline EffectParams paddle_params(int32_t ball_mass, int32_t initial_velocity, int32_t direction,
                                  int32_t paddle_compliance, int32_t paddle_damping, int32_t gravity,
                                  bool interim_reporting = false) {
    EffectParams p;
    p.type = EffectType::dynamic_paddle;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.dynamic.ball_mass = ball_mass;
    p.dynamic.initial_velocity = initial_velocity;
    p.dynamic.initial_velocity_direction = direction;
    p.dynamic.paddle_compliance = paddle_compliance;
    p.dynamic.paddle_damping = paddle_damping;
    p.dynamic.gravity = gravity;
    p.dynamic.interim_reporting = interim_reporting;
    return p;
}

// Restitution and contact time of a ball bouncing off a still paddle with damping ratio
// ζ, derived independently of the model (see paddle_contact.hpp): the ball leaves when the
// spring-damper force falls to zero (the paddle pushes, never pulls).
//   ζ < 1:  x(t) = −(V/ω_d)·e^{−ζωt}·sin ω_d t; the force −k·x − b·ẋ vanishes where
//           tan ω_d t = −2ζ√(1−ζ²)/(1−2ζ²), i.e. ω_d·t_c = π − 2·asin ζ, and there
//           ẋ = V·e^{−ζω t_c}.
//   ζ > 1:  with decay rates λ1 < λ2 (λ1·λ2 = ω², λ1 + λ2 = 2ζω), the force vanishes where
//           λ2²·e^{−λ2 t} = λ1²·e^{−λ1 t}, and e = (λ1/λ2)^((λ1+λ2)/(λ2−λ1)).
struct Bounce {
    double restitution = 0;
    double contact_s = 0;
};

inline Bounce pushes_only_bounce(double zeta, double omega) {
    if (zeta < 1) {
        const double wd = omega * std::sqrt(1 - zeta * zeta);
        const double tc = (kBallPi - 2 * std::asin(zeta)) / wd;
        return {std::exp(-zeta * omega * tc), tc};
    }
    if (zeta == 1) return {std::exp(-2.0), 2.0 / omega};  // the limit of both sides: ω·t_c → 2
    const double root = std::sqrt(zeta * zeta - 1);
    const double l1 = omega * (zeta - root);
    const double l2 = omega * (zeta + root);
    const double tc = 2 * std::log(l2 / l1) / (l2 - l1);
    return {std::pow(l1 / l2, (l1 + l2) / (l2 - l1)), tc};
}

// Calls a model directly. The handle is wherever the test puts it.
class BallRig {
public:
    using Model = void (*)(const detail::DynamicContext&, float*, detail::DynamicResult&) noexcept;

    BallRig(Model model, const EffectParams& params, const EngineConfig& config = EngineConfig{})
        : model_(model), params_(params), config_(config) {}

    struct Tick {
        double force[kMaxAxes] = {};  // the model's float force, widened for the tests' arithmetic
        detail::DynamicResult result{};
    };

    // One tick dt_s after the previous one (the first tick of the effect: any dt_s; the
    // engine passes 0 on its own first tick).
    Tick tick(double dt_s) {
        Tick t;
        if (!started_) {
            for (int a = 0; a < kMaxAxes; ++a) start_[a] = position[a];
            started_ = true;
        }
        const float acceleration[kMaxAxes] = {};
        const detail::SlotDynamicBlock block = detail::slot_dynamic_block(params_);
        const detail::SlotParams stored = detail::slot_params(params_, &block);
        // The engine's tick length is float; the rig's double rounds as the models once did.
        const detail::DynamicContext c{&stored, &config_, position, velocity, acceleration, start_, static_cast<float>(dt_s), tau_us_, &state};
        float force[kMaxAxes] = {};
        model_(c, force, t.result);
        for (int a = 0; a < kMaxAxes; ++a) t.force[a] = force[a];
        tau_us_ += static_cast<int64_t>(std::llround(dt_s * 1e6));
        return t;
    }

    const EffectParams& params() const { return params_; }
    const EngineConfig& config() const { return config_; }

    float position[kMaxAxes] = {};  // the handle, sensed, position units
    float velocity[kMaxAxes] = {};  // the handle's estimated velocity, position units/s
    detail::DynamicState state{};

private:
    Model model_;
    EffectParams params_;
    EngineConfig config_;
    float start_[kMaxAxes] = {};
    bool started_ = false;
    int64_t tau_us_ = 0;
};

inline double norm2(double x, double y) { return std::sqrt(x * x + y * y); }

// The ball's position in the fixed frame on device axis a: the models keep it relative to
// the handle sensed at the last tick (ball_state.hpp).
inline double ball_position(const BallRig& rig, int a) {
    return static_cast<double>(rig.state.ball.now.offset[a]) + rig.state.ball.handle[a];
}

}  // namespace feel::test
