// Shared pieces of the control-law dynamics tests: effect builders, a rig that plays one
// effect on an Engine against a handle the test moves (kinematically), and the textbook
// solutions the tests compare against.
//
// The analytic solutions here are written independently of src/engine/dynamics: the
// standard forms of the damped oscillator (under-, critically and over-damped), and plain
// numerical quadrature for the mean force over a tick. The physical constants come from
// the EngineConfig the engine reads (what 10000 of mass, stiffness, damping, gravity and
// velocity means), so the tests hold whatever scales a profile chooses.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <vector>

#include "feel/effect.hpp"
#include "feel/engine.hpp"
#include "feel/units.hpp"

namespace feel::test {

inline constexpr double kPiD = std::numbers::pi;

// The value of a Dynamic Struct integer whose 10000 means `reference`.
inline double per_10000(int32_t value, double reference) { return value / 10000.0 * reference; }

// A dynamic_control_law effect on the given axes, every axis with the same block.
inline EffectParams control_law_params(const ControlLawBlock& block, std::initializer_list<Axis> axes = {Axis::x}) {
    EffectParams p;
    p.type = EffectType::dynamic_control_law;
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) {
        p.axes[i] = a;
        p.dynamic.control_law[i] = block;
        ++i;
    }
    return p;
}

inline ControlLawBlock law_block(int32_t mass, int32_t k, int32_t b = 0) {
    ControlLawBlock c;
    c.mass = mass;
    c.k_pos = k;
    c.k_neg = k;
    c.b = b;
    return c;
}

inline EffectParams planar_dynamic(EffectType type) {
    EffectParams p;
    p.type = type;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    return p;
}

inline EffectParams recoil_params(int32_t direction, int32_t intensity, int32_t mass, int32_t resonance,
                                  int32_t decay) {
    EffectParams p = planar_dynamic(EffectType::dynamic_recoil);
    p.dynamic.blast_direction = direction;
    p.dynamic.blast_intensity = intensity;
    p.dynamic.dynamic_mass = mass;
    p.dynamic.blast_resonance = resonance;
    p.dynamic.blast_decay = decay;
    return p;
}

inline EffectParams impact_params(int32_t direction, int32_t intensity, int32_t mass, int32_t elasticity,
                                  int32_t absorption) {
    EffectParams p = planar_dynamic(EffectType::dynamic_impact);
    p.dynamic.impact_direction = direction;
    p.dynamic.impact_intensity = intensity;
    p.dynamic.dynamic_mass = mass;
    p.dynamic.elasticity = elasticity;
    p.dynamic.collision_absorption = absorption;
    return p;
}

inline EffectParams liquid_params(int32_t density, int32_t settle, int32_t viscosity,
                                  std::initializer_list<Axis> axes = {Axis::x}) {
    EffectParams p;
    p.type = EffectType::dynamic_liquid;
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) p.axes[i++] = a;
    p.dynamic.density = density;
    p.dynamic.settle = settle;
    p.dynamic.viscosity = viscosity;
    return p;
}

inline EffectParams inertia_params(int32_t inertia, int32_t play) {
    EffectParams p;
    p.type = EffectType::dynamic_inertia;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.dynamic.inertia = inertia;
    p.dynamic.play = play;
    return p;
}

inline EffectParams center_drift_params(int32_t stiffness, int32_t drift_resistance) {
    EffectParams p;
    p.type = EffectType::dynamic_center_drift;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.dynamic.stiffness = stiffness;
    p.dynamic.drift_resistance = drift_resistance;
    return p;
}

// The textbook damped oscillator m·ÿ + c·ẏ + k·y = 0 from (y0, v0): position and velocity.
struct Oscillator {
    double m, c, k;
    double y0, v0;

    [[nodiscard]] double gamma() const { return c / (2 * m); }
    [[nodiscard]] double omega0() const { return std::sqrt(k / m); }

    void at(double t, double& y, double& v) const {
        const double g = gamma();
        const double w0 = omega0();
        if (g < w0 * (1 - 1e-9)) {  // underdamped
            const double wd = std::sqrt(w0 * w0 - g * g);
            const double a = y0;
            const double b = (v0 + g * y0) / wd;
            const double e = std::exp(-g * t);
            y = e * (a * std::cos(wd * t) + b * std::sin(wd * t));
            v = e * (-g * (a * std::cos(wd * t) + b * std::sin(wd * t)) + wd * (-a * std::sin(wd * t) + b * std::cos(wd * t)));
        } else if (g > w0 * (1 + 1e-9)) {  // overdamped: two real roots
            const double root = std::sqrt(g * g - w0 * w0);
            const double r1 = -g + root;
            const double r2 = -g - root;
            const double c2 = (v0 - r1 * y0) / (r2 - r1);
            const double c1 = y0 - c2;
            y = c1 * std::exp(r1 * t) + c2 * std::exp(r2 * t);
            v = c1 * r1 * std::exp(r1 * t) + c2 * r2 * std::exp(r2 * t);
        } else {  // critical
            const double b = v0 + g * y0;
            const double e = std::exp(-g * t);
            y = (y0 + b * t) * e;
            v = (b - g * (y0 + b * t)) * e;
        }
    }
    [[nodiscard]] double position(double t) const {
        double y, v;
        at(t, y, v);
        return y;
    }
    [[nodiscard]] double velocity(double t) const {
        double y, v;
        at(t, y, v);
        return v;
    }
};

// The mean of f over [a, b] by composite Simpson with n (even) intervals.
inline double mean_over(const std::function<double(double)>& f, double a, double b, int n = 200) {
    const double h = (b - a) / n;
    double s = f(a) + f(b);
    for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4 : 2);
    return s * h / 3 / (b - a);
}

// Seconds from `from_us` to `to_us`.
inline double seconds_between(int64_t from_us, int64_t to_us) { return static_cast<double>(to_us - from_us) * 1e-6; }

// One effect on an Engine, ticked at a fixed period against a handle the test places.
class DynamicRig {
public:
    explicit DynamicRig(EngineConfig config = {}, int64_t period_us = 1000) : period_us_(period_us) {
        config.max_effects = 4;
        config.max_samples = 16;
        engine_ = std::make_unique<Engine>(config);
    }

    EffectId play(const EffectParams& p) {
        const CreateResult r = engine_->create(p);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        EXPECT_TRUE(engine_->start(r.id).ok());
        id_ = r.id;
        return r.id;
    }

    // Ticks once with the handle at `position` (per device axis), then advances the clock.
    TickOutput tick(std::initializer_list<double> position = {}) {
        TickInput in;
        in.t_us = t_us_;
        int a = 0;
        for (double x : position) in.position[a++] = static_cast<float>(x);
        TickOutput out;
        engine_->tick(in, out);
        t_us_ += period_us_;
        return out;
    }

    [[nodiscard]] double period_s() const { return static_cast<double>(period_us_) * 1e-6; }
    [[nodiscard]] int64_t t_us() const { return t_us_; }
    [[nodiscard]] Engine& engine() { return *engine_; }
    [[nodiscard]] EffectId id() const { return id_; }
    [[nodiscard]] const EngineConfig& config() const { return engine_->config(); }

private:
    std::unique_ptr<Engine> engine_;
    int64_t period_us_;
    int64_t t_us_ = 0;
    EffectId id_{};
};

}  // namespace feel::test
