// Effects through the host API on the in-process simulated device: forces checked against
// the primer's formulas (a spring's F = -k·x, §3.2; gain scales linearly, §6.3), play
// semantics against DirectInput's (iterations, solo, status, SetParameters with and
// without DIEP_START), errors against the ranges of units.hpp and the profile's budgets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "feel/host/device.hpp"
#include "host_test_support.hpp"
#include "support/valid_effects.hpp"

namespace feel::host::test {
namespace {

EffectParams constant_x(int32_t magnitude, int64_t duration_us) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = duration_us;
    p.constant.magnitude = magnitude;
    return p;
}

EffectParams sine_x(int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::sine;
    p.duration_us = kInfiniteUs;
    p.periodic.magnitude = magnitude;
    p.periodic.period_us = 20'000;
    return p;
}

// The largest |force| on x over `window` of state reports.
float peak_force(Device& dev, std::chrono::milliseconds window) {
    float peak = 0;
    const auto end = std::chrono::steady_clock::now() + window;
    while (std::chrono::steady_clock::now() < end) {
        Result<InputState> in = dev.wait_input(100ms);
        if (in) peak = std::max(peak, std::fabs(in->force[0]));
    }
    return peak;
}

TEST(HostEffects, SpringPushesBackWithMinusKX) {
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:3000,0", fast_reports());
    Device& dev = *rig.host;
    ASSERT_TRUE(wait_for_full_force(dev));
    Result<Effect> spring = dev.create_effect(spring_x(1000));
    ASSERT_TRUE(spring) << spring.status().message;
    ASSERT_TRUE(spring->start().ok());
    const InputState in = settled(dev);
    // §3.2: F = -k·(x - offset), coefficient 10000 = 1 force unit per position unit.
    const double x = in.position[0];
    EXPECT_NEAR(x, 3000, 5);  // the hand holds it there (to a sensor step)
    EXPECT_NEAR(in.force[0], -0.1 * x, 2.0);
    EXPECT_NEAR(in.force[1], 0, 1.0);

    // §6.3 / DIPROP_FFGAIN: the device gain scales every force.
    ASSERT_TRUE(dev.set_gain(5000).ok());
    const InputState half = settled(dev);
    EXPECT_EQ(half.gain, 5000);
    EXPECT_NEAR(half.force[0], -0.05 * half.position[0], 2.0);
}

TEST(HostEffects, IterationsPlayTheEffectThatManyTimes) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    EffectParams p = constant_x(2000, 60'000);
    p.iterations = 2;
    Result<Effect> e = dev.create_effect(p);
    ASSERT_TRUE(e) << e.status().message;

    ASSERT_TRUE(e->start(3).ok());  // this play: 3 iterations
    Result<EffectStatusInfo> st = e->status();
    ASSERT_TRUE(st) << st.status().message;
    EXPECT_EQ(st->iterations, 3);
    ASSERT_TRUE(wait_until([&] { return e->status()->state == runtime::ReportedEffectState::stopped; }));
    st = e->status();
    EXPECT_EQ(st->completed_iterations, 3);
    EXPECT_EQ(st->last_end, PlayEnd::finished);
    EXPECT_GE(st->elapsed_us, 3 * 60'000);

    ASSERT_TRUE(e->start().ok());  // the effect's own count
    EXPECT_EQ(e->status()->iterations, 2);
    ASSERT_TRUE(wait_until([&] { return e->status()->state == runtime::ReportedEffectState::stopped; }));
    EXPECT_EQ(e->status()->completed_iterations, 2);

    ASSERT_TRUE(e->start(kInfiniteIterations).ok());
    EXPECT_EQ(e->status()->iterations, kInfiniteIterations);
    ASSERT_TRUE(e->stop().ok());
    EXPECT_EQ(e->status()->last_end, PlayEnd::stopped);

    const Status bad = e->start(300);
    EXPECT_EQ(bad.kind, ErrorKind::invalid_parameter);
    EXPECT_NE(bad.message.find("iterations = 300 is out of range (allowed 1..255)"), std::string::npos) << bad.message;
    // 255 finite iterations travel on a feel device (its Loop Count is 16 bits).
    ASSERT_TRUE(e->start(255).ok());
    EXPECT_EQ(e->status()->iterations, 255);
    ASSERT_TRUE(e->stop().ok());
}

TEST(HostEffects, SoloStopsEveryOtherEffect) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> a = dev.create_effect(constant_x(1000, kInfiniteUs));
    Result<Effect> b = dev.create_effect(sine_x(1000));
    Result<Effect> c = dev.create_effect(constant_x(-1000, kInfiniteUs));
    ASSERT_TRUE(a && b && c);
    ASSERT_TRUE(a->start().ok());
    ASSERT_TRUE(b->start().ok());
    EXPECT_EQ(a->status()->state, runtime::ReportedEffectState::playing);
    ASSERT_TRUE(c->start(runtime::kEffectIterations, true).ok());
    EXPECT_EQ(a->status()->state, runtime::ReportedEffectState::stopped);
    EXPECT_EQ(a->status()->last_end, PlayEnd::stopped);
    EXPECT_EQ(b->status()->state, runtime::ReportedEffectState::stopped);
    EXPECT_EQ(c->status()->state, runtime::ReportedEffectState::playing);
}

TEST(HostEffects, StatusGoesDelayedPlayingStopped) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    EffectParams p = constant_x(1000, 100'000);
    p.start_delay_us = 200'000;
    Result<Effect> e = dev.create_effect(p);
    ASSERT_TRUE(e) << e.status().message;
    EXPECT_EQ(e->status()->state, runtime::ReportedEffectState::stopped);
    EXPECT_EQ(e->status()->last_end, PlayEnd::none);
    ASSERT_TRUE(e->start().ok());
    EXPECT_EQ(e->status()->state, runtime::ReportedEffectState::delayed);
    ASSERT_TRUE(wait_until([&] { return e->status()->state == runtime::ReportedEffectState::playing; }));
    ASSERT_TRUE(wait_until([&] { return e->status()->state == runtime::ReportedEffectState::stopped; }));
    const EffectStatusInfo done = e->status().value();
    EXPECT_EQ(done.last_end, PlayEnd::finished);
    EXPECT_GE(done.elapsed_us, 100'000);
    EXPECT_FALSE(done.emulated);
}

TEST(HostEffects, SetParametersWithoutRestartKeepsItPlaying) {
    SimRig rig = SimRig::make("iforce2", "kinematic", "hold:0", fast_reports());
    Device& dev = *rig.host;
    ASSERT_TRUE(wait_for_full_force(dev));
    Result<Effect> e = dev.create_effect(sine_x(2000));
    ASSERT_TRUE(e) << e.status().message;
    ASSERT_TRUE(e->start().ok());
    EXPECT_NEAR(peak_force(dev, 200ms), 2000, 100);
    const int64_t before = e->status()->elapsed_us;

    EffectParams louder = e->parameters();
    louder.periodic.magnitude = 6000;
    louder.duration_us = 5;  // not in the mask: ignored
    ASSERT_TRUE(e->set_parameters(louder, effect_field::kTypeSpecific).ok());
    EXPECT_EQ(e->parameters().periodic.magnitude, 6000);
    EXPECT_EQ(e->parameters().duration_us, kInfiniteUs);
    const EffectStatusInfo after = e->status().value();
    EXPECT_EQ(after.state, runtime::ReportedEffectState::playing);
    EXPECT_GT(after.elapsed_us, before);  // not restarted
    EXPECT_NEAR(peak_force(dev, 200ms), 6000, 250);

    // With DIEP_START the effect starts over.
    const int64_t running = e->status()->elapsed_us;
    ASSERT_TRUE(e->set_parameters(louder, effect_field::kGain, true).ok());
    EXPECT_LT(e->status()->elapsed_us, running);

    // A refused change changes nothing.
    louder.periodic.magnitude = 12000;
    const Status bad = e->set_parameters(louder, effect_field::kTypeSpecific);
    EXPECT_EQ(bad.kind, ErrorKind::invalid_parameter);
    EXPECT_NE(bad.message.find("periodic.magnitude = 12000 is out of range (allowed 0..10000)"), std::string::npos)
        << bad.message;
    EXPECT_EQ(e->parameters().periodic.magnitude, 6000);
    EXPECT_EQ(e->set_parameters(constant_x(1, 1), effect_field::kAll).kind, ErrorKind::invalid_parameter);
    EXPECT_EQ(e->set_parameters(louder, 1u << 12).kind, ErrorKind::invalid_parameter);
}

TEST(HostEffects, TheIforce1IsFullAfterItsSixteenSlots) {
    SimRig rig = SimRig::make("iforce1");
    Device& dev = *rig.host;
    const int slots = dev.capabilities().effect_slots;
    ASSERT_EQ(slots, 16);  // the profile's data sheet
    std::vector<Effect> effects;
    for (int i = 0; i < slots; ++i) {
        Result<Effect> e = dev.create_effect(constant_x(100 * i, 100'000));
        ASSERT_TRUE(e) << i << ": " << e.status().message;
        effects.push_back(std::move(e.value()));
    }
    Result<PoolInfo> pool = dev.pool();
    ASSERT_TRUE(pool) << pool.status().message;
    EXPECT_EQ(pool->max_effects, slots);
    EXPECT_EQ(pool->free_effects, 0);
    Result<Effect> more = dev.create_effect(constant_x(1, 100'000));
    ASSERT_FALSE(more);
    EXPECT_EQ(more.status().kind, ErrorKind::device_full) << more.status().message;
    // RAII: dropping a handle frees its block.
    effects.pop_back();
    EXPECT_EQ(dev.pool()->free_effects, 1);
    EXPECT_TRUE(dev.create_effect(constant_x(1, 100'000)));
}

TEST(HostEffects, DynamicsOnIforce1AreRenderedByTheHost) {
    // The device plays no Dynamics (§5.1); the host renders them (§1.2.c, host_rendering_test.cpp).
    SimRig rig = SimRig::make("iforce1");
    ASSERT_FALSE(rig.host->capabilities().supports(EffectType::dynamic_recoil));
    Result<Effect> e = rig.host->create_effect(feel::test::valid_effect(EffectType::dynamic_recoil));
    ASSERT_TRUE(e) << e.status().message;
    EXPECT_TRUE(e->emulated());
    EXPECT_EQ(e->block(), 0);
}

TEST(HostEffects, HostChecksNameTheFieldAndTheRange) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    EffectParams p = spring_x(1000);
    p.conditions[0].deadband = 12000;
    Result<Effect> e = dev.create_effect(p);
    ASSERT_FALSE(e);
    EXPECT_EQ(e.status().kind, ErrorKind::invalid_parameter);
    EXPECT_EQ(e.status().message, "create spring: conditions[0].deadband = 12000 is out of range (allowed 0..10000)");
    EXPECT_STREQ(e.status().detail.field, "conditions[0].deadband");

    EffectParams wide = spring_x(1000);  // three axes on a two-axis stick
    wide.axis_count = 3;
    e = dev.create_effect(wide);
    ASSERT_FALSE(e);
    EXPECT_NE(e.status().message.find("axis_count = 3 is out of range (allowed 1..2)"), std::string::npos)
        << e.status().message;

    EffectParams button = constant_x(1000, 100'000);
    button.trigger = {TriggerKind::button, 5};  // the stick has 4
    e = dev.create_effect(button);
    ASSERT_FALSE(e);
    EXPECT_NE(e.status().message.find("trigger_button = 5 is out of range (allowed 1..4)"), std::string::npos)
        << e.status().message;

    EffectParams loops = constant_x(1000, 100'000);
    loops.iterations = 255;  // finite: a feel device's iterations are 16 bits, 0xFFFF infinite
    e = dev.create_effect(loops);
    ASSERT_TRUE(e) << e.status().message;
    loops.iterations = 256;
    e = dev.create_effect(loops);
    ASSERT_FALSE(e);
    EXPECT_NE(e.status().message.find("iterations = 256 is out of range (allowed 1..255)"), std::string::npos)
        << e.status().message;

    EXPECT_EQ(dev.set_gain(10001).message, "set_gain: gain = 10001 is out of range (allowed 0..10000)");
    EXPECT_EQ(dev.set_report_rate(50).kind, ErrorKind::invalid_parameter);
    // Nothing reached the device.
    EXPECT_EQ(dev.pool()->free_effects, dev.capabilities().effect_slots);
}

TEST(HostEffects, EveryTypeDownloadsOnIforce2AndFreesOnUnload) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    for (const EffectSupport& s : dev.effects()) {
        SCOPED_TRACE(std::string(effect_type_name(s.type)));
        const EffectParams p = feel::test::valid_effect(s.type);
        const std::span<const int16_t> samples = s.type == EffectType::force_profile
                                                     ? std::span<const int16_t>(feel::test::kFourSamples)
                                                     : std::span<const int16_t>();
        Result<Effect> e = dev.create_effect(p, samples);
        ASSERT_TRUE(e) << e.status().message;
        EXPECT_TRUE(e->downloaded());
        EXPECT_NE(e->block(), 0);
        EXPECT_TRUE(e->start().ok());
        EXPECT_TRUE(e->stop().ok());
    }
    EXPECT_EQ(dev.pool()->free_effects, dev.capabilities().effect_slots);
}

TEST(HostEffects, UnloadDownloadAndInvalidHandles) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    Result<Effect> e = dev.create_effect(sine_x(1000));
    ASSERT_TRUE(e);
    ASSERT_TRUE(e->unload().ok());
    EXPECT_FALSE(e->downloaded());
    EXPECT_TRUE(e->valid());
    const Status gone = e->start();
    EXPECT_EQ(gone.kind, ErrorKind::invalid_handle);
    EXPECT_NE(gone.message.find("unloaded"), std::string::npos) << gone.message;
    // Parameters changed while unloaded go down with the next download.
    EffectParams p = e->parameters();
    p.periodic.magnitude = 3000;
    ASSERT_TRUE(e->set_parameters(p, effect_field::kTypeSpecific).ok());
    ASSERT_TRUE(e->download().ok());
    EXPECT_TRUE(e->start().ok());

    Effect moved = std::move(e.value());
    EXPECT_EQ(e->start().kind, ErrorKind::invalid_handle);  // NOLINT(bugprone-use-after-move): the point
    EXPECT_TRUE(moved.valid());
    Effect empty;
    EXPECT_EQ(empty.stop().kind, ErrorKind::invalid_handle);
    EXPECT_FALSE(empty.status());

    dev.close();
    EXPECT_FALSE(moved.valid());
    EXPECT_EQ(moved.start().kind, ErrorKind::invalid_handle);
    EXPECT_EQ(dev.create_effect(sine_x(1)).status().kind, ErrorKind::disconnected);
}

}  // namespace
}  // namespace feel::host::test
