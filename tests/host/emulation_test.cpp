// Host emulation of reflexes (§1.2.c): on the I-FORCE 1.x-class device, which runs no
// reflexes itself, the host starts a trigger effect on the press and says so
// (emulated); on the 2.0-class device the same effect is a device reflex. The device's own
// reflex counter (RuntimeCounters::reflex_starts) tells who started it.
#include <gtest/gtest.h>

#include <thread>

#include "feel/host/device.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

// A jolt on button 1, repeating while held.
EffectParams jolt_on_button_1(int64_t duration_us, int64_t repeat_us) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = duration_us;
    p.constant.magnitude = 4000;
    p.trigger = {TriggerKind::button, 1};
    p.trigger_repeat_interval_us = repeat_us;
    return p;
}

int64_t device_reflex_starts(SimRig& rig) { return rig.device->stats().runtime.pipeline.reflex_starts; }

runtime::ReportedEffectState state_of(Effect& e) {
    Result<EffectStatusInfo> st = e.status();
    return st ? st->state : runtime::ReportedEffectState::stopped;
}

TEST(HostEmulation, Iforce1ReflexIsPlayedByTheHostAndSaysEmulated) {
    SimRig rig = SimRig::make("iforce1");
    Device& dev = *rig.host;
    ASSERT_FALSE(dev.capabilities().local_reflexes);
    Result<Effect> e = dev.create_effect(jolt_on_button_1(300'000, 0));
    ASSERT_TRUE(e) << e.status().message;
    EXPECT_TRUE(e->emulated());
    EffectStatusInfo st = e->status().value();
    EXPECT_TRUE(st.emulated);
    EXPECT_EQ(st.state, runtime::ReportedEffectState::stopped);

    rig.set_buttons(0b1);
    ASSERT_TRUE(wait_until([&] { return state_of(*e) == runtime::ReportedEffectState::emulated; }));
    st = e->status().value();
    EXPECT_TRUE(st.emulated);
    EXPECT_EQ(device_reflex_starts(rig), 0);  // the device did not start it: the host did
    rig.set_buttons(0);
    ASSERT_TRUE(wait_until([&] { return state_of(*e) == runtime::ReportedEffectState::stopped; }));
    EXPECT_EQ(e->status()->last_end, PlayEnd::finished);

    // The game's own start plays it normally: playing, not "emulated" (it still is an
    // emulated reflex, so emulated stays true).
    ASSERT_TRUE(e->start().ok());
    st = e->status().value();
    EXPECT_EQ(st.state, runtime::ReportedEffectState::playing);
    EXPECT_TRUE(st.emulated);
}

TEST(HostEmulation, Iforce1HeldTriggerRepeatsAtTheInterval) {
    SimRig rig = SimRig::make("iforce1");
    Device& dev = *rig.host;
    // 60 ms jolts every 200 ms while held: in 700 ms of holding, plays start at 0, 200,
    // 400 and 600 ms.
    Result<Effect> e = dev.create_effect(jolt_on_button_1(60'000, 200'000));
    ASSERT_TRUE(e) << e.status().message;
    rig.set_buttons(0b1);
    const auto end = std::chrono::steady_clock::now() + 700ms;
    int plays = 0;
    bool was_playing = false;
    while (std::chrono::steady_clock::now() < end) {
        const bool playing = state_of(*e) == runtime::ReportedEffectState::emulated;
        if (playing && !was_playing) ++plays;
        was_playing = playing;
        std::this_thread::sleep_for(5ms);
    }
    rig.set_buttons(0);
    EXPECT_GE(plays, 3);
    EXPECT_LE(plays, 4);
    EXPECT_EQ(device_reflex_starts(rig), 0);
}

TEST(HostEmulation, ATriggerHeldWhenArmedIsNotAPress) {
    SimRig rig = SimRig::make("iforce1");
    Device& dev = *rig.host;
    rig.set_buttons(0b1);
    ASSERT_TRUE(wait_until([&] { return dev.input().buttons == 1u; }));
    Result<Effect> e = dev.create_effect(jolt_on_button_1(100'000, 0));
    ASSERT_TRUE(e);
    std::this_thread::sleep_for(100ms);
    EXPECT_EQ(state_of(*e), runtime::ReportedEffectState::stopped);
    rig.set_buttons(0);
    std::this_thread::sleep_for(30ms);
    rig.set_buttons(0b1);
    EXPECT_TRUE(wait_until([&] { return state_of(*e) == runtime::ReportedEffectState::emulated; }));
}

TEST(HostEmulation, Iforce2RunsTheSameReflexOnTheDevice) {
    SimRig rig = SimRig::make("iforce2");
    Device& dev = *rig.host;
    ASSERT_TRUE(dev.capabilities().local_reflexes);
    Result<Effect> e = dev.create_effect(jolt_on_button_1(300'000, 0));
    ASSERT_TRUE(e) << e.status().message;
    EXPECT_FALSE(e->emulated());
    rig.set_buttons(0b1);
    ASSERT_TRUE(wait_until([&] { return state_of(*e) == runtime::ReportedEffectState::playing; }));
    EXPECT_FALSE(e->status()->emulated);
    EXPECT_EQ(device_reflex_starts(rig), 1);  // the device's own reflex table started it
}

TEST(HostEmulation, ChangingTheTriggerMovesTheReflex) {
    for (const char* profile : {"iforce1", "iforce2"}) {
        SCOPED_TRACE(profile);
        SimRig rig = SimRig::make(profile);
        Device& dev = *rig.host;
        Result<Effect> e = dev.create_effect(jolt_on_button_1(300'000, 0));
        ASSERT_TRUE(e);
        EffectParams p = e->parameters();
        p.trigger = {TriggerKind::button, 3};
        ASSERT_TRUE(e->set_parameters(p, effect_field::kTrigger).ok());
        rig.set_buttons(0b001);  // the old trigger: nothing
        std::this_thread::sleep_for(80ms);
        EXPECT_EQ(state_of(*e), runtime::ReportedEffectState::stopped);
        rig.set_buttons(0b101);  // button 3
        EXPECT_TRUE(wait_until([&] { return state_of(*e) != runtime::ReportedEffectState::stopped; }));
    }
}

}  // namespace
}  // namespace feel::host::test
