// PidDevice's reflexes (Set Effect's Trigger Button and Trigger Repeat Interval, or the
// host's run of a trigger the device cannot name) and its custom forces (Set Custom Force
// and Custom Force Data), against feel's simulated device in lockstep (pid_lockstep.hpp):
// every tick's motor force is recorded, so when an effect starts is read to the tick.
//
// Truth.
//  - A reflex (§1.2.c): the effect starts when its button is pressed and, with a repeat
//    interval R, again every R while held. Run by the device, it starts on the tick of the
//    press (the device's reflex, no host in the loop). Run by the host, the press is seen in
//    the first Input report at or after it and the start reaches the device one tick later
//    (the rig's link): within one report period T of the press; each repeat k lands in
//    [s_0 + k·R, s_0 + k·R + T − 1 tick] (the host fires at the first report at or after
//    the due time).
//  - A custom force (§4.3.a): each sample is played for one sample period, channel i on the
//    effect's axis i, so the force at a tick τ into the play is sample ⌊τ / period⌋.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

#include "../support/valid_effects.hpp"
#include "emulation/emulated_loop.hpp"
#include "feel/host/pid_device.hpp"
#include "pid_lockstep.hpp"

namespace feel::host {
namespace {

// A short push on x alone, a reflex on `trigger` repeating every `repeat_us`.
EffectParams jolt(Trigger trigger, int64_t repeat_us) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = 5'000;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.direction.kind = DirectionKind::none;
    p.constant.magnitude = 6000;
    p.trigger = trigger;
    p.trigger_repeat_interval_us = repeat_us;
    return p;
}

struct Rig {
    Lockstep lockstep;
    std::optional<PidDevice> dev;
    Rig(int32_t report_rate_hz) : lockstep("iforce2", "hold:0", report_rate_hz) {
        lockstep.background(true);
        Result<PidDevice> opened = PidDevice::attach(lockstep.host_end(), "sim:iforce2", OpenOptions{},
                                                     [this] { return lockstep.now_us(); });
        lockstep.background(false);
        if (!opened) {
            ADD_FAILURE() << opened.status().message;
            return;
        }
        dev.emplace(std::move(opened.value()));
    }
    ~Rig() {
        lockstep.background(true);
        if (dev) dev->close();
        lockstep.background(false);
    }
    // A host call that waits for the device (Create New Effect's Block Load): steps meanwhile.
    template <class F>
    auto with_device(F&& f) {
        lockstep.background(true);
        auto r = f();
        lockstep.background(false);
        return r;
    }
    runtime::SimBackend& backend() { return static_cast<runtime::SimBackend&>(lockstep.pipeline().backend()); }
    float force_x() { return lockstep.pipeline().motor_force()[0]; }
};

// The ticks (from `from`) on which the force on x went from rest to pushing (at rest before
// the first: the callers check that nothing played before the press).
std::vector<int64_t> starts(const std::vector<float>& force_x, int64_t from) {
    std::vector<int64_t> out;
    for (std::size_t m = 0; m < force_x.size(); ++m) {
        const bool before = m > 0 && std::abs(force_x[m - 1]) > 100.0f;
        if (std::abs(force_x[m]) > 100.0f && !before) out.push_back(from + static_cast<int64_t>(m));
    }
    return out;
}

// Holds `press` (buttons or hats) from tick `press_tick` for `held` ticks; the force on x
// per tick from press_tick on.
std::vector<float> press_and_hold(Rig& rig, bool hat, int64_t press_tick, int held) {
    while (rig.lockstep.tick() < press_tick) rig.lockstep.step();
    EXPECT_TRUE(hat ? rig.backend().set_hats(0b1) : rig.backend().set_buttons(0b1));
    std::vector<float> force;
    for (int i = 0; i < held; ++i) {
        rig.lockstep.step();
        force.push_back(rig.force_x());
    }
    EXPECT_TRUE(hat ? rig.backend().set_hats(0) : rig.backend().set_buttons(0));
    return force;
}

constexpr int64_t kRepeatTicks = 20;  // R = 20 ms

TEST(PidReflex, TheDeviceRunsAButtonReflexFromSetEffectsTriggerButton) {
    Rig rig(1000);
    ASSERT_TRUE(rig.dev);
    Result<uint16_t> block = rig.with_device([&] {
        return rig.dev->create_effect(jolt({TriggerKind::button, 1}, kRepeatTicks * kTickUs));
    });
    ASSERT_TRUE(block) << block.status().message;
    EXPECT_FALSE(rig.dev->trigger_emulated(*block));  // feel's Set Effect has a Trigger Button
    const int64_t press = rig.lockstep.tick() + 50;
    // Nothing plays before the press.
    for (int i = 0; i < 40; ++i) {
        rig.lockstep.step();
        EXPECT_EQ(rig.force_x(), 0.0f);
    }
    const std::vector<float> force = press_and_hold(rig, false, press, 70);
    const std::vector<int64_t> s = starts(force, 0);
    // Pressed at tick 0 of the recording (sensed by the tick that records it): the device
    // starts it at once, then every R while held (70 ticks: starts at 0, 20, 40, 60).
    ASSERT_EQ(s.size(), 4u) << "starts at " << ::testing::PrintToString(s);
    for (std::size_t k = 0; k < s.size(); ++k) EXPECT_LE(std::abs(s[k] - static_cast<int64_t>(k) * kRepeatTicks), 1) << k;
}

TEST(PidReflex, TheHostRunsAHatReflexWithinAReportPeriod) {
    for (const int32_t rate : {1000, 250}) {
        SCOPED_TRACE("report rate " + std::to_string(rate) + " Hz");
        const int64_t period = 1000 / rate;  // T, ticks
        Rig rig(rate);
        ASSERT_TRUE(rig.dev);
        Result<uint16_t> block = rig.with_device([&] {
            return rig.dev->create_effect(jolt({TriggerKind::hat, 1}, kRepeatTicks * kTickUs));
        });
        ASSERT_TRUE(block) << block.status().message;
        // PID's Trigger Button names buttons only: the host runs a hat trigger, and the
        // block's status says so (the device plays it; the host starts it).
        EXPECT_TRUE(rig.dev->trigger_emulated(*block));
        Result<EffectStatusInfo> status = rig.dev->status(*block);
        ASSERT_TRUE(status) << status.status().message;
        EXPECT_EQ(status->state, runtime::ReportedEffectState::emulated);
        EXPECT_TRUE(status->emulated);
        const int64_t press = rig.lockstep.tick() + 50;
        const std::vector<float> force = press_and_hold(rig, true, press, 70);
        const std::vector<int64_t> s = starts(force, 0);
        ASSERT_GE(s.size(), 3u) << "starts at " << ::testing::PrintToString(s);
        EXPECT_GE(s[0], 1);  // the host's start crosses the link: a tick at least
        EXPECT_LE(s[0], period + 1);
        for (std::size_t k = 1; k < s.size(); ++k) {
            const int64_t due = s[0] + static_cast<int64_t>(k) * kRepeatTicks;
            EXPECT_GE(s[k], due) << k;
            EXPECT_LE(s[k], due + period - 1 + 1) << k;  // the next report, and at most a tick of rounding
        }
        // Released: no more starts.
        for (int i = 0; i < 60; ++i) {
            rig.lockstep.step();
            EXPECT_EQ(rig.force_x(), 0.0f) << "tick " << i << " after the release";
        }
    }
}

TEST(PidReflex, AHostRenderedEffectPlaysOnItsButton) {
    Rig rig(1000);
    ASSERT_TRUE(rig.dev);
    EffectParams recoil = test::valid_effect(EffectType::dynamic_recoil);
    recoil.trigger = {TriggerKind::button, 2};
    Result<uint16_t> handle = rig.with_device([&] { return rig.dev->create_effect(recoil); });
    ASSERT_TRUE(handle) << handle.status().message;
    EXPECT_TRUE(rig.dev->emulated(*handle));
    EXPECT_TRUE(rig.dev->trigger_emulated(*handle));
    for (int i = 0; i < 20; ++i) rig.lockstep.step();
    EXPECT_EQ(rig.dev->status(*handle)->state, runtime::ReportedEffectState::stopped);
    ASSERT_TRUE(rig.backend().set_buttons(0b10));
    rig.lockstep.step();  // the press, in this tick's report
    rig.lockstep.step();
    EXPECT_EQ(rig.dev->status(*handle)->state, runtime::ReportedEffectState::emulated);
}

// --- custom force -----------------------------------------------------------------------

TEST(PidCustomForce, FeelsDevicePlaysTheSamplesEachForItsPeriod) {
    Rig rig(1000);
    ASSERT_TRUE(rig.dev);
    ASSERT_TRUE(rig.dev->capabilities().supports(EffectType::force_profile));
    // Two channels, x and y, 30 frames of 2 ms: more than one Custom Force Data report.
    constexpr int kFrames = 30;
    constexpr int64_t kPeriodTicks = 2;
    std::vector<int16_t> samples;
    for (int f = 0; f < kFrames; ++f) {
        samples.push_back(static_cast<int16_t>(300 * (f + 1)));
        samples.push_back(static_cast<int16_t>(-200 * (f + 1)));
    }
    const EffectParams p = test::profile_on_xy(kFrames, kPeriodTicks * kTickUs);
    Result<uint16_t> block = rig.with_device([&] { return rig.dev->create_effect(p, samples); });
    ASSERT_TRUE(block) << block.status().message;
    EXPECT_FALSE(rig.dev->emulated(*block));  // the device plays it
    for (int i = 0; i < 10; ++i) rig.lockstep.step();
    ASSERT_TRUE(rig.dev->start(*block).ok());
    std::vector<float> fx, fy;
    for (int i = 0; i < kFrames * kPeriodTicks + 10; ++i) {
        rig.lockstep.step();
        fx.push_back(rig.lockstep.pipeline().motor_force()[0]);
        fy.push_back(rig.lockstep.pipeline().motor_force()[1]);
    }
    // The first tick that pushes is the play's start (the start crosses the link).
    std::size_t s = 0;
    while (s < fx.size() && fx[s] == 0.0f) ++s;
    ASSERT_LT(s, 5u) << "the profile did not start";
    for (int64_t tau = 0; tau < kFrames * kPeriodTicks; ++tau) {
        const auto frame = static_cast<std::size_t>(tau / kPeriodTicks);
        const auto m = s + static_cast<std::size_t>(tau);
        EXPECT_NEAR(fx[m], samples[2 * frame], 1.0) << "tick " << tau;
        EXPECT_NEAR(fy[m], samples[2 * frame + 1], 1.0) << "tick " << tau;
    }
    // Then it has ended.
    EXPECT_EQ(fx[s + kFrames * kPeriodTicks + 2], 0.0f);
}

TEST(PidCustomForce, SamplesOutOfRangeAreRefusedNamingTheField) {
    Rig rig(1000);
    ASSERT_TRUE(rig.dev);
    EffectParams p;
    p.type = EffectType::force_profile;
    p.duration_us = 10'000;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.custom = {1, 1'000, 2};
    const std::vector<int16_t> samples = {20000, 0};
    Result<uint16_t> refused = rig.with_device([&] { return rig.dev->create_effect(p, samples); });
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(refused.status().message.find("custom.samples[0]"), std::string::npos) << refused.status().message;
}

// --- a standard device without custom force: the host renders the profile ------------

// Open FFBoard's descriptor (tests/protocol/pid_descriptors/) behind a scripted device that
// answers as a PID device does: PID Pool, and PID Block Load after each Create New Effect
// (blocks 1, 2, ...). Its Set Constant Force (ID 5) levels are kept per block, and every
// output report in order. `without_trigger_button` blanks Set Effect's Trigger Button
// usage (its one Usage 0x53 item, byte 327, made Usage 0x00: the field stays, unnamed), a
// device that cannot run reflexes.
class FakeFfboard {
public:
    explicit FakeFfboard(bool without_trigger_button = false) {
        transport::ConnectionPair pair = transport::in_process_pair("ffboard");
        host_ = std::move(pair.host);
        device_ = std::move(pair.device);
        std::ifstream in(std::string(FEEL_SOURCE_DIR) + "/tests/protocol/pid_descriptors/openffboard_2axis.bin",
                         std::ios::binary);
        descriptor_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        if (without_trigger_button) {
            EXPECT_EQ(descriptor_.at(327), 0x09);
            EXPECT_EQ(descriptor_.at(328), 0x53);
            descriptor_.at(328) = 0x00;
        }
        thread_ = std::thread([this] { run(); });
    }
    ~FakeFfboard() {
        device_->close();
        thread_.join();
    }
    std::unique_ptr<transport::Connection> host_end() { return std::move(host_); }
    // Its Input report (ID 1: 64 one-bit buttons, then X..Rz, Slider, Dial, 16 bits each).
    void push_input(int16_t x, int16_t y, uint8_t buttons_1_to_8 = 0) {
        std::vector<uint8_t> r(25, 0);
        r[0] = 1;
        r[1] = buttons_1_to_8;
        r[9] = static_cast<uint8_t>(x & 0xFF);
        r[10] = static_cast<uint8_t>((x >> 8) & 0xFF);
        r[11] = static_cast<uint8_t>(y & 0xFF);
        r[12] = static_cast<uint8_t>((y >> 8) & 0xFF);
        device_->send(Frame{FrameKind::input_report, r});
    }
    std::map<int, int> levels() {
        std::lock_guard lock(mu_);
        return levels_;
    }
    std::vector<std::vector<uint8_t>> outputs() {
        std::lock_guard lock(mu_);
        return outputs_;
    }

private:
    void run() {
        try {
            int next_block = 1;
            for (;;) {
                std::optional<Frame> f = device_->receive(std::chrono::milliseconds(20));
                if (!f) continue;
                if (f->kind == FrameKind::get_descriptor) device_->send(Frame{FrameKind::descriptor_reply, descriptor_});
                if (f->kind == FrameKind::get_feature && f->payload.size() == 1) {
                    if (f->payload[0] == 19) device_->send(Frame{FrameKind::feature_reply, {19, 0, 0x10, 40, 0b01}});
                    if (f->payload[0] == 18) {
                        // Block Load: block, status 1 (Block Load Success), RAM Pool Available.
                        device_->send(Frame{FrameKind::feature_reply,
                                            {18, static_cast<uint8_t>(next_block++), 1, 0xFF, 0x0F}});
                    }
                }
                if (f->kind == FrameKind::output_report) {
                    std::lock_guard lock(mu_);
                    outputs_.push_back(f->payload);
                    if (f->payload.size() == 4 && f->payload[0] == 5)
                        levels_[f->payload[1]] = static_cast<int16_t>(f->payload[2] | f->payload[3] << 8);
                }
            }
        } catch (const std::exception&) {
        }
    }
    std::unique_ptr<transport::Connection> host_, device_;
    std::vector<uint8_t> descriptor_;
    std::thread thread_;
    std::mutex mu_;
    std::map<int, int> levels_;
    std::vector<std::vector<uint8_t>> outputs_;
};

// A stall render (the device silent: before the report period is known, for 10 ms of the
// host's time) renders on the last positions read, and its observer update carries them.
// (It carried zeros once: the VM's emulation log showed x=0 in the middle of a sweep.)
TEST(PidEmulationObserver, AStallRenderCarriesThePositionsItRenderedOn) {
    FakeFfboard board;
    std::atomic<int64_t> now_us{0};
    Result<PidDevice> dev = PidDevice::attach(board.host_end(), "ffboard", OpenOptions{}, [&] { return now_us.load(); });
    ASSERT_TRUE(dev) << dev.status().message;
    std::mutex mu;
    std::vector<PidEmulationUpdate> updates;
    dev->observe_emulation([&](const PidEmulationUpdate& u) {
        std::lock_guard lock(mu);
        updates.push_back(u);
    });
    Result<uint16_t> wall = dev->create_effect(emulation::wall_on_x(2000));
    ASSERT_TRUE(wall) << wall.status().message;
    ASSERT_TRUE(dev->emulated(*wall));
    ASSERT_TRUE(dev->start(*wall).ok());
    // Reports (the same) until one is rendered, then silence.
    auto until = std::chrono::steady_clock::now() + 10s;
    for (int64_t t = 1'000; dev->emulation_stats().updates == 0 && std::chrono::steady_clock::now() < until;
         t += 2'000) {
        now_us = t;
        board.push_input(12000, -3000);
        std::this_thread::sleep_for(2ms);
    }
    ASSERT_GT(dev->emulation_stats().updates, 0) << "no report was rendered";
    until = std::chrono::steady_clock::now() + 10s;
    auto stalled = [&]() -> std::optional<PidEmulationUpdate> {
        std::lock_guard lock(mu);
        for (const PidEmulationUpdate& u : updates)
            if (u.stalled) return u;
        return std::nullopt;
    };
    while (!stalled() && std::chrono::steady_clock::now() < until) std::this_thread::sleep_for(5ms);
    const std::optional<PidEmulationUpdate> stall = stalled();
    ASSERT_TRUE(stall.has_value()) << "no stall render within 10 s of silence";
    std::optional<PidEmulationUpdate> read;
    {
        std::lock_guard lock(mu);
        for (const PidEmulationUpdate& u : updates)
            if (!u.stalled) read = u;
    }
    ASSERT_TRUE(read.has_value()) << "the report was not rendered";
    EXPECT_NE(read->position[0], 0.0f);  // the report's x, normalized: 12000 of 32767 one way
    EXPECT_NE(read->position[1], 0.0f);
    for (int a = 0; a < kMaxAxes; ++a) EXPECT_EQ(stall->position[a], read->position[a]) << "axis " << a;
    dev->close();
}

TEST(PidReflex, WithoutTriggerButtonTheHostRunsAButtonReflex) {
    FakeFfboard board(true);
    std::atomic<int64_t> now_us{0};
    Result<PidDevice> dev = PidDevice::attach(board.host_end(), "ffboard", OpenOptions{}, [&] { return now_us.load(); });
    ASSERT_TRUE(dev) << dev.status().message;
    EXPECT_FALSE(protocol::pid::device_runs_trigger(dev->layout(), Trigger{TriggerKind::button, 3}));
    constexpr int64_t kRepeatUs = 20'000;
    Result<uint16_t> block = dev->create_effect(jolt({TriggerKind::button, 3}, kRepeatUs));
    ASSERT_TRUE(block) << block.status().message;
    EXPECT_TRUE(dev->trigger_emulated(*block));
    const uint8_t operation_id = dev->layout().report(protocol::pid::PidReport::effect_operation).id;
    // Effect Operation Start (its array's first usage, Op Effect Start) of our block, per report.
    auto started = [&] {
        int n = 0;
        for (const std::vector<uint8_t>& r : board.outputs())
            n += r.size() >= 3 && r[0] == operation_id && r[1] == *block && r[2] == 1 ? 1 : 0;
        return n;
    };
    // A report every T = 3 ms; button 3 held from the report at 10 ms to the one at 67 ms.
    constexpr int64_t kReportUs = 3'000;
    std::vector<int64_t> starts_at;
    for (int64_t t = 1'000; t <= 100'000; t += kReportUs) {
        now_us = t;
        const bool held = t >= 10'000 && t <= 67'000;
        const int before = started();
        board.push_input(0, 0, held ? 0b100 : 0);
        // The host answers a press by the report that shows it: wait for its Start, or
        // long enough to be sure none comes.
        for (int i = 0; i < 40 && started() == before; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        for (int n = started(); n > before; --n) starts_at.push_back(t);
    }
    // Starts at the press (10 ms), then due at 30 and 50 ms, each fired by the first report
    // at or after its due time (31 and 52 ms: within T), none after the release.
    ASSERT_EQ(starts_at.size(), 3u) << ::testing::PrintToString(starts_at);
    EXPECT_EQ(starts_at[0], 10'000);
    for (std::size_t k = 1; k < starts_at.size(); ++k) {
        const int64_t due = starts_at[0] + static_cast<int64_t>(k) * kRepeatUs;
        EXPECT_GE(starts_at[k], due) << k;
        EXPECT_LT(starts_at[k], due + kReportUs) << k;
    }
    dev->close();
}

TEST(PidCustomForce, ADeviceWithoutItGetsTheProfileRenderedByTheHost) {
    FakeFfboard board;
    std::atomic<int64_t> now_us{0};
    Result<PidDevice> dev = PidDevice::attach(board.host_end(), "ffboard", OpenOptions{}, [&] { return now_us.load(); });
    ASSERT_TRUE(dev) << dev.status().message;
    ASSERT_FALSE(dev->capabilities().supports(EffectType::force_profile));
    ASSERT_NE(dev->capabilities().emulated_types & effect_type_bit(EffectType::force_profile), 0u)
        << dev->capabilities().emulation_problem;
    constexpr int kFrames = 4;
    constexpr int64_t kPeriodUs = 10'000;
    const std::vector<int16_t> samples = {4000, -2000, -7000, 1000, 10000, 0, -3000, 3000};
    const EffectParams p = test::profile_on_xy(kFrames, kPeriodUs);
    Result<uint16_t> handle = dev->create_effect(p, samples);
    ASSERT_TRUE(handle) << handle.status().message;
    EXPECT_TRUE(dev->emulated(*handle));
    const PidEmulationStats link = dev->emulation_stats();
    ASSERT_EQ(link.link_blocks.size(), 2u);  // x and y: the axes both reported and in Axes Enable
    ASSERT_TRUE(dev->start(*handle).ok());
    // One report every 2 ms of host time; the host renders each and streams the level. The
    // play's time starts at the update where the host's engine starts it (the first to push:
    // within two updates of start()); from there the level is sample ⌊τ / period⌋ on its axis,
    // scaled as a level onto Magnitude's -32767..32767 (PID: 10000 is the logical maximum).
    std::vector<std::pair<int64_t, std::map<int, int>>> sent;
    for (int64_t t = 1'000; t < 1'000 + kFrames * kPeriodUs + 4'000; t += 2'000) {
        now_us = t;
        const int64_t before = dev->emulation_stats().updates;
        board.push_input(0, 0);
        for (int i = 0; i < 500 && dev->emulation_stats().updates == before; ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        std::this_thread::sleep_for(std::chrono::milliseconds(5));  // the level's trip
        sent.emplace_back(t, board.levels());
    }
    const int x_block = link.link_blocks[0], y_block = link.link_blocks[1];
    std::size_t first = 0;
    while (first < sent.size() && sent[first].second[x_block] == 0) ++first;
    ASSERT_LE(first, 1u) << "the profile did not start within two updates";
    const int64_t t0 = sent[first].first;
    for (std::size_t k = first; k < sent.size(); ++k) {
        const int64_t tau = sent[k].first - t0;
        if (tau >= kFrames * kPeriodUs) break;
        const auto frame = static_cast<std::size_t>(tau / kPeriodUs);
        const double x = std::round(samples[2 * frame] * 32767.0 / 10000.0);
        const double y = std::round(samples[2 * frame + 1] * 32767.0 / 10000.0);
        // A unit of force is 3.3 counts of Magnitude: the host rounds its force to a unit.
        EXPECT_NEAR(sent[k].second[x_block], x, 4.0) << "tau " << tau << " us";
        EXPECT_NEAR(sent[k].second[y_block], y, 4.0) << "tau " << tau << " us";
    }
    dev->close();
}

}  // namespace
}  // namespace feel::host
