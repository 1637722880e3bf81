// Properties of the control-law dynamics over random parameters, devices, tick rates and
// hand motions (issue 4, section 4): nothing is ever NaN or infinite, the engine's output
// obeys the motor limit, the model's own output is finite before the engine's clamp, and a
// tether that nothing drives never gains energy.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/dynamic.hpp"
#include "feel/effect_validation.hpp"
#include "feel/sim/device_profile.hpp"
#include "tether_fixture.hpp"

namespace feel::test {
namespace {

// An integer in [lo, hi], at an end of the range a third of the time.
rc::Gen<int32_t> param(int32_t lo, int32_t hi) {
    return rc::gen::weightedOneOf<int32_t>({{1, rc::gen::just(lo)}, {1, rc::gen::just(hi)}, {4, rc::gen::inRange(lo, hi + 1)}});
}

ControlLawBlock random_block() {
    ControlLawBlock b;
    b.mass = *param(1, 10000);
    b.k_pos = *param(1, 10000);
    b.k_neg = *param(1, 10000);
    b.b = *param(0, 10000);
    b.vel_init = *param(-10000, 10000);
    b.pos_init = *param(-10000, 10000);
    b.half_cycles = *rc::gen::weightedOneOf<int32_t>({{3, rc::gen::just(0)}, {1, param(1, 10000)}});
    b.length = *param(0, 10000);
    b.drag = *param(0, 10000);
    b.gravity = *param(-10000, 10000);
    return b;
}

EngineConfig random_config() {
    const int which = *rc::gen::inRange(0, 4);
    if (which == 3) return EngineConfig{};  // the defaults, no profile
    return sim::engine_config_for(sim::device_profiles()[static_cast<size_t>(which)]);
}

EffectParams random_dynamic(const EngineConfig& c) {
    EffectType type = *rc::gen::element(EffectType::dynamic_recoil, EffectType::dynamic_impact,
                                        EffectType::dynamic_liquid, EffectType::dynamic_inertia,
                                        EffectType::dynamic_center_drift, EffectType::dynamic_control_law);
    if (c.axis_count < 2 && (type == EffectType::dynamic_recoil || type == EffectType::dynamic_impact)) {
        type = EffectType::dynamic_control_law;
    }
    EffectParams p;
    p.type = type;
    p.duration_us = kInfiniteUs;
    DynamicBlock& d = p.dynamic;
    if (type == EffectType::dynamic_recoil || type == EffectType::dynamic_impact) {
        p.axis_count = 2;
        const bool swapped = *rc::gen::arbitrary<bool>();
        p.axes[0] = swapped ? Axis::y : Axis::x;
        p.axes[1] = swapped ? Axis::x : Axis::y;
    } else {
        p.axis_count = *rc::gen::inRange(1, c.axis_count + 1);
        for (int i = 0; i < p.axis_count; ++i) p.axes[i] = static_cast<Axis>(i);
    }
    d.blast_direction = d.impact_direction = *param(0, 35999);
    d.blast_intensity = d.impact_intensity = *param(-10000, 10000);
    d.dynamic_mass = *param(1, 10000);
    d.blast_resonance = d.elasticity = *param(1, 10000);
    d.blast_decay = d.collision_absorption = *param(0, 10000);
    d.density = *param(1, 10000);
    d.settle = *param(1, 10000);
    d.viscosity = *param(0, 10000);
    d.inertia = *param(1, 10000);
    d.play = *param(0, 10000);
    d.stiffness = *param(1, 10000);
    d.drift_resistance = *param(0, 10000);
    for (int i = 0; i < p.axis_count; ++i) d.control_law[i] = random_block();
    d.interim_reporting = *rc::gen::arbitrary<bool>();
    return p;
}

// A hand motion, one position per tick per axis, within the travel.
std::vector<std::vector<double>> random_hand(int ticks, int axes, double period_s) {
    const int kind = *rc::gen::inRange(0, 4);
    std::vector<std::vector<double>> path(static_cast<size_t>(ticks), std::vector<double>(static_cast<size_t>(axes), 0.0));
    for (int a = 0; a < axes; ++a) {
        double x = *rc::gen::inRange(-10000, 10001);
        const double amplitude = *rc::gen::inRange(0, 10001);
        const double hz = *rc::gen::inRange(1, 50);
        for (int n = 0; n < ticks; ++n) {
            switch (kind) {
                case 0: break;  // held still
                case 1: x += *rc::gen::inRange(-300, 301); break;                            // jittery walk
                case 2: x = amplitude * std::sin(2 * kPiD * hz * n * period_s); break;       // shaking
                default: if (*rc::gen::inRange(0, 20) == 0) x = *rc::gen::inRange(-10000, 10001); break;  // jumps
            }
            x = std::clamp(x, -10000.0, 10000.0);
            path[static_cast<size_t>(n)][static_cast<size_t>(a)] = x;
        }
    }
    return path;
}

RC_GTEST_PROP(ControlLawProperty, FiniteAndWithinTheMotorLimitForAnyParametersRateAndHand, ()) {
    EngineConfig config = random_config();
    config.max_effects = 2;
    config.max_samples = 16;
    const EffectParams p = random_dynamic(config);
    RC_PRE(validate_effect(p).ok());
    const int64_t period_us = *rc::gen::element<int64_t>(100, 250, 1000, 4000, 10000);
    const bool jitter = *rc::gen::arbitrary<bool>();
    const int ticks = 250;
    const auto hand = random_hand(ticks, config.axis_count, static_cast<double>(period_us) * 1e-6);

    Engine engine(config);
    const CreateResult created = engine.create(p);
    RC_ASSERT(created.error.ok());
    RC_ASSERT(engine.start(created.id).ok());
    // The model alone, fed the same hand, to see its force before the engine's clamp.
    detail::DynamicState state;
    float previous[kMaxAxes] = {};
    int64_t t_us = 0, previous_t_us = 0;
    for (int n = 0; n < ticks; ++n) {
        TickInput in;
        in.t_us = t_us;
        for (int a = 0; a < config.axis_count; ++a) in.position[a] = static_cast<float>(hand[static_cast<size_t>(n)][static_cast<size_t>(a)]);
        TickOutput out;
        engine.tick(in, out);
        for (int a = 0; a < kMaxAxes; ++a) {
            RC_ASSERT(std::isfinite(out.force[a]));
            RC_ASSERT(std::fabs(out.force[a]) <= 10000.0f);
            RC_ASSERT(std::isfinite(out.mass_position[a]));
            RC_ASSERT(std::isfinite(out.mass_velocity[a]));
        }
        DynamicReport report;
        while (engine.pop_report(report)) {
            for (int i = 0; i < report.axis_count; ++i) {
                RC_ASSERT(std::isfinite(report.position[i]));
                RC_ASSERT(std::isfinite(report.velocity[i]));
            }
        }

        const int64_t dt_us = t_us - previous_t_us;
        float velocity[kMaxAxes] = {};
        for (int a = 0; a < config.axis_count; ++a) {
            velocity[a] = n == 0 ? 0.0f : static_cast<float>((in.position[a] - previous[a]) / (static_cast<double>(dt_us) * 1e-6));
        }
        const float acceleration[kMaxAxes] = {};
        const detail::SlotDynamicBlock block = detail::slot_dynamic_block(p);
        const detail::SlotParams stored = detail::slot_params(p, &block);
        const detail::DynamicContext context{&stored, &config, in.position, velocity, acceleration, in.position, n == 0 ? 0.0f : static_cast<float>(static_cast<double>(dt_us) * 1e-6), t_us, &state};
        float raw[kMaxAxes] = {};
        detail::DynamicResult result;
        detail::render_dynamic(context, raw, result);
        for (int a = 0; a < kMaxAxes; ++a) {
            RC_ASSERT(std::isfinite(raw[a]));
            RC_ASSERT(std::isfinite(result.mass_position[a]));
            RC_ASSERT(std::isfinite(result.mass_velocity[a]));
        }
        for (int a = 0; a < kMaxAxes; ++a) previous[a] = in.position[a];
        previous_t_us = t_us;
        const int64_t step = jitter ? period_us / 2 + *rc::gen::inRange<int64_t>(0, period_us + 1) : period_us;
        t_us += std::max<int64_t>(step, 1);
    }
}

RC_GTEST_PROP(ControlLawProperty, AnUndrivenTetherNeverGainsEnergy, ()) {
    // Handle held still, no gravity: whatever the mass, stiffnesses, play, damping and drag,
    // and whatever it starts with, the energy ½·m·ṡ² + U(s) never grows.
    const EngineConfig config = random_config();
    ControlLawBlock b = random_block();
    b.gravity = 0;
    b.half_cycles = 0;
    DynamicRig rig(config, *rc::gen::element<int64_t>(250, 1000, 4000));
    rig.tick({0, 0, 0});
    rig.play(control_law_params(b));
    const double m = per_10000(b.mass, config.dynamic_mass_ref);
    const double kp = per_10000(b.k_pos, config.dynamic_stiffness_ref), kn = per_10000(b.k_neg, config.dynamic_stiffness_ref);
    auto energy = [&](double s, double v) {
        double u = 0;
        if (s > b.length) u = 0.5 * kp * (s - b.length) * (s - b.length);
        if (s < -b.length) u = 0.5 * kn * (s + b.length) * (s + b.length);
        return 0.5 * m * v * v + u;
    };
    // What the float outputs' rounding can do to the energy computed from them: half an
    // ulp of the stretch times the spring force, half an ulp of the velocity times the
    // momentum.
    auto rounding = [&](float s, float v) {
        const double us = std::nextafter(std::fabs(s), INFINITY) - std::fabs(s);
        const double uv = std::nextafter(std::fabs(v), INFINITY) - std::fabs(v);
        const double stretch = std::max(std::fabs(s) - static_cast<double>(b.length), 0.0);
        return std::max(kp, kn) * stretch * us + m * std::fabs(v) * uv;
    };
    // The outputs are the simulated state itself, which is float (docs/dynamics.md,
    // "Precision"): every piece of a tick rounds it (a tick is cut into pieces of at most
    // a radian of the stiffer side's ω), so its energy takes a random walk of steps of
    // about one rounding around the true, never-growing energy. A rounding is worth most
    // deep in a stiff side beyond a wide play (k·depth·ulp(stretch): the stretch is
    // relative to the handle, so its resolution is that of the play's width), and the
    // energy it moves is carried on as speed once the mass is back in the play: the walk
    // is counted in the largest rounding the energy allows between ticks. From there, n
    // pieces later it may stand some sqrt(n) such roundings higher; a creep (a systematic
    // gain) grows as n and is still caught.
    const TickOutput first = rig.tick({0, 0, 0});
    double e = energy(first.mass_position[0], first.mass_velocity[0]);
    double slack = rounding(first.mass_position[0], first.mass_velocity[0]);
    const double floor = 1e-12 * e;  // once it has all but stopped, rounding of the rest
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::sqrt(std::max(kp, kn) / m) * rig.period_s())));
    // The largest rounding a state of energy E can meet between two ticks: deepest in a
    // side, sqrt(2E/k) beyond the play, or fastest, sqrt(2E/m) (an ulp is at most 2^-23
    // of the value).
    auto deepest_rounding = [&](double held) {
        double worst = 0;
        for (const double k : {kp, kn}) {
            const double depth = std::sqrt(2 * held / k);
            worst = std::max(worst, k * depth * std::ldexp(b.length + depth, -23));
        }
        const double speed = std::sqrt(2 * held / m);
        return std::max(worst, m * speed * std::ldexp(speed, -23));
    };
    int since_lowest = 0;
    double largest_rounding = slack;
    for (int n = 0; n < 400; ++n) {
        const TickOutput out = rig.tick({0, 0, 0});
        const double e1 = energy(out.mass_position[0], out.mass_velocity[0]);
        const double r = rounding(out.mass_position[0], out.mass_velocity[0]);
        since_lowest += pieces;
        largest_rounding = std::max({largest_rounding, slack, r, deepest_rounding(e)});
        const double walk = 4 * std::sqrt(static_cast<double>(since_lowest)) * largest_rounding;
        RC_ASSERT(e1 <= e * (1 + 1e-9) + slack + r + walk + floor);
        if (e1 < e) {  // compare against the lowest seen, so a slow creep is caught too
            e = e1;
            slack = r;
            since_lowest = 0;
            largest_rounding = r;
        }
    }
}

}  // namespace
}  // namespace feel::test
