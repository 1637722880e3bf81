// The tick never allocates: a hooked global allocator counts every allocation made while
// a busy mix of waves plays for many ticks.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "feel/engine.hpp"
#include "support/counting_allocator.hpp"

namespace feel {
namespace {

TEST(TickAllocation, TheCounterSeesAllocations) {
    counting = true;
    auto* probe = new int(7);
    counting = false;
    EXPECT_GT(allocations.exchange(0), 0);
    delete probe;
}

TEST(TickAllocation, ABusyWaveMixTicksWithoutAllocating) {
    Engine engine(EngineConfig{});
    const std::array<int16_t, 8> samples = {100, 200, 300, 400, -100, -200, -300, -400};
    for (int i = 0; i < 64; ++i) {
        EffectParams p;
        p.type = static_cast<EffectType>(static_cast<int>(EffectType::vector_force) + i % 15);
        p.duration_us = 500'000;
        p.axis_count = 2;
        p.axes[0] = Axis::x;
        p.axes[1] = Axis::y;
        p.direction.kind = is_sweep(p.type) ? DirectionKind::none : DirectionKind::polar;
        p.direction.value[0] = (1000 * i) % 36000;
        p.constant.magnitude = 100;
        p.periodic = {100, 0, 10'000, 0, 0, 9000, SweepSense::clockwise};
        p.ramp = {0, 100};
        p.custom = {2, 1000, 8};
        p.iterations = kInfiniteIterations;
        if (p.type == EffectType::force_profile) p.direction.kind = DirectionKind::none;
        const CreateResult r = engine.create(p, p.type == EffectType::force_profile ? std::span<const int16_t>(samples)
                                                                                    : std::span<const int16_t>());
        ASSERT_TRUE(r.error.ok()) << effect_type_name(p.type) << ": " << r.error.message();
        ASSERT_TRUE(engine.start(r.id).ok());
    }
    TickOutput out;
    counting = true;
    for (int n = 0; n < 20'000; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        engine.tick(in, out);
    }
    counting = false;
    EXPECT_EQ(allocations.load(), 0);
    EXPECT_EQ(out.playing_effects, 64);
}

// Every Spatial Condition, with the handle moving through walls, barriers, textures and
// friction so that every branch of their state machines runs.
TEST(TickAllocation, EveryConditionTicksWithoutAllocating) {
    Engine engine(EngineConfig{});
    const EffectType types[] = {EffectType::spring,    EffectType::damper,       EffectType::inertia,
                                EffectType::friction,  EffectType::angle_spring, EffectType::axis_barrier,
                                EffectType::angle_barrier, EffectType::axis_wall, EffectType::angle_wall,
                                EffectType::texture};
    for (int copy = 0; copy < 6; ++copy) {
        for (EffectType t : types) {
            EffectParams p;
            p.type = t;
            p.duration_us = kInfiniteUs;
            const bool one_axis = t == EffectType::axis_wall || t == EffectType::axis_barrier;
            const bool polar = t == EffectType::angle_spring || t == EffectType::texture;
            p.axis_count = one_axis ? 1 : 2;
            p.axes[0] = Axis::x;
            p.axes[1] = Axis::y;
            if (polar) {
                p.direction.kind = DirectionKind::polar;
                p.direction.value[0] = 1500 * copy;
            }
            for (ConditionBlock& c : p.conditions) c = {3000, 2000, 100, 9000, 8000, 50, OffsetMode::absolute};
            p.texture = {4000, 3000, 500, 5000};
            p.wall = {8000, copy % 2 ? WallSense::positive : WallSense::negative, 1000 * copy - 2000,
                      OffsetMode::absolute, 4500 * copy % 36000, 3000, 2000, copy % 2 == 0};
            p.barrier = {6000, 7000, 400, 500 * copy - 1000, 3000 * copy % 36000, 2000, 1000};
            if (one_axis) p.wall.angle = p.barrier.angle = 0;  // axis elements have no angle
            const CreateResult r = engine.create(p);
            ASSERT_TRUE(r.error.ok()) << effect_type_name(t) << ": " << r.error.message();
            ASSERT_TRUE(engine.start(r.id).ok());
        }
    }
    TickOutput out;
    counting = true;
    for (int n = 0; n < 20'000; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        // A slow circle of radius 6000 units with a fast wiggle on top.
        const double t = n * 1e-3;
        in.position[0] = static_cast<float>(6000 * std::cos(2 * 3.14159265 * 0.5 * t) + 300 * std::sin(60 * t));
        in.position[1] = static_cast<float>(6000 * std::sin(2 * 3.14159265 * 0.5 * t));
        engine.tick(in, out);
    }
    counting = false;
    EXPECT_EQ(allocations.load(), 0);
    EXPECT_EQ(out.playing_effects, 60);
}

}  // namespace
}  // namespace feel

namespace feel {
namespace {

// Every Dynamic Sensation with interim reporting on, the handle moving, and the host
// draining the reports: the tick allocates nothing, whatever the model does.
TEST(TickAllocation, EveryDynamicTicksWithoutAllocating) {
    Engine engine(EngineConfig{});
    const EffectType types[] = {EffectType::dynamic_recoil,       EffectType::dynamic_impact,
                                EffectType::dynamic_liquid,       EffectType::dynamic_inertia,
                                EffectType::dynamic_center_drift, EffectType::dynamic_control_law,
                                EffectType::dynamic_sling,        EffectType::dynamic_paddle};
    for (int copy = 0; copy < 4; ++copy) {
        for (EffectType t : types) {
            EffectParams p;
            p.type = t;
            p.duration_us = kInfiniteUs;
            p.axis_count = 2;
            p.axes[0] = Axis::x;
            p.axes[1] = Axis::y;
            DynamicBlock& d = p.dynamic;
            d.blast_direction = d.impact_direction = d.initial_velocity_direction = 9000 * copy;
            d.blast_intensity = d.impact_intensity = d.initial_velocity = 4000;
            d.dynamic_mass = d.density = d.inertia = d.ball_mass = 1000 + 2000 * copy;
            d.blast_resonance = d.elasticity = d.settle = d.stiffness = d.string_compliance =
                d.paddle_compliance = 2000 + 2000 * copy;
            d.blast_decay = d.collision_absorption = d.viscosity = d.paddle_damping = 500 * copy;
            d.play = 300;
            d.drift_resistance = 1000;
            d.string_length = 1000 + 500 * copy;
            d.ball_damping = 200;
            // Asymmetric, with free play, gravity and a half-cycle count: every branch.
            for (ControlLawBlock& c : d.control_law) c = {3000, 5000, 2000, 300, 2000, 500, copy * 3, 200, 100, -1000};
            d.interim_reporting = true;
            const CreateResult r = engine.create(p);
            ASSERT_TRUE(r.error.ok()) << effect_type_name(t) << ": " << r.error.message();
            ASSERT_TRUE(engine.start(r.id).ok());
        }
    }
    TickOutput out;
    DynamicReport report;
    long reports = 0;
    counting = true;
    for (int n = 0; n < 20'000; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        const double t = n * 1e-3;
        in.position[0] = static_cast<float>(4000 * std::cos(2 * 3.14159265 * 1.5 * t));
        in.position[1] = static_cast<float>(4000 * std::sin(2 * 3.14159265 * 1.5 * t));
        engine.tick(in, out);
        while (engine.pop_report(report)) ++reports;
    }
    counting = false;
    EXPECT_EQ(allocations.load(), 0);
    EXPECT_GT(reports, 0);
}

}  // namespace
}  // namespace feel
