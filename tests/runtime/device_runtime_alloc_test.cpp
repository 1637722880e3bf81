// The assembled device runtime never allocates once it runs (issue 5, §4): a hooked global
// allocator counts every allocation of the process while
//   1. the pipeline is ticked by hand, 3000 ticks of a busy mix (the joystick's slots full
//      of waves, conditions and dynamics; reflexes on scripted button presses; the hand
//      letting go and grabbing again; IDF on), while every kind of command streams in
//      through the command queue (force-profile samples in chunks, creates and destroys,
//      updates, starts and stops, gains, pauses, resets of the actuators, IDF and safety
//      settings, report rates, status and pool queries, reflex assignments) and the host
//      drains the acks, state reports and dynamics' reports;
//   2. the DeviceRuntime runs the same on its real-time thread for 300 ms while this thread
//      sends and polls.
// The count must be zero. Counting opens only after start-up (building the runtime and the
// loop thread allocate, by design) and closes before anything is torn down; inside the
// window the test thread only builds commands (plain data), pushes, pops, sleeps and counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <span>
#include <thread>

#include "../../bench/busy_mix.hpp"
#include "feel/runtime/device_runtime.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/input_schedule.hpp"
#include "support/counting_allocator.hpp"

namespace feel::runtime {
namespace {

const sim::DeviceProfile& joystick() { return *sim::find_device_profile("joystick"); }

// Effects of the busy mix the runtime is loaded with; the joystick's other slots are
// left for the stream's creates and the reflexes.
constexpr int kMixEffects = 26;

// What the host saw, counted without allocating.
struct Tally {
    int64_t acks = 0;
    int64_t refused = 0;
    int64_t states = 0;
    int64_t dynamics = 0;
    int64_t playing = 0;         // effects playing, summed over the state reports
    EffectId created{};          // the effect of the last successful create
    uint32_t create_sequence = 0;
    uint32_t last_error_sequence = 0;
    CommandKind last_error_kind = CommandKind::keep_alive;

    void take(const Report& r) {
        switch (r.kind) {
            case ReportKind::ack:
                ++acks;
                if (!r.ack.error.ok()) {
                    ++refused;
                    last_error_sequence = r.ack.sequence;
                    last_error_kind = r.ack.command;
                }
                if (r.ack.sequence == create_sequence && r.ack.error.ok()) created = r.ack.effect;
                break;
            case ReportKind::state:
                ++states;
                playing += r.state.playing_effects;
                break;
            case ReportKind::dynamic: ++dynamics; break;
        }
    }
};

// The host's busy stream: on step n, one or two commands of every kind in turn. `mix` holds
// the resident busy-mix effects; `profile` the samples of the force profiles it creates.
class CommandStream {
public:
    CommandStream(HostLink& host, const EffectId* mix, std::span<const int16_t> profile)
        : host_(host), mix_(mix), profile_(profile) {}

    void step(int64_t n, Tally& tally) {
        // Steps 3 and 4 of a cycle stop and restart the same effect.
        const EffectId target = mix_[(n / 20) % kMixEffects];
        switch (n % 20) {
            case 0: (void)host_.keep_alive(); break;
            case 1: (void)host_.set_gain(static_cast<int32_t>(6000 + n % 4000)); break;
            case 2: {
                EffectParams p = bench::busy_mix_effect(static_cast<int>((n / 20) % kMixEffects));
                p.gain = static_cast<int32_t>(5000 + n % 5000);
                p.direction.value[0] = static_cast<int32_t>((n * 97) % 36000);
                (void)host_.update(target, p, effect_field::kGain, n % 40 == 2);
                break;
            }
            case 3: (void)host_.stop_effect(target); break;
            case 4: (void)host_.start_effect(target, n % 3 == 0 ? kInfiniteIterations : kEffectIterations); break;
            case 5: (void)host_.status(target); break;
            case 6: (void)host_.query_pool(); break;
            case 7: {
                // A force profile: its samples cross in chunks ahead of the create.
                EffectParams p;
                p.type = EffectType::force_profile;
                p.axis_count = 1;
                p.custom = {1, 2000, static_cast<int32_t>(profile_.size())};
                p.trigger = {TriggerKind::button, 3};
                if (const auto seq = host_.create(p, profile_)) tally.create_sequence = *seq;
                break;
            }
            case 8:
                if (tally.created.valid()) (void)host_.start_effect(tally.created);
                break;
            case 9: (void)host_.set_idf(IdfSettings{.periodic = n % 40 == 9, .impulse = true}); break;
            case 10: (void)host_.control(n % 40 == 10 ? DeviceControl::pause : DeviceControl::resume); break;
            case 11: (void)host_.control(DeviceControl::resume); break;
            case 12: (void)host_.control(n % 40 == 12 ? DeviceControl::actuators_off : DeviceControl::actuators_on); break;
            case 13: (void)host_.control(DeviceControl::actuators_on); break;
            case 14:
                if (tally.created.valid()) (void)host_.remove_reflex(tally.created);
                break;
            case 15:
                if (tally.created.valid()) (void)host_.assign_reflex(tally.created);
                break;
            case 16: (void)host_.set_report_rate(n % 40 == 16 ? 500 : 1000); break;
            case 17:
                if (n % 200 == 17) (void)host_.configure_safety(safety_);
                break;
            case 18:
                if (tally.created.valid()) {
                    (void)host_.destroy(tally.created);
                    tally.created = EffectId{};
                }
                break;
            case 19:
                // Now and then everything stops, and the host starts it all again.
                if (n % 1000 == 19) {
                    (void)host_.control(DeviceControl::stop_all);
                    for (int i = 0; i < kMixEffects; ++i) (void)host_.start_effect(mix_[i]);
                }
                break;
        }
    }
    void set_safety(const SafetyConfig& c) { safety_ = c; }

private:
    HostLink& host_;
    const EffectId* mix_;
    std::span<const int16_t> profile_;
    SafetyConfig safety_{};
};

RuntimeConfig busy_config() {
    RuntimeConfig c = runtime_config_for(joystick());
    c.report_rate_hz = 1000;
    c.idf.settings = {.periodic = true, .impulse = true};
    c.safety.fade_in_us = 50'000;
    return c;
}

sim::InputSchedule busy_script() {
    sim::InputSchedule s(joystick());
    // Buttons 1, 2 and 3 in turn, held 9 ms, every 37 ms; the hand away 120 ms in 700.
    for (int64_t t = 100'000; t < 4'000'000; t += 37'000) {
        const auto button = static_cast<int32_t>(1 + t / 37'000 % 3);
        s.press(t, button).release(t + 9'000, button);
    }
    for (int64_t t = 500'000; t < 4'000'000; t += 700'000) s.let_go(t).grab(t + 120'000);
    return s;
}

// Loads the mix and two reflexes through the queue; returns false (with a failure) if
// anything is refused. Uses `tick` to let the device apply the commands.
template <typename Tick>
bool load(HostLink& host, EffectId* mix, Tick&& tick) {
    Report r;
    for (int i = 0; i < kMixEffects; ++i) {
        const EffectParams p = bench::busy_mix_effect(i);
        const auto data = p.type == EffectType::force_profile ? std::span<const int16_t>(bench::kBusyMixSamples)
                                                              : std::span<const int16_t>();
        const auto seq = host.create(p, data);
        if (!seq) return false;
        bool acked = false;
        for (int k = 0; k < 5000 && !acked; ++k) {
            tick();
            while (host.poll(r)) {
                if (r.kind != ReportKind::ack || r.ack.sequence != *seq) continue;
                EXPECT_TRUE(r.ack.error.ok()) << i << ": " << r.ack.error.message();
                if (!r.ack.error.ok()) return false;
                mix[i] = r.ack.effect;
                acked = true;
            }
        }
        if (!acked || !host.start_effect(mix[i])) return false;
    }
    // Two reflexes: a jolt on button 1 that repeats while held, a sine burst on button 2.
    EffectParams jolt;
    jolt.type = EffectType::constant;
    jolt.axis_count = 2;
    jolt.axes[1] = Axis::y;
    jolt.direction = {DirectionKind::polar, {4500, 0, 0}};
    jolt.duration_us = 20'000;
    jolt.constant.magnitude = 4000;
    jolt.trigger = {TriggerKind::button, 1};
    jolt.trigger_repeat_interval_us = 3'000;
    EffectParams burst = bench::mixed_wave(4);
    burst.duration_us = 30'000;
    burst.iterations = 1;
    burst.trigger = {TriggerKind::button, 2};
    return host.create(jolt).has_value() && host.create(burst).has_value();
}

TEST(DeviceRuntimeAllocation, TheCounterSeesAllocationsOfAnyThread) {
    counting = true;
    std::thread other([] {
        auto* probe = new int(7);
        delete probe;
    });
    other.join();
    counting = false;
    EXPECT_GE(allocations.exchange(0), 2);
}

TEST(DeviceRuntimeAllocation, PipelineTicksNeverAllocateUnderACommandStream) {
    const RuntimeConfig config = busy_config();
    RuntimePipeline pipeline(config, std::make_unique<SimBackend>(joystick(), sim::Grip::firm,
                                                                  sim::TargetMotion::parse("circle:5000:1", 4, 2),
                                                                  busy_script()));
    HostLink host(pipeline.commands(), pipeline.reports());
    EffectId mix[kMixEffects];
    int64_t n = 0;
    ASSERT_TRUE(load(host, mix, [&] { pipeline.tick(n++); }));
    const std::vector<int16_t> profile(300, 1200);  // 3 chunks
    CommandStream stream(host, mix, profile);
    stream.set_safety(config.safety);
    Tally tally;
    Report r;
    for (int i = 0; i < 100; ++i) {  // settle: every queue and path warm
        stream.step(i, tally);
        pipeline.tick(n++);
        while (host.poll(r)) tally.take(r);
    }
    const RuntimeCounters before = pipeline.counters();
    tally = Tally{};

    allocations = 0;
    counting = true;
    for (int i = 0; i < 3000; ++i) {
        stream.step(100 + i, tally);
        pipeline.tick(n++);
        while (host.poll(r)) tally.take(r);
    }
    counting = false;

    EXPECT_EQ(allocations.load(), 0);
    const RuntimeCounters after = pipeline.counters();
    std::printf("3000 ticks: %lld acks, %lld state reports, %lld dynamics' reports, %.1f effects playing on average, "
                "%lld reflex starts\n",
                static_cast<long long>(tally.acks), static_cast<long long>(tally.states),
                static_cast<long long>(tally.dynamics),
                static_cast<double>(tally.playing) / static_cast<double>(std::max<int64_t>(tally.states, 1)),
                static_cast<long long>(after.reflex_starts - before.reflex_starts));
    EXPECT_EQ(after.ticks - before.ticks, 3000);
    EXPECT_GT(tally.acks, 2500);  // every kind of command went through
    EXPECT_EQ(tally.refused, 0) << "command " << tally.last_error_sequence << " ("
                                << command_kind_name(tally.last_error_kind) << ") was refused";
    EXPECT_GT(tally.states, 1500);
    EXPECT_GT(tally.dynamics, 0);
    // Busy: on average most of the mix plays (a few dynamics end by themselves).
    EXPECT_GT(tally.playing / tally.states, kMixEffects / 2);
    EXPECT_GT(after.reflex_starts, before.reflex_starts);
    EXPECT_EQ(after.dropped_state_reports, 0);
}

TEST(DeviceRuntimeAllocation, TheRunningRuntimeNeverAllocates) {
    const RuntimeConfig config = busy_config();
    DeviceRuntimeOptions options;
    options.lock_memory = false;
    DeviceRuntime rt(config, std::make_unique<SimBackend>(joystick(), sim::Grip::firm,
                                                          sim::TargetMotion::parse("circle:5000:1", 4, 2), busy_script()),
                     options);
    rt.start();
    EffectId mix[kMixEffects];
    ASSERT_TRUE(load(rt, mix, [] { std::this_thread::sleep_for(std::chrono::milliseconds(1)); }));
    const std::vector<int16_t> profile(300, -800);
    CommandStream stream(rt, mix, profile);
    stream.set_safety(config.safety);
    Tally tally;
    Report r;
    for (int i = 0; i < 40; ++i) {
        stream.step(i, tally);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        while (rt.poll(r)) tally.take(r);
    }
    const int64_t ticks_before = rt.stats().pipeline.ticks;
    tally = Tally{};

    allocations = 0;
    counting = true;
    const auto window_end = std::chrono::steady_clock::now() + std::chrono::milliseconds(300);
    for (int64_t i = 40; std::chrono::steady_clock::now() < window_end; ++i) {
        stream.step(i, tally);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
        while (rt.poll(r)) tally.take(r);
    }
    counting = false;
    const DeviceRuntimeStats s = rt.stats();
    rt.stop();

    EXPECT_EQ(allocations.load(), 0) << "over " << s.pipeline.ticks - ticks_before << " ticks";
    EXPECT_GT(s.pipeline.ticks - ticks_before, 100);  // the window saw real work
    EXPECT_GT(tally.acks, 50);
    EXPECT_GT(tally.states, 50);
    EXPECT_GT(tally.playing / std::max<int64_t>(tally.states, 1), kMixEffects / 2);
    // Refusals are possible here (the host acts on acks that come back when the thread
    // pleases); the deterministic test above checks that the stream is valid.
}

}  // namespace
}  // namespace feel::runtime
