// Host rendering (§1.2.c, src/host/emulation): effect types the device does not play are
// rendered by the host's engine on the positions the device reports and streamed back as a
// force. Against the in-process simulated device: the I-FORCE 1.x class (no Dynamics) and
// a device with only HID PID 1.0's effect types (pid_effects_only: no walls, textures...).
//
// Truth. A wall's force is the spring law of §3.7: F = −K·(h/10000)·penetration, with K the
// profile's hardness-10000 stiffness (sim::engine_config_for, docs/stability.md) and the
// penetration measured from the surface. The handle here is held still by a kinematic hand,
// so the lag of the host's loop (an update period plus the link's latency) costs nothing
// and what remains is resolution: the device senses the position in whole sensor counts q
// (both renderings see that same count), and the host reads it from the Joystick Input
// report rounded to a whole unit (≤ 0.5 unit), then rounds its force to a whole unit
// (≤ 0.5). So |F_host − K_h·p_sensed| ≤ K_h·0.5 + 0.5 + the device's own rounding, and
// |F − K_h·p_true| ≤ K_h·q/2 plus those, where p_true is the hand's position.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <thread>

#include "../support/valid_effects.hpp"
#include "emulation/emulated_loop.hpp"
#include "feel/host/device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/transport/transport.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

// SimRig::make, with the device's pid_effects_only option.
SimRig make_rig(const std::string& profile, bool pid_only, const std::string& hand, const std::string& motion) {
    peripheral::PeripheralOptions po;
    po.profile = profile;
    po.hand = hand;
    po.motion = motion;
    po.pid_effects_only = pid_only;
    po.runtime.realtime_priority = false;
    po.runtime.lock_memory = false;
    SimRig rig;
    rig.device = std::make_unique<peripheral::Peripheral>(po);
    transport::ConnectionPair pair = transport::in_process_pair("sim:" + profile);
    rig.device->attach(std::move(pair.device));
    Result<Device> opened = Device::attach(std::move(pair.host), "sim:" + profile);
    if (!opened) ADD_FAILURE() << opened.status().message;
    else rig.host.emplace(std::move(opened.value()));
    return rig;
}

EffectParams wall_x(int32_t hardness) { return emulation::wall_on_x(hardness); }

// The motor force on x once it has settled: after the safety fade-in and the stream's
// first ramp (half a second), 50 state rounds in a row within 1 unit of each other.
double settled_force_x(Device& dev) {
    std::this_thread::sleep_for(500ms);
    double last = 1e9;
    int same = 0;
    for (int i = 0; i < 2000 && same < 50; ++i) {
        Result<InputState> in = dev.wait_input(200ms);
        if (!in) continue;
        const double f = in->force[0];
        same = std::abs(f - last) <= 1.0 ? same + 1 : 0;
        last = f;
    }
    return last;
}

TEST(HostRendering, Iforce1DynamicsAreCreatedAndPlayedByTheHost) {
    SimRig rig = make_rig("iforce1", false, "firm", "hold:0");
    Device& dev = *rig.host;
    ASSERT_FALSE(dev.capabilities().supports(EffectType::dynamic_recoil));
    // EnumEffects lists what the host can create: the device's types and the host's.
    bool listed = false;
    for (const EffectSupport& s : dev.effects(EffectClass::dynamic)) listed |= s.type == EffectType::dynamic_recoil;
    EXPECT_TRUE(listed);

    Result<Effect> recoil = dev.create_effect(feel::test::valid_effect(EffectType::dynamic_recoil));
    ASSERT_TRUE(recoil) << recoil.status().message;
    EXPECT_TRUE(recoil->emulated());
    EXPECT_TRUE(recoil->downloaded());
    EXPECT_EQ(recoil->block(), 0);  // no device block: the host holds it
    EXPECT_EQ(recoil->status()->state, runtime::ReportedEffectState::stopped);

    ASSERT_TRUE(recoil->start().ok());
    EffectStatusInfo st = recoil->status().value();
    EXPECT_TRUE(st.emulated);
    EXPECT_EQ(st.state, runtime::ReportedEffectState::emulated);
    // The blast pushes from 180° (south): the force reaches the device's motors. Every
    // state round is watched until the recoil ends by itself.
    float peak = 0;
    const auto deadline = std::chrono::steady_clock::now() + 3s;
    while (std::chrono::steady_clock::now() < deadline &&
           recoil->status()->state != runtime::ReportedEffectState::stopped) {
        if (Result<InputState> in = dev.wait_input(50ms)) peak = std::max(peak, std::abs(in->force[1]));
    }
    // Nothing else plays on the device, so any force beyond the stream's rounding (1 unit)
    // is the host's; the firm grip keeps the recoil's tether force small (~100 units).
    EXPECT_GT(peak, 20.0f) << "the host's force never reached the device";
    // The host then sends one zero and the motors rest.
    EXPECT_EQ(recoil->status()->state, runtime::ReportedEffectState::stopped);
    EXPECT_EQ(recoil->status()->last_end, PlayEnd::finished);
    EXPECT_TRUE(wait_until([&] { return std::abs(dev.input().force[1]) < 1.0f; }));
}

// A dynamic's interim and final reports (§5.2), as the effect's and the device's subscribers
// receive them: `effect_events` those of the effect's own subscription.
struct DynamicRun {
    std::vector<DynamicEvent> effect_events, device_events, other_events;
};

DynamicRun play_reporting_recoil(Device& dev) {
    EffectParams p = feel::test::valid_effect(EffectType::dynamic_recoil);
    p.dynamic.interim_reporting = true;
    Result<Effect> recoil = dev.create_effect(p);
    Result<Effect> other = dev.create_effect(feel::test::valid_effect(EffectType::dynamic_recoil));
    EXPECT_TRUE(recoil && other);
    DynamicRun run;
    if (!recoil || !other) return run;
    std::mutex mu;
    Subscription mine = recoil->subscribe([&](const DynamicEvent& ev) {
        std::lock_guard lock(mu);
        run.effect_events.push_back(ev);
    });
    Subscription every = dev.subscribe([&](const DynamicEvent& ev) {
        std::lock_guard lock(mu);
        run.device_events.push_back(ev);
    });
    Subscription theirs = other->subscribe([&](const DynamicEvent& ev) {
        std::lock_guard lock(mu);
        run.other_events.push_back(ev);
    });
    EXPECT_TRUE(recoil->start().ok());
    EXPECT_TRUE(wait_until([&] { return recoil->status()->state == runtime::ReportedEffectState::stopped; }, 5s));
    std::this_thread::sleep_for(100ms);  // the last report's trip
    std::lock_guard lock(mu);
    return run;
}

// What a device-rendered dynamic's subscribers get (§5.2's rules, independent of who renders):
// interim reports at the engine's rate while it plays (the k-th due k periods after the
// first, on a grid, so never more of them than the rate allows), in time order, and one
// final report when it ends by itself, after them.
void expect_reports_of_one_play(const DynamicRun& run, double interim_hz, const char* who) {
    SCOPED_TRACE(who);
    int interim = 0, finals = 0;
    int64_t first_interim = -1;
    const auto period = static_cast<int64_t>(1e6 / interim_hz);
    for (std::size_t i = 0; i < run.effect_events.size(); ++i) {
        const DynamicEvent& ev = run.effect_events[i];
        EXPECT_EQ(ev.axis_count, 2);
        if (ev.kind == DynamicReport::Kind::interim) {
            EXPECT_EQ(finals, 0) << "an interim report after the final one";
            if (first_interim < 0) first_interim = ev.t_us;
            EXPECT_GE(ev.t_us - first_interim, interim * period - 1) << "interim report " << interim;
            ++interim;
        } else {
            ++finals;
        }
        if (i > 0) {
            EXPECT_GE(ev.t_us, run.effect_events[i - 1].t_us);
        }
    }
    EXPECT_GE(interim, 3) << "the recoil plays for tenths of a second at " << interim_hz << " Hz";
    EXPECT_LE(finals, 1);
    // The device's subscription gets the same events; another effect's gets none.
    EXPECT_EQ(run.device_events.size(), run.effect_events.size());
    EXPECT_TRUE(run.other_events.empty());
}

TEST(HostRendering, HostRenderedDynamicsReportToSubscribersAsTheDevicesDo) {
    // iforce1 has no Dynamics: the host renders the recoil. iforce2 renders it itself.
    SimRig host_side = make_rig("iforce1", false, "firm", "hold:0");
    ASSERT_FALSE(host_side.host->capabilities().supports(EffectType::dynamic_recoil));
    const DynamicRun emulated = play_reporting_recoil(*host_side.host);
    SimRig device_side = make_rig("iforce2", false, "firm", "hold:0");
    ASSERT_TRUE(device_side.host->capabilities().supports(EffectType::dynamic_recoil));
    const DynamicRun native = play_reporting_recoil(*device_side.host);
    // The host's engine reports at the engine's rate, EngineConfig's default (iforce1's
    // profile has none of its own: it has no Dynamics); iforce2 says its rate.
    expect_reports_of_one_play(emulated, EngineConfig{}.interim_report_hz, "host-rendered on iforce1");
    expect_reports_of_one_play(native, device_side.host->capabilities().interim_report_hz, "device-rendered on iforce2");
    int emulated_finals = 0, native_finals = 0;
    for (const DynamicEvent& ev : emulated.effect_events) emulated_finals += ev.kind == DynamicReport::Kind::final;
    for (const DynamicEvent& ev : native.effect_events) native_finals += ev.kind == DynamicReport::Kind::final;
    EXPECT_EQ(emulated_finals, native_finals);
}

TEST(HostRendering, TypesTheDevicePlaysStayOnTheDevice) {
    SimRig rig = make_rig("iforce1", false, "firm", "hold:0");
    Result<Effect> spring = rig.host->create_effect(feel::test::valid_effect(EffectType::spring));
    ASSERT_TRUE(spring) << spring.status().message;
    EXPECT_FALSE(spring->emulated());
    EXPECT_NE(spring->block(), 0);
    ASSERT_TRUE(spring->start().ok());
    EXPECT_EQ(spring->status()->state, runtime::ReportedEffectState::playing);
}

TEST(HostRendering, PidOnlyDeviceRefusesAWallItselfAndTheHostRendersIt) {
    SimRig rig = make_rig("iforce2", true, "kinematic", "hold:400");
    Device& dev = *rig.host;
    EXPECT_FALSE(dev.capabilities().supports(EffectType::axis_wall));
    EXPECT_FALSE(dev.capabilities().supports(EffectType::texture));
    EXPECT_TRUE(dev.capabilities().supports(EffectType::spring));
    Result<Effect> wall = dev.create_effect(wall_x(1000));
    ASSERT_TRUE(wall) << wall.status().message;
    EXPECT_TRUE(wall->emulated());
}

// The same wall rendered by the device (iforce2) and by the host (iforce2 with PID's
// effect types only), against the spring law. Both devices are the joystick's mechanics.
TEST(HostRendering, HostWallMatchesTheDeviceWallAndTheSpringLaw) {
    const sim::DeviceProfile& profile = *sim::find_device_profile("iforce2");
    const double k = sim::engine_config_for(profile).wall_stiffness;  // hardness 10000
    const int32_t hardness = 2000;
    const double k_h = k * hardness / 10000.0;
    const double p_true = 400.0;                     // the kinematic hand's x
    const double q = 20000.0 / profile.axes[0].sensor_counts;  // one sensor count
    const double expected = -k_h * p_true;          // the wall pushes toward −x

    double force[2] = {};
    for (int host = 0; host < 2; ++host) {
        SimRig rig = make_rig("iforce2", host == 1, "kinematic", "hold:400");
        Result<Effect> wall = rig.host->create_effect(wall_x(hardness));
        ASSERT_TRUE(wall) << wall.status().message;
        EXPECT_EQ(wall->emulated(), host == 1);
        ASSERT_TRUE(wall->start().ok());
        force[host] = settled_force_x(*rig.host);
    }
    // Each against the law: the sensed position is within half a count of the hand's
    // (a count is K_h·q of force), plus the reports' and the host's rounding.
    const double law_tolerance = k_h * q / 2 + k_h * 0.5 + 1.0;
    EXPECT_NEAR(force[0], expected, law_tolerance) << "device-side wall";
    EXPECT_NEAR(force[1], expected, law_tolerance) << "host-rendered wall";
    // Against each other: the same sensed count; the host reads it rounded to a unit.
    EXPECT_NEAR(force[1], force[0], k_h * 0.5 + 1.0);
}

TEST(HostRendering, ResetFreesHostEffectsAndDownloadBringsThemBack) {
    SimRig rig = make_rig("iforce1", false, "firm", "hold:0");
    Device& dev = *rig.host;
    Result<Effect> e = dev.create_effect(feel::test::valid_effect(EffectType::dynamic_recoil));
    ASSERT_TRUE(e) << e.status().message;
    ASSERT_TRUE(dev.command(runtime::DeviceControl::reset).ok());
    EXPECT_FALSE(e->downloaded());
    Status s = e->start();
    EXPECT_EQ(s.kind, ErrorKind::invalid_handle) << s.message;
    EXPECT_NE(s.message.find("reset"), std::string::npos) << s.message;
    ASSERT_TRUE(e->download().ok());
    EXPECT_TRUE(e->downloaded());
    EXPECT_TRUE(e->start().ok());
}

}  // namespace
}  // namespace feel::host::test
