// Force streaming through the device runtime (§2.4): stream_force commands through the
// command queue, the reconstructed force added to the effects' before the safety monitor,
// and what ends a stream. Truth: the samples the host sent, the effects' definitions (a
// constant of magnitude m pushes m; the device gain multiplies), the motor limit (±10000),
// the primer's device commands (stop all, reset, pause) and a second run of the same
// commands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "feel/runtime/runtime_pipeline.hpp"
#include "runtime_rig.hpp"

namespace feel::runtime::test {
namespace {

EffectParams constant_x(int32_t magnitude) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = kInfiniteUs;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.constant.magnitude = magnitude;
    return p;
}

// Streams (x, y) to the joystick; the sample acts from the next tick.
std::optional<uint32_t> stream(Rig& rig, int16_t x, int16_t y) {
    const int16_t force[2] = {x, y};
    return rig.host().stream_force(force);
}

float motor(Rig& rig, int axis) { return rig.pipeline().motor_force()[axis]; }

TEST(ForceStreamPipeline, TheJoystickHasTwoAxes) {
    ASSERT_EQ(quiet_config().engine.axis_count, 2);  // what the samples below carry
}

TEST(ForceStreamPipeline, AOneKilohertzStreamReachesTheMotorsInTheTickItArrives) {
    Rig rig(quiet_config());
    for (int64_t n = 0; n < 1000; ++n) {
        const double t_s = static_cast<double>(n) / 1000;
        const auto x = static_cast<int16_t>(std::lround(9000 * std::sin(2 * std::numbers::pi * 5 * t_s)));
        const auto y = static_cast<int16_t>(std::lround(-4000 * std::cos(2 * std::numbers::pi * 3 * t_s)));
        ASSERT_TRUE(stream(rig, x, y).has_value());
        rig.run(1);
        if (n >= 1) {  // the first sample's rate is not known yet
            ASSERT_EQ(motor(rig, 0), x) << "tick " << n;
            ASSERT_EQ(motor(rig, 1), y) << "tick " << n;
        }
    }
    for (const CommandAck& a : rig.acks) {
        ASSERT_EQ(a.command, CommandKind::stream_force);
        ASSERT_TRUE(a.error.ok()) << a.error.message();
    }
    EXPECT_EQ(rig.acks.size(), 1000u);
    EXPECT_EQ(rig.pipeline().force_stream().samples(), 1000);
}

TEST(ForceStreamPipeline, ABadSampleIsRefusedByNameAndChangesNothing) {
    Rig rig(quiet_config());
    rig.ok(stream(rig, 3000, -3000));
    rig.run(30);
    ASSERT_EQ(motor(rig, 0), 3000.0f);

    const int16_t one[1] = {5000};
    CommandAck a = rig.ack(rig.host().stream_force(one));
    EXPECT_EQ(a.error.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(a.error.message(), "stream.axis_count = 1 is out of range (allowed 2..2)");
    const int16_t seven[7] = {1, 2, 3, 4, 5, 6, 7};  // more than any device has
    a = rig.ack(rig.host().stream_force(seven));
    EXPECT_EQ(a.error.message(), "stream.axis_count = 7 is out of range (allowed 2..2)");
    a = rig.ack(stream(rig, 0, 10001));
    EXPECT_EQ(a.error.message(), "stream.force[1] = 10001 is out of range (allowed -10000..10000)");
    a = rig.ack(stream(rig, -10001, 0));
    EXPECT_EQ(a.error.message(), "stream.force[0] = -10001 is out of range (allowed -10000..10000)");

    rig.run(30);
    EXPECT_EQ(motor(rig, 0), 3000.0f);
    EXPECT_EQ(motor(rig, 1), -3000.0f);
    EXPECT_EQ(rig.pipeline().force_stream().samples(), 1);
}

TEST(ForceStreamPipeline, TheStreamAddsToTheEffectsAndTheSumIsClamped) {
    Rig rig(quiet_config());
    const CommandAck created = rig.ok(rig.host().create(constant_x(8000)));
    rig.ok(rig.host().start_effect(created.effect));
    rig.ok(stream(rig, 5000, 2500));
    rig.run(40);
    EXPECT_EQ(motor(rig, 0), 10000.0f);  // 8000 + 5000, at the motor limit
    EXPECT_EQ(motor(rig, 1), 2500.0f);
    rig.ok(stream(rig, -10000, -10000));
    rig.run(40);
    EXPECT_EQ(motor(rig, 0), -2000.0f);  // 8000 − 10000
    EXPECT_EQ(motor(rig, 1), -10000.0f);
    for (const StateReport& s : rig.states) {
        for (int a = 0; a < 2; ++a) {
            ASSERT_FALSE(std::isnan(s.force[a]));
            ASSERT_LE(std::abs(s.force[a]), 10000.0f);
        }
    }
}

TEST(ForceStreamPipeline, TheDeviceGainScalesTheStream) {
    Rig rig(quiet_config());
    rig.ok(rig.host().set_gain(2500));
    rig.ok(stream(rig, 8000, -6000));
    rig.run(40);
    EXPECT_EQ(motor(rig, 0), 2000.0f);
    EXPECT_EQ(motor(rig, 1), -1500.0f);
    EXPECT_EQ(rig.pipeline().streamed_force()[0], 8000.0f);  // reconstructed before the gain
}

TEST(ForceStreamPipeline, PauseSilencesTheStreamAndKeepsIt) {
    Rig rig(quiet_config());
    rig.ok(stream(rig, 6000, 0));
    rig.run(40);
    rig.ok(rig.host().control(DeviceControl::pause));
    rig.run(100);
    EXPECT_EQ(motor(rig, 0), 0.0f);
    rig.ok(rig.host().control(DeviceControl::resume));
    EXPECT_EQ(motor(rig, 0), 6000.0f);  // the tick that applied the resume
    rig.ok(rig.host().control(DeviceControl::actuators_off));
    EXPECT_EQ(motor(rig, 0), 0.0f);
}

TEST(ForceStreamPipeline, AStoppedStreamHoldsForSeconds) {
    Rig rig(quiet_config());
    for (int k = 0; k < 30; ++k) {
        rig.ok(stream(rig, static_cast<int16_t>(100 * k), static_cast<int16_t>(-100 * k)));
        rig.run(16);
    }
    rig.run(20);
    for (int64_t n = 0; n < 5000; ++n) {  // 5 s of silence
        rig.run(1);
        ASSERT_EQ(motor(rig, 0), 2900.0f);
        ASSERT_EQ(motor(rig, 1), -2900.0f);
    }
}

TEST(ForceStreamPipeline, StopAllAndResetClearTheStream) {
    for (const DeviceControl control : {DeviceControl::stop_all, DeviceControl::reset}) {
        Rig rig(quiet_config());
        rig.ok(stream(rig, 7000, 7000));
        rig.run(40);
        ASSERT_EQ(motor(rig, 0), 7000.0f);
        rig.ok(rig.host().control(control));
        EXPECT_EQ(motor(rig, 0), 0.0f) << device_control_name(control);
        rig.run(100);
        EXPECT_EQ(motor(rig, 0), 0.0f) << device_control_name(control);
        EXPECT_FALSE(rig.pipeline().force_stream().active());
    }
}

TEST(ForceStreamPipeline, LosingTheHostEndsTheStream) {
    RuntimeConfig config = quiet_config();
    config.safety.host_timeout_us = 100'000;
    config.safety.host_fade_out_us = 0;  // cut at once
    Rig rig(config);
    const CommandAck last = rig.ok(stream(rig, 6000, -6000));
    rig.run(40);
    EXPECT_EQ(motor(rig, 0), 6000.0f);
    // Silence: the force holds until the watchdog trips, then it is gone.
    while (rig.t_us() <= last.t_us + 100'000) {
        rig.run(1);
        ASSERT_EQ(motor(rig, 0), 6000.0f) << rig.t_us();
    }
    rig.run(1);
    EXPECT_EQ(motor(rig, 0), 0.0f);
    EXPECT_EQ(rig.pipeline().counters().host_losses, 1);
    EXPECT_FALSE(rig.pipeline().force_stream().active());
    // The host comes back: heard again, and nothing of the old stream returns.
    rig.ok(rig.host().keep_alive());
    rig.run(100);
    EXPECT_FALSE(rig.pipeline().safety().state().host_lost);
    EXPECT_EQ(motor(rig, 0), 0.0f);
    EXPECT_EQ(motor(rig, 1), 0.0f);
}

// A game's 60 Hz stream of a 1 Hz sine plus a step, as a host would send it.
struct Trace {
    std::vector<float> motor_x;   // per tick
    std::vector<int16_t> latest;  // per tick: the newest sample sent
};

Trace run_sixty_hertz(Rig& rig, int64_t ticks) {
    Trace trace;
    int16_t latest = 0;
    int64_t next_frame = 0;
    for (int64_t n = 0; n < ticks; ++n) {
        // Frame k goes out in the first tick at or after k/60 s.
        if (n >= (next_frame * 1000 + 59) / 60) {
            const double t_s = static_cast<double>(next_frame) / 60;
            const double value = 6000 * std::sin(2 * std::numbers::pi * t_s) + (t_s >= 1.5 ? 3000 : 0);
            latest = static_cast<int16_t>(std::lround(value));
            EXPECT_TRUE(stream(rig, latest, static_cast<int16_t>(-latest)).has_value());
            ++next_frame;
        }
        rig.run(1);
        trace.motor_x.push_back(motor(rig, 0));
        trace.latest.push_back(latest);
    }
    return trace;
}

TEST(ForceStreamPipeline, ASixtyHertzStreamIsSmoothAndTheSameEveryRun) {
    Rig first(quiet_config());
    Rig second(quiet_config());
    const Trace a = run_sixty_hertz(first, 3000);
    const Trace b = run_sixty_hertz(second, 3000);
    ASSERT_EQ(a.motor_x.size(), b.motor_x.size());
    EXPECT_EQ(std::memcmp(a.motor_x.data(), b.motor_x.data(), a.motor_x.size() * sizeof(float)), 0);

    // Overshoot: how far the output goes beyond the range of the samples sent so far in
    // the last 3 frames (50 ms); step: the largest tick-to-tick change, and the largest
    // change between frames it is made of.
    double overshoot = 0;
    float step = 0;
    int32_t frame_change = 0;
    for (size_t n = 51; n < a.motor_x.size(); ++n) {
        const auto window = std::minmax_element(a.latest.begin() + static_cast<std::ptrdiff_t>(n - 50),
                                                a.latest.begin() + static_cast<std::ptrdiff_t>(n + 1));
        overshoot = std::max({overshoot, static_cast<double>(a.motor_x[n]) - *window.second,
                              static_cast<double>(*window.first) - a.motor_x[n]});
        step = std::max(step, std::abs(a.motor_x[n] - a.motor_x[n - 1]));
        frame_change = std::max(frame_change, std::abs(a.latest[n] - a.latest[n - 1]));
    }
    EXPECT_LE(overshoot, 0.0);
    EXPECT_LE(step, 1.15 * frame_change / (1000.0 / 60));
    std::printf("60 Hz stream: max overshoot %.3f, max tick step %.1f (largest frame change %d; "
                "a zero-order hold steps by it)\n",
                overshoot, static_cast<double>(step), frame_change);

    // The trace, for the docs' plot (docs/runtime.md, "Force streaming").
    if (FILE* csv = std::fopen(FEEL_BINARY_DIR "/force_stream_60hz.csv", "w")) {
        std::fprintf(csv, "tick,sample,motor_x\n");
        for (size_t n = 0; n < a.motor_x.size(); ++n)
            std::fprintf(csv, "%zu,%d,%.3f\n", n, a.latest[n], static_cast<double>(a.motor_x[n]));
        std::fclose(csv);
    }
}

}  // namespace
}  // namespace feel::runtime::test
