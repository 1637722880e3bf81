// Host emulation on a standard PID device (PidDevice, src/host/emulation/pid_emulation.hpp):
// sensations the device lacks, rendered by the host on the positions the device reports
// and streamed as the level of one Constant Force effect per axis.
//
// The rig. The simulated device (its DeviceSession on a RuntimePipeline, as the peripheral
// tests build it) is ticked by the test in lockstep with the host: a tick, then the host is
// handed the frames the tick produced and the test waits until it has answered and sits in
// receive() again. So everything runs on device time (the host's clock reads it) and a run
// repeats exactly: the host's Set Constant Force computed from the Joystick Input of tick n
// reaches the engine at tick n + 1 (one tick of link latency, L = 1 ms).
//
// Truth. The same sensation with the same kinematic hand motion (so the same sensed
// positions, tick by tick) is rendered a second time by the device itself (the engine on the
// device, the sensation's own effect type): the device-side rendering F_dev(m). The host's
// engine is configured as the device's, so it computes what the device would, on the
// position reported at tick n, and that level plays from tick n + 1 until the next report's:
// the host's force at tick m is F_dev(m − τ) with τ ∈ [L, L + T − 1 tick] where T is the
// report period (a report every T). Hence, per tick,
//
//   |F_host(m) − F_dev(m)| ≤ max over τ in [L, L + T − 1] of |F_dev(m) − F_dev(m − τ)| + ε,
//
// the first term being how far the device-side force moves over the link's lag (its rate of
// change times the delay, read off the device-side rendering itself), and ε the resolution:
// the host reads the position rounded to a whole unit (≤ 0.5 unit: half the force's slope per
// unit of position, which the device-side rendering gives as |ΔF_dev/Δp| between ticks),
// plus the host's rounding of its level to a whole unit (0.5) and 0.5 for the device's
// float. For an effect that depends on time alone (a recoil held still) the slope term is 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <cstdio>
#include <thread>

#include "../support/valid_effects.hpp"
#include "emulation/emulated_loop.hpp"
#include "feel/host/pid_device.hpp"
#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "pid_lockstep.hpp"

namespace feel::host {
namespace {


struct Run {
    std::vector<float> force[2];     // the motor's force on x and y, per tick
    std::vector<float> position;     // the sensed x, per tick
};

void record(runtime::RuntimePipeline& p, Run& run) {
    for (int a = 0; a < 2; ++a) run.force[a].push_back(p.motor_force()[a]);
    run.position.push_back(p.last_input().position[0]);
}

// The sensation rendered by the device itself: created and started through the runtime's
// host link, started on tick `start_tick`, recorded for `ticks` ticks from there.
Run device_side(const EffectParams& params, const std::string& motion, int32_t rate, int64_t start_tick, int ticks) {
    const sim::DeviceProfile& p = *sim::find_device_profile("iforce2");
    std::unique_ptr<runtime::RuntimePipeline> pipeline = make_pipeline(p, motion, rate);
    runtime::HostLink link(pipeline->commands(), pipeline->reports());
    EXPECT_TRUE(link.create(params).has_value());
    EffectId id{};
    int64_t tick = 0;
    for (; tick < start_tick; ++tick) {
        pipeline->tick(tick);
        runtime::Report r;
        while (link.poll(r))
            if (r.kind == runtime::ReportKind::ack && r.ack.command == runtime::CommandKind::create) id = r.ack.effect;
    }
    EXPECT_TRUE(id.valid()) << "the device did not create the effect";
    EXPECT_TRUE(link.start_effect(id).has_value());
    Run run;
    for (int i = 0; i < ticks; ++i, ++tick) {
        pipeline->tick(tick);
        runtime::Report r;
        while (link.poll(r)) {
        }
        record(*pipeline, run);
    }
    return run;
}

// The same through PidDevice: the effect created over the PID link (the host renders it),
// started on tick `start_tick`, recorded likewise.
Run host_side(const EffectParams& params, const std::string& motion, int32_t rate, int64_t start_tick, int ticks,
              PidEmulationStats* stats = nullptr) {
    Lockstep rig("iforce2", motion, rate);
    rig.background(true);
    Result<PidDevice> dev = PidDevice::attach(rig.host_end(), "sim:iforce2", OpenOptions{}, [&rig] { return rig.now_us(); });
    if (!dev) {
        rig.background(false);
        ADD_FAILURE() << dev.status().message;
        return {};
    }
    Result<uint16_t> handle = dev->create_effect(params);
    rig.background(false);
    EXPECT_TRUE(handle) << handle.status().message;
    if (!handle) return {};
    EXPECT_TRUE(dev->emulated(*handle));
    EXPECT_LT(rig.tick(), start_tick) << "setting up took longer than the test allows";
    while (rig.tick() < start_tick) rig.step();
    // The device-side start is drained on tick start_tick; the host's renderer starts at its
    // next render, the report of tick start_tick: the same engine time.
    EXPECT_TRUE(dev->start(*handle).ok());
    EXPECT_EQ(dev->status(*handle)->state, runtime::ReportedEffectState::emulated);
    Run run;
    for (int i = 0; i < ticks; ++i) {
        rig.step();
        record(rig.pipeline(), run);
    }
    if (stats) *stats = dev->emulation_stats();
    rig.background(true);
    dev->close();
    rig.background(false);
    return run;
}

struct Comparison {
    double worst_excess = -1e9;  // max over ticks of |F_host − F_dev| − tolerance
    double worst_error = 0;      // max |F_host − F_dev|
    double worst_tolerance = 0;
};

// The bound of the header, per tick and axis, for reports every `period` ticks. The slope
// |ΔF/Δp| is read off the device-side rendering within kSlopeWindow ticks (the sensor holds
// a count for several ticks, so neighbouring ticks alone often show no change). A force that
// follows the handle's velocity (a texture's bumps) gets the velocity's resolution too: the
// host's position difference between two reports is the sensed step q ± 1 unit (two
// roundings of ≤ 0.5), so its velocity, and a force proportional to it, is off by up to 1/q.
constexpr int kSlopeWindow = 100;

Comparison compare(const Run& host, const Run& dev, int period, int from_tick, double velocity_resolution) {
    Comparison c;
    const int lag_min = 1, lag_max = period;  // L = 1 tick, L + T − 1 tick
    const std::size_t n = std::min(host.position.size(), dev.position.size());
    for (int a = 0; a < 2; ++a) {
        for (std::size_t m = static_cast<std::size_t>(from_tick); m < n; ++m) {
            double lag_term = 0;
            for (int tau = lag_min; tau <= lag_max; ++tau)
                lag_term = std::max(lag_term, std::abs(double(dev.force[a][m]) - dev.force[a][m - tau]));
            double slope = 0;
            const std::size_t from = m > kSlopeWindow ? m - kSlopeWindow : 1;
            const std::size_t to = std::min(n - 1, m + kSlopeWindow);
            for (std::size_t k = from; k <= to; ++k) {
                const double dp = std::abs(double(dev.position[k]) - dev.position[k - 1]);
                if (dp > 1e-3) slope = std::max(slope, std::abs(double(dev.force[a][k]) - dev.force[a][k - 1]) / dp);
            }
            const double tolerance = lag_term + 0.5 * slope + velocity_resolution * std::abs(dev.force[a][m]) + 1.0;
            const double error = std::abs(double(host.force[a][m]) - dev.force[a][m]);
            c.worst_excess = std::max(c.worst_excess, error - tolerance);
            c.worst_error = std::max(c.worst_error, error);
            c.worst_tolerance = std::max(c.worst_tolerance, tolerance);
        }
    }
    return c;
}

void expect_matches(const EffectParams& params, const std::string& motion, int32_t rate_hz, double min_force,
                    bool follows_velocity = false) {
    constexpr int64_t kStart = 600;  // ticks: room for the open and the link's set-up
    constexpr int kTicks = 1500;
    PidEmulationStats stats;
    const Run host = host_side(params, motion, rate_hz, kStart, kTicks, &stats);
    const Run dev = device_side(params, motion, rate_hz, kStart, kTicks);
    ASSERT_EQ(host.position.size(), static_cast<std::size_t>(kTicks));
    // The same hand: the same sensed positions.
    for (int m = 0; m < kTicks; ++m) ASSERT_EQ(host.position[m], dev.position[m]) << "tick " << m;
    double peak = 0;
    for (int a = 0; a < 2; ++a)
        for (float f : dev.force[a]) peak = std::max(peak, double(std::abs(f)));
    EXPECT_GT(peak, min_force) << "the device-side rendering hardly pushes: nothing is compared";
    const int period = 1000 / rate_hz;
    const sim::DeviceProfile& profile = *sim::find_device_profile("iforce2");
    const double q = 2.0 * kFullScale / profile.axes[0].sensor_counts;  // the sensed step
    const Comparison c = compare(host, dev, period, period + 1, follows_velocity ? 1.0 / q : 0.0);
    std::printf("[ measured ] worst |F_host - F_dev| %.1f units, largest tolerance %.1f\n", c.worst_error,
                c.worst_tolerance);
    EXPECT_LE(c.worst_excess, 0.0) << "worst error " << c.worst_error << " against tolerance up to "
                                   << c.worst_tolerance;
    // The link: one render per report, and only changed levels sent.
    EXPECT_TRUE(stats.active);
    EXPECT_EQ(stats.link_blocks.size(), 2u);  // x and y
    EXPECT_GE(stats.updates, kTicks / period - 1);
    EXPECT_GT(stats.levels_sent, 0);
    EXPECT_LE(stats.levels_sent, 2 * (stats.updates + 1));
}

// A wall the handle pushes into (the kinematic hand ramps through it). The wall's passivity
// controller reads the velocity (its damper), so the velocity's resolution applies too.
TEST(PidEmulation, WallMatchesTheDeviceSideWallAt1kHzAnd250Hz) {
    const EffectParams wall = emulation::wall_on_x(2000);
    for (const int32_t rate : {1000, 250}) {
        SCOPED_TRACE("report rate " + std::to_string(rate) + " Hz");
        expect_matches(wall, "ramp:x:-1500:4000", rate, 1000.0, true);
    }
}

// A texture: a force that depends on the position alone, swept through by the hand.
TEST(PidEmulation, TextureMatchesTheDeviceSideTexture) {
    EffectParams texture = test::valid_effect(EffectType::texture);
    texture.axes[0] = Axis::x;
    expect_matches(texture, "ramp:x:-3000:3000", 1000, 500.0, true);
}

// A recoil: a force in time (the handle held still).
TEST(PidEmulation, RecoilMatchesTheDeviceSideRecoil) {
    EffectParams recoil = test::valid_effect(EffectType::dynamic_recoil);
    expect_matches(recoil, "hold:0", 1000, 100.0);
}

TEST(PidEmulation, CapabilitiesSayWhatTheHostRenders) {
    Lockstep rig("iforce2", "hold:0", 1000);
    rig.background(true);
    Result<PidDevice> dev = PidDevice::attach(rig.host_end(), "sim:iforce2", OpenOptions{}, [&rig] { return rig.now_us(); });
    ASSERT_TRUE(dev) << dev.status().message;
    const PidCaps& caps = dev->capabilities();
    EXPECT_EQ(caps.input_axes, (std::vector<Axis>{Axis::x, Axis::y}));
    EXPECT_TRUE(caps.emulation_problem.empty()) << caps.emulation_problem;
    EXPECT_NE(caps.emulated_types & effect_type_bit(EffectType::axis_wall), 0u);
    EXPECT_EQ(caps.emulated_types & effect_type_bit(EffectType::spring), 0u);  // the device's own
    EXPECT_EQ(caps.profile, "iforce2");
    // A device block has no status; a freed host handle is gone.
    Result<uint16_t> wall = dev->create_effect(emulation::wall_on_x(1000));
    ASSERT_TRUE(wall) << wall.status().message;
    EXPECT_EQ(dev->effects(), std::vector<uint16_t>{*wall});  // the link's blocks are not listed
    EXPECT_EQ(dev->status(*wall)->state, runtime::ReportedEffectState::stopped);
    EXPECT_EQ(dev->status(1).status().kind, ErrorKind::not_supported);
    ASSERT_TRUE(dev->free_effect(*wall).ok());
    EXPECT_EQ(dev->start(*wall).kind, ErrorKind::invalid_handle);
    const PidEmulationStats stats = dev->emulation_stats();
    ASSERT_EQ(stats.link_blocks.size(), 2u);
    EXPECT_EQ(dev->free_effect(stats.link_blocks[0]).kind, ErrorKind::invalid_handle);
    dev->close();
    rig.background(false);
}

}  // namespace
}  // namespace feel::host
