// A watched control law (one with play, or k_pos ≠ k_neg) may catch up by taking the state
// its last prediction ended in (control_law_dynamic.cpp): the same advance on the same
// inputs. These tests hold that to the inputs being the same: after a command changes the
// law, or when the tick length changes, the mass must move by the new law over the new
// tick, as an engine given the new law from the start does, or as physics says.
#include <gtest/gtest.h>

#include <initializer_list>

#include "tether_fixture.hpp"

namespace feel::test {
namespace {

// Ticks `engine` at `t_us` with the handle at `x` on the x axis.
TickOutput tick_at(Engine& engine, int64_t t_us, double x) {
    TickInput in;
    in.t_us = t_us;
    in.position[0] = static_cast<float>(x);
    TickOutput out;
    engine.tick(in, out);
    return out;
}

TEST(KeptPrediction, AnInertiaUpdatedMidPlayMovesByItsNewLaw) {
    // Two engines see the same handle, accelerating hard enough for the mass to reach the
    // side of a short play within a tick. One plays a light inertia with a short play and
    // is updated, after the effect's first tick, to a heavy one with a long play; the other
    // plays the heavy one from the start. After the first tick both masses are where the
    // effect starts them (at rest in the middle of the play) and both engines have the same
    // handle history, so from the next tick on the updated one must render exactly what the
    // other does: the tick after the update moves the mass by the new law, not by the
    // prediction the old law made over it.
    const EngineConfig config;
    const int64_t period_us = 1000;
    const double a = 4e6;  // units/s²: 2 units in the first millisecond, past a play of 1
    const auto handle = [&](int n) {
        const double t = n * period_us * 1e-6;
        return -5000 + a * t * t / 2;
    };
    const EffectParams light = inertia_params(2000, 1);
    const EffectParams heavy = inertia_params(9000, 400);
    DynamicRig updated(config, period_us), reference(config, period_us);
    for (int n = 0; n < 8; ++n) {  // the estimator sees the handle accelerate
        updated.tick({handle(n)});
        reference.tick({handle(n)});
    }
    const EffectId id = updated.play(light);
    reference.play(heavy);
    const TickOutput first = updated.tick({handle(8)});
    reference.tick({handle(8)});
    ASSERT_TRUE(first.has_mass);
    ASSERT_NE(first.acceleration[0], 0.0f) << "the mass must be driven in its first tick";
    ASSERT_TRUE(updated.engine().update(id, heavy, effect_field::kTypeSpecific, false).ok());
    for (int n = 9; n < 60; ++n) {
        const TickOutput got = updated.tick({handle(n)});
        const TickOutput want = reference.tick({handle(n)});
        ASSERT_EQ(got.mass_position[0], want.mass_position[0]) << "tick " << n;
        ASSERT_EQ(got.mass_velocity[0], want.mass_velocity[0]) << "tick " << n;
        ASSERT_EQ(got.force[0], want.force[0]) << "tick " << n;
    }
}

TEST(KeptPrediction, AMassCoastingInThePlayCoversALongerTickWhole) {
    // A control law with a wide play on a still handle: the mass, started at v, coasts
    // across the play with no force on it (no gravity, no drag), so it is at v·t, t the
    // time since the effect's first tick, however the ticks are spaced. The ticks go from 1
    // ms to 2 ms and back: each tick's catch-up must cover the tick that was, not the one
    // the last prediction assumed.
    ControlLawBlock block = law_block(5000, 5000, 2000);
    block.k_neg = 3000;
    block.length = 3000;
    block.vel_init = 1000;  // 10000 units/s on the default scale: 3000 units in 0.3 s
    EffectParams p = control_law_params(block);
    Engine engine([] {
        EngineConfig c;
        c.max_effects = 4;
        c.max_samples = 16;
        return c;
    }());
    const double v = per_10000(1000, engine.config().velocity_ref);
    tick_at(engine, 0, 0);
    const CreateResult created = engine.create(p);
    ASSERT_TRUE(created.error.ok());
    ASSERT_TRUE(engine.start(created.id).ok());
    const int64_t start_us = 1000;
    int64_t t_us = start_us;
    tick_at(engine, t_us, 0);
    for (const int64_t period_us : {1000, 1000, 2000, 2000, 2000, 1000, 1000, 3000, 1000}) {
        t_us += period_us;
        const TickOutput out = tick_at(engine, t_us, 0);
        const double t = seconds_between(start_us, t_us);
        ASSERT_EQ(out.force[0], 0.0f) << "t=" << t;
        // float's rounding of a few hundred units; a tick lost or doubled is v·1 ms = 10.
        ASSERT_NEAR(out.mass_position[0], v * t, 1e-3) << "t=" << t;
        ASSERT_NEAR(out.mass_velocity[0], v, 1e-3) << "t=" << t;
    }
}

TEST(KeptPrediction, GravitySetMidPlayPullsTheMassFromTheNextTick) {
    // The same coasting mass; after some ticks a command gives the law a gravity g (the
    // tick it is given on has already predicted without it). From then on the mass falls
    // freely from where it was: s = s_u + v·τ + g·τ²/2, τ the time since the update's
    // tick. Had the tick after the update kept the prediction made without gravity, the
    // mass would lag that by g·T·τ ever after (10⁵ units/s² · 1 ms: 100 units/s).
    ControlLawBlock block = law_block(5000, 5000, 2000);
    block.length = 3000;
    block.vel_init = 1000;
    DynamicRig rig;
    rig.tick({0});
    const EffectId id = rig.play(control_law_params(block));
    const double v = per_10000(1000, rig.config().velocity_ref);
    const double T = rig.period_s();
    const int updated_at = 20;
    for (int n = 0; n <= updated_at; ++n) rig.tick({0});
    const double s_u = v * updated_at * T;
    block.gravity = -500;
    ASSERT_TRUE(rig.engine().update(id, control_law_params(block), effect_field::kTypeSpecific, false).ok());
    const double g = per_10000(-500, rig.config().gravity_ref);
    for (int n = updated_at + 1; n < updated_at + 80; ++n) {
        const TickOutput out = rig.tick({0});
        const double tau = (n - updated_at) * T;
        const double s = s_u + v * tau + g * tau * tau / 2;
        ASSERT_LT(s, 3000.0) << "the mass stays in the play";
        ASSERT_NEAR(out.mass_position[0], s, 1e-3 + 1e-6 * std::fabs(s)) << "tau=" << tau;
        ASSERT_NEAR(out.mass_velocity[0], v + g * tau, 1e-3 + 1e-6 * std::fabs(v)) << "tau=" << tau;
    }
}

}  // namespace
}  // namespace feel::test
