// The device runtime's per-tick pipeline, ticked by hand (no thread): every command through
// the command queue with its ack through the report queue, and the assembled behaviour the
// primer asks of the local processor (§2.2): a full device refuses without disturbing what
// plays, reflexes fire in the tick of the press, the safety features show in the host's
// reports, IDF steadies the reported position, reports come at the configured rate, and the
// dynamics' reports reach the host.
//
// Truth comes from outside the code under test: the cost table of the parameter memory
// (docs/runtime.md, the I-FORCE block sizes), the effects' definitions (a constant of
// magnitude m pushes m; gains multiply), the input script (sim::InputSchedule's own record
// of when the hand and buttons act), the safety ramp (t − t_grab)/fade_in, the arithmetic
// of a report schedule, and a second, undisturbed run of the same device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../bench/busy_mix.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "runtime_rig.hpp"
#include "runtime_tick.hpp"

namespace feel::runtime::test {
namespace {

using test_support::kTickUs;

EffectParams constant_x(int32_t magnitude, int64_t duration_us = kInfiniteUs) {
    EffectParams p;
    p.type = EffectType::constant;
    p.duration_us = duration_us;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.constant.magnitude = magnitude;  // no direction: pushes along +x with its own sign
    return p;
}

EffectParams profile_x(int32_t samples, int64_t sample_period_us) {
    EffectParams p;
    p.type = EffectType::force_profile;
    p.duration_us = kInfiniteUs;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.custom = {1, sample_period_us, samples};
    return p;
}

std::vector<int16_t> ramp_samples(int n, int step) {
    std::vector<int16_t> s(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i) s[static_cast<size_t>(i)] = static_cast<int16_t>((i * step) % 20001 - 10000);
    return s;
}

// --- every command, through the queues, with its ack ------------------------------------------

TEST(RuntimePipeline, EveryCommandRoundTripsWithItsAck) {
    Rig rig(quiet_config());
    HostLink& host = rig.host();
    const RuntimePipeline& p = rig.pipeline();

    // The pool of an I-FORCE 2.0-class device: 32 slots, 16 KiB, 8192 samples.
    const CommandAck pool = rig.ok(host.query_pool());
    EXPECT_EQ(pool.command, CommandKind::query_pool);
    EXPECT_EQ(pool.pool.total_bytes, 16384);
    EXPECT_EQ(pool.pool.free_bytes, 16384);
    EXPECT_EQ(pool.pool.max_effects, 32);
    EXPECT_EQ(pool.pool.free_effects, 32);

    // create: a constant costs the effect block (14 bytes) and the magnitude block (2).
    const CommandAck created = rig.ok(host.create(constant_x(5000)));
    EXPECT_EQ(created.command, CommandKind::create);
    const EffectId id = created.effect;
    ASSERT_TRUE(id.valid());
    EXPECT_EQ(created.pool.free_bytes, 16384 - (14 + 2));
    EXPECT_EQ(created.pool.free_effects, 31);
    EXPECT_EQ(rig.ok(host.status(id)).status.state, EffectState::stopped);

    // start: it plays in the tick that applies the command.
    const CommandAck started = rig.ok(host.start_effect(id));
    EXPECT_EQ(started.status.starts, 1u);
    EXPECT_EQ(started.t_us, p.counters().t_us);
    EXPECT_FLOAT_EQ(p.motor_force()[0], 5000.0f);
    rig.run(5);
    EXPECT_EQ(rig.ok(host.status(id)).status.state, EffectState::playing);

    // Device gain multiplies.
    rig.ok(host.set_gain(5000));
    EXPECT_FLOAT_EQ(p.motor_force()[0], 2500.0f);

    // A partial update (the effect's gain only), without restart: its clock goes on.
    const int64_t elapsed_before = rig.ok(host.status(id)).status.elapsed_us;
    EffectParams half = constant_x(0);  // only the gain is taken
    half.gain = 5000;
    const CommandAck updated = rig.ok(host.update(id, half, effect_field::kGain));
    EXPECT_FLOAT_EQ(p.motor_force()[0], 1250.0f);
    EXPECT_EQ(updated.status.starts, 1u);
    EXPECT_GT(updated.status.elapsed_us, elapsed_before);
    // With restart: started again.
    EXPECT_EQ(rig.ok(host.update(id, half, effect_field::kGain, true)).status.starts, 2u);

    // Pause freezes the effect's clock and the force; resume lets both go on.
    rig.ok(host.control(DeviceControl::pause));
    EXPECT_EQ(p.motor_force()[0], 0.0f);
    const int64_t paused_at = rig.ok(host.status(id)).status.elapsed_us;
    rig.run(20);
    EXPECT_EQ(rig.ok(host.status(id)).status.elapsed_us, paused_at);
    rig.ok(host.control(DeviceControl::resume));
    EXPECT_FLOAT_EQ(p.motor_force()[0], 1250.0f);
    rig.run(20);
    EXPECT_GT(rig.ok(host.status(id)).status.elapsed_us, paused_at + 15 * kTickUs);

    // Actuators off: no force, the effect plays on; on: the force is back.
    rig.ok(host.control(DeviceControl::actuators_off));
    EXPECT_EQ(p.motor_force()[0], 0.0f);
    const int64_t off_at = rig.ok(host.status(id)).status.elapsed_us;
    rig.run(10);
    EXPECT_EQ(rig.ok(host.status(id)).status.state, EffectState::playing);
    EXPECT_GT(rig.ok(host.status(id)).status.elapsed_us, off_at);
    rig.ok(host.control(DeviceControl::actuators_on));
    EXPECT_FLOAT_EQ(p.motor_force()[0], 1250.0f);

    // Stop: resident, not playing, ended by a command.
    const CommandAck stopped = rig.ok(host.stop_effect(id));
    EXPECT_EQ(stopped.status.state, EffectState::stopped);
    EXPECT_EQ(stopped.status.last_end, PlayEnd::stopped);
    EXPECT_EQ(p.motor_force()[0], 0.0f);

    // Stop all, keep-alive.
    rig.ok(host.start_effect(id));
    EXPECT_NE(p.motor_force()[0], 0.0f);
    rig.ok(host.control(DeviceControl::stop_all));
    EXPECT_EQ(p.motor_force()[0], 0.0f);
    EXPECT_EQ(rig.ok(host.keep_alive()).command, CommandKind::keep_alive);

    // Destroy returns every byte; the handle goes stale.
    EXPECT_EQ(rig.ok(host.destroy(id)).pool.free_bytes, 16384);
    const CommandAck stale = rig.ack(host.status(id));
    EXPECT_EQ(stale.error.code, ErrorCode::invalid_handle);
    EXPECT_EQ(stale.status.state, EffectState::free);
    EXPECT_EQ(rig.ack(host.start_effect(id)).error.code, ErrorCode::invalid_handle);
    EXPECT_EQ(rig.ack(host.destroy(id)).error.code, ErrorCode::invalid_handle);

    // Reset: every effect freed, gain 10000.
    const EffectId a = rig.ok(host.create(constant_x(1000))).effect;
    const EffectId b = rig.ok(host.create(constant_x(2000))).effect;
    rig.ok(host.start_effect(b));
    const CommandAck reset = rig.ok(host.control(DeviceControl::reset));
    EXPECT_EQ(reset.pool.free_bytes, 16384);
    EXPECT_EQ(reset.pool.free_effects, 32);
    EXPECT_EQ(rig.ack(host.status(a)).error.code, ErrorCode::invalid_handle);
    EXPECT_EQ(rig.ack(host.status(b)).error.code, ErrorCode::invalid_handle);
    EXPECT_EQ(p.engine().gain(), 10000);
    EXPECT_EQ(p.resident_effects(), 0);

    // Every ack answers its own command, in order.
    for (size_t i = 1; i < rig.acks.size(); ++i) EXPECT_EQ(rig.acks[i].sequence, rig.acks[i - 1].sequence + 1);
    EXPECT_EQ(p.counters().commands, static_cast<int64_t>(rig.acks.size()));
}

TEST(RuntimePipeline, RefusedCommandsNameTheFieldAndRange) {
    Rig rig(quiet_config());
    HostLink& host = rig.host();
    const EffectId id = rig.ok(host.create(constant_x(5000))).effect;

    const CommandAck gain = rig.ack(host.set_gain(10001));
    EXPECT_EQ(gain.error.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(gain.error.message(), "gain = 10001 is out of range (allowed 0..10000)");

    EXPECT_EQ(rig.ack(host.start_effect(id, 300)).error.message(), "iterations = 300 is out of range (allowed 1..255)");
    EXPECT_EQ(rig.ack(host.set_report_rate(99)).error.message(),
              "report_rate_hz = 99 is out of range (allowed 100..1000)");
    EXPECT_EQ(rig.ack(host.update(id, constant_x(1), 1u << 20)).error.code, ErrorCode::invalid_parameter);

    SafetyConfig bad = quiet_config().safety;
    bad.fade_in_us = -5;
    const CommandAck safety = rig.ack(host.configure_safety(bad));
    EXPECT_EQ(std::string(safety.error.field), "safety.fade_in_us");
    bad = quiet_config().safety;
    bad.axis_count = 3;
    EXPECT_EQ(rig.ack(host.configure_safety(bad)).error.message(),
              "safety.axis_count = 3 is out of range (allowed 2..2)");

    Command control = make_device_control(9000, DeviceControl::reset);
    control.control = static_cast<DeviceControl>(9);
    ASSERT_TRUE(host.send(control));
    const CommandAck c = rig.ack(9000);
    EXPECT_EQ(c.error.message(), "control = 9 is out of range (allowed 0..5)");

    Command unknown = make_keep_alive(9001);
    unknown.kind = static_cast<CommandKind>(99);
    ASSERT_TRUE(host.send(unknown));
    EXPECT_EQ(rig.ack(9001).error.message(), "command.kind = 99 is out of range (allowed 0..17)");

    // Nothing refused changed anything: the effect is still there, the gain full.
    EXPECT_EQ(rig.ok(host.status(id)).status.state, EffectState::stopped);
    EXPECT_EQ(rig.pipeline().engine().gain(), 10000);
    EXPECT_EQ(rig.pipeline().counters().commands_refused, 8);
}

TEST(RuntimePipeline, SoloStartsStopEveryOtherEffect) {
    Rig rig(quiet_config());
    HostLink& host = rig.host();
    const EffectId a = rig.ok(host.create(constant_x(1000))).effect;
    const EffectId b = rig.ok(host.create(constant_x(2000))).effect;
    rig.ok(host.start_effect(a));
    rig.ok(host.start_effect(b));
    EXPECT_FLOAT_EQ(rig.pipeline().motor_force()[0], 3000.0f);

    // The effect's own count, solo.
    rig.ok(host.start_effect(b, kEffectIterations, true));
    EXPECT_FLOAT_EQ(rig.pipeline().motor_force()[0], 2000.0f);
    const CommandAck sa = rig.ok(host.status(a));
    EXPECT_EQ(sa.status.state, EffectState::stopped);
    EXPECT_EQ(sa.status.last_end, PlayEnd::stopped);
    EXPECT_EQ(rig.ok(host.status(b)).status.starts, 2u);

    // A count of 3, solo.
    const CommandAck s3 = rig.ok(host.start_effect(a, 3, true));
    EXPECT_EQ(s3.status.iterations, 3);
    EXPECT_FLOAT_EQ(rig.pipeline().motor_force()[0], 1000.0f);
    EXPECT_EQ(rig.ok(host.status(b)).status.state, EffectState::stopped);
}

// --- force-profile samples cross the queue in chunks ------------------------------------------

TEST(RuntimePipeline, ForceProfileSamplesCrossTheQueueInChunks) {
    Rig rig(quiet_config());
    HostLink& host = rig.host();
    const std::vector<int16_t> samples = ramp_samples(1000, 37);  // 8 chunks
    const uint32_t first = host.next_sequence();
    const CommandAck created = rig.ok(host.create(profile_x(1000, kTickUs), samples));
    // 8 stage_samples commands went first, each acked with the samples staged so far.
    ASSERT_EQ(rig.acks.size(), 9u);
    for (int k = 0; k < 8; ++k) {
        EXPECT_EQ(rig.acks[static_cast<size_t>(k)].sequence, first + static_cast<uint32_t>(k));
        EXPECT_EQ(rig.acks[static_cast<size_t>(k)].command, CommandKind::stage_samples);
        EXPECT_EQ(rig.acks[static_cast<size_t>(k)].staged_samples, std::min(1000, 128 * (k + 1)));
    }
    // Effect 14 + custom block 8 + 2 bytes a sample.
    EXPECT_EQ(created.pool.free_bytes, 16384 - (14 + 8 + 2 * 1000));
    EXPECT_EQ(rig.pipeline().staged_samples(), 0);

    // Played: sample k during [k, k+1) ms of effect time, one per tick.
    rig.ok(host.start_effect(created.effect));
    for (size_t k = 0; k < 1000; ++k) {
        ASSERT_EQ(rig.pipeline().motor_force()[0], static_cast<float>(samples[k])) << "sample " << k;
        rig.run(1);
    }
    EXPECT_EQ(rig.pipeline().motor_force()[0], static_cast<float>(samples[0]));  // it loops

    // New samples with an update of the type-specific block, from the start.
    const std::vector<int16_t> other = ramp_samples(1000, 91);
    rig.ok(host.update(created.effect, profile_x(1000, kTickUs), effect_field::kTypeSpecific, true, other));
    for (size_t k = 0; k < 300; ++k) {
        ASSERT_EQ(rig.pipeline().motor_force()[0], static_cast<float>(other[k])) << "sample " << k;
        rig.run(1);
    }
}

TEST(RuntimePipeline, SampleChunksMustComeInOrder) {
    Rig rig(quiet_config());
    HostLink& host = rig.host();
    Command chunk = make_keep_alive(500);
    chunk.kind = CommandKind::stage_samples;
    chunk.sample_offset = 128;  // nothing staged yet
    chunk.sample_count = 128;
    ASSERT_TRUE(host.send(chunk));
    const CommandAck a = rig.ack(500);
    EXPECT_EQ(a.error.message(), "sample_offset = 128 is out of range (allowed 0..0)");
    chunk.sequence = 501;
    chunk.sample_offset = 0;
    chunk.sample_count = 129;
    ASSERT_TRUE(host.send(chunk));
    EXPECT_EQ(rig.ack(501).error.message(), "sample_count = 129 is out of range (allowed 1..128)");

    // A profile with no samples staged is refused by the engine's own check.
    const CommandAck missing = rig.ack(host.create(profile_x(10, 1000)));
    EXPECT_EQ(missing.error.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(rig.pipeline().resident_effects(), 0);
}

// --- a full device disturbs nothing -----------------------------------------------------------

TEST(RuntimePipeline, DeviceFullDisturbsNoResidentEffect) {
    // Two identical devices run the same effects in lockstep; one is also sent creates that
    // cannot fit. Every force either puts out, on every axis at every tick, must be the same.
    Rig full(quiet_config());
    Rig calm(quiet_config());
    auto step_both = [&] {
        full.run(1);
        calm.run(1);
        for (int a = 0; a < 2; ++a) {
            ASSERT_EQ(full.pipeline().motor_force()[a], calm.pipeline().motor_force()[a]) << "t = " << full.t_us();
        }
    };
    // Runs both until `rig` has the ack of `sequence`.
    auto ack_in_step = [&](Rig& rig, std::optional<uint32_t> sequence) {
        EXPECT_TRUE(sequence.has_value());
        for (int i = 0; i < 10; ++i) {
            step_both();
            for (const CommandAck& a : rig.acks) {
                if (a.sequence == *sequence) return a;
            }
        }
        ADD_FAILURE() << "no ack";
        return CommandAck{};
    };

    // The same 31 effects on both: 30 of the busy mix and a 7000-sample profile.
    const std::vector<int16_t> big = ramp_samples(7000, 13);
    for (Rig* rig : {&full, &calm}) {
        for (int i = 0; i < 30; ++i) {
            const EffectParams e = bench::busy_mix_effect(i);
            const auto data = e.type == EffectType::force_profile ? std::span<const int16_t>(bench::kBusyMixSamples)
                                                                  : std::span<const int16_t>();
            rig->ok(rig->host().start_effect(rig->ok(rig->host().create(e, data)).effect));
        }
        rig->ok(rig->host().start_effect(rig->ok(rig->host().create(profile_x(7000, 500), big)).effect));
    }
    ASSERT_EQ(full.next_tick(), calm.next_tick());
    for (int i = 0; i < 100; ++i) step_both();

    // Out of parameter bytes: a 1000-sample profile needs 14 + 8 + 2000.
    const CommandAck pool = ack_in_step(full, full.host().query_pool());
    ASSERT_LT(pool.pool.free_bytes, 14 + 8 + 2000);
    const CommandAck no_bytes = ack_in_step(full, full.host().create(profile_x(1000, 1000), ramp_samples(1000, 7)));
    EXPECT_EQ(no_bytes.error.code, ErrorCode::device_full);
    EXPECT_EQ(std::string(no_bytes.error.field), "pool_bytes");
    EXPECT_EQ(no_bytes.error.value, 14 + 8 + 2000);
    EXPECT_EQ(no_bytes.pool.free_bytes, pool.pool.free_bytes);
    for (int i = 0; i < 50; ++i) step_both();

    // Out of slots: both take a 32nd effect; the full one is then asked for a 33rd.
    const EffectParams small = constant_x(0);
    const auto seq_full = full.host().create(small);
    const auto seq_calm = calm.host().create(small);
    ack_in_step(full, seq_full);
    const CommandAck last_full = full.acks.back();
    const CommandAck last_calm = calm.acks.back();
    ASSERT_EQ(last_full.sequence, *seq_full);
    ASSERT_EQ(last_calm.sequence, *seq_calm);
    EXPECT_EQ(last_full.pool.free_effects, 0);
    const CommandAck no_slot = ack_in_step(full, full.host().create(small));
    EXPECT_EQ(no_slot.error.code, ErrorCode::device_full);
    EXPECT_EQ(no_slot.pool.free_bytes, last_full.pool.free_bytes);
    for (int i = 0; i < 300; ++i) step_both();

    // Every resident effect is as it would have been.
    ASSERT_EQ(full.pipeline().resident_effects(), 32);
    ASSERT_EQ(calm.pipeline().resident_effects(), 32);
    ASSERT_FALSE(full.states.empty());
    const StateReport& sf = full.states.back();
    const StateReport& sc = calm.states.back();
    ASSERT_EQ(sf.t_us, sc.t_us);
    ASSERT_EQ(sf.effect_count, sc.effect_count);
    for (int i = 0; i < sf.effect_count; ++i) {
        EXPECT_EQ(sf.effects[i].id, sc.effects[i].id);
        EXPECT_EQ(sf.effects[i].state, sc.effects[i].state);
    }
    EXPECT_EQ(last_calm.effect, last_full.effect);
}

// --- reflexes -----------------------------------------------------------------------------------

TEST(RuntimePipeline, AReflexAssignedByCommandFiresInThePressTick) {
    sim::InputSchedule script(joystick());
    script.press(200'000, 1).release(260'000, 1);
    script.press(400'000, 2).release(420'000, 2);
    script.press(600'000, 2).release(620'000, 2);
    script.press(800'000, 2).release(820'000, 2);
    const sim::InputSchedule truth = script;
    Rig rig(quiet_config(), joystick(), sim::Grip::firm, sim::TargetMotion::hold_at({0}), std::move(script));
    HostLink& host = rig.host();

    // A: a trigger button in the Effect Structure makes the reflex at create.
    EffectParams jolt = constant_x(6000, 50'000);
    jolt.trigger = {TriggerKind::button, 1};
    const EffectId a = rig.ok(host.create(jolt)).effect;
    ASSERT_NE(rig.pipeline().reflexes().find(a), nullptr);
    // B: created without one, given button 2 by an update of its trigger.
    const EffectId b = rig.ok(host.create(constant_x(-3000, 30'000))).effect;
    EffectParams trigger = constant_x(0);
    trigger.trigger = {TriggerKind::button, 2};
    rig.ok(host.update(b, trigger, effect_field::kTrigger));
    EXPECT_EQ(rig.pipeline().reflexes().size(), 2);

    // Record the force and the buttons of every tick until 900 ms.
    std::vector<float> force;
    std::vector<uint32_t> buttons;
    std::vector<int64_t> t;
    bool removed = false;
    while (rig.t_us() < 900'000) {
        if (!removed && rig.t_us() >= 700'000) {
            rig.ok(host.remove_reflex(b));  // button 2 at 800 ms must do nothing
            removed = true;
            continue;
        }
        t.push_back(rig.t_us());
        rig.run(1);
        force.push_back(rig.pipeline().motor_force()[0]);
        buttons.push_back(rig.pipeline().last_input().buttons);
    }
    // The script's buttons are what the device read, tick by tick.
    for (size_t i = 0; i < t.size(); ++i) ASSERT_EQ(buttons[i], truth.buttons_at(t[i])) << t[i];

    auto first_force_at_or_after = [&](int64_t from_us) -> int64_t {
        for (size_t i = 0; i < t.size(); ++i) {
            if (t[i] >= from_us && force[i] != 0.0f) return t[i];
        }
        return -1;
    };
    // Press -> first force: 0 ticks.
    const int64_t latency_ticks = (first_force_at_or_after(0) - 200'000) / kTickUs;
    std::printf("reflex latency (press to first force): %lld ticks\n", static_cast<long long>(latency_ticks));
    EXPECT_EQ(latency_ticks, 0);
    for (size_t i = 0; i < t.size(); ++i) {
        const int64_t ti = t[i];
        float want = 0;
        if (ti >= 200'000 && ti < 250'000) want = 6000;   // A, 50 ms from the press of button 1
        if (ti >= 400'000 && ti < 430'000) want = -3000;  // B, 30 ms from each press of button 2
        if (ti >= 600'000 && ti < 630'000) want = -3000;
        ASSERT_EQ(force[i], want) << "t = " << ti << " us";
    }
    EXPECT_EQ(rig.pipeline().counters().reflex_starts, 3);

    // assign_reflex makes it again from the effect's own trigger fields.
    rig.ok(host.assign_reflex(b));
    EXPECT_EQ(rig.pipeline().reflexes().size(), 2);
    EXPECT_EQ(rig.ack(host.remove_reflex(b)).error.code, ErrorCode::ok);
    EXPECT_EQ(rig.ack(host.remove_reflex(b)).error.code, ErrorCode::invalid_handle);  // none left
}

TEST(RuntimePipeline, AnIforce1ClassDeviceArmsNoReflexes) {
    // §1.2.c: a processor that does not run reflexes leaves them to the host's driver.
    const sim::DeviceProfile& iforce1 = *sim::find_device_profile("iforce1");
    sim::InputSchedule script(iforce1);
    script.press(50'000, 1).release(60'000, 1);
    const RuntimeConfig config = quiet_config(iforce1);
    ASSERT_FALSE(config.local_reflexes);
    Rig rig(config, iforce1, sim::Grip::firm, sim::TargetMotion::hold_at({0}), std::move(script));
    EffectParams jolt = constant_x(6000, 50'000);
    jolt.trigger = {TriggerKind::button, 1};
    const EffectId id = rig.ok(rig.host().create(jolt)).effect;  // the trigger is a parameter
    EXPECT_EQ(rig.pipeline().reflexes().size(), 0);
    const CommandAck refused = rig.ack(rig.host().assign_reflex(id));
    EXPECT_EQ(refused.error.code, ErrorCode::not_supported);
    EXPECT_EQ(std::string(refused.error.field), "trigger_button");
    float most = 0;
    uint32_t pressed = 0;
    while (rig.t_us() < 120'000) {
        rig.run(1);
        most = std::max(most, std::abs(rig.pipeline().motor_force()[0]));
        pressed |= rig.pipeline().last_input().buttons;
    }
    EXPECT_EQ(pressed, 1u);  // the device saw the press
    EXPECT_EQ(most, 0.0f);  // the press at 50 ms started nothing
}

// --- safety in the host's reports -------------------------------------------------------------

TEST(RuntimePipeline, GrabLetGoGrabShowsInHostReports) {
    constexpr int64_t kFadeIn = 200'000;
    sim::InputSchedule script(joystick());
    script.let_go(300'000).grab(600'000);
    const sim::InputSchedule truth = script;
    RuntimeConfig config = quiet_config();
    config.safety.fade_in_us = kFadeIn;
    config.report_rate_hz = 1000;
    Rig rig(config, joystick(), sim::Grip::firm, sim::TargetMotion::hold_at({0}), std::move(script));
    rig.ok(rig.host().start_effect(rig.ok(rig.host().create(constant_x(4000))).effect));
    rig.run_until(1'000'000);

    // The grabs: power-on (the handle held from the start) and the grab at 600 ms.
    auto expected_fade = [&](int64_t t_us) {
        if (!truth.hand_present_at(t_us)) return 0.0;
        const int64_t grab = t_us >= 600'000 ? 600'000 : 0;
        return std::min(1.0, static_cast<double>(t_us - grab) / kFadeIn);
    };
    int held = 0, let_go = 0;
    for (const StateReport& s : rig.states) {
        if (s.t_us < 2 * kTickUs) continue;  // the effect starts at the second tick
        const bool hand = truth.hand_present_at(s.t_us);
        ASSERT_EQ(s.safety.handle_held, hand) << s.t_us;
        ASSERT_NEAR(s.safety.fade_level, expected_fade(s.t_us), 1e-6) << s.t_us;
        ASSERT_NEAR(s.force[0], 4000.0 * expected_fade(s.t_us), 0.05) << s.t_us;
        ASSERT_FALSE(s.safety.hands_off) << s.t_us;
        ASSERT_FALSE(s.safety.host_lost);
        (hand ? held : let_go)++;
    }
    EXPECT_EQ(let_go, 300);
    EXPECT_GT(held, 600);
}

TEST(RuntimePipeline, ASilentHostStopsEveryEffect) {
    RuntimeConfig config = quiet_config();
    config.safety.host_timeout_us = 100'000;
    config.safety.host_fade_out_us = 0;  // cut at once (the fade: ReleasingTheHost...)
    config.report_rate_hz = 1000;
    Rig rig(config);
    HostLink& host = rig.host();
    const CommandAck created = rig.ok(host.create(constant_x(4000)));  // heard at tick 0
    const CommandAck started = rig.ok(host.start_effect(created.effect));    // and at tick 1
    rig.run_until(300'000);
    for (const StateReport& s : rig.states) {
        const bool lost = s.t_us > started.t_us + 100'000;
        ASSERT_EQ(s.safety.host_lost, lost) << s.t_us;
        if (s.t_us > started.t_us) {
            ASSERT_EQ(s.force[0], lost ? 0.0f : 4000.0f) << s.t_us;
        }
    }
    EXPECT_EQ(rig.pipeline().counters().host_losses, 1);
    // The host is back: heard, and its effect was stopped by the watchdog.
    const CommandAck status = rig.ok(host.status(created.effect));
    EXPECT_EQ(status.status.state, EffectState::stopped);
    EXPECT_EQ(status.status.last_end, PlayEnd::stopped);
    rig.run(1);
    EXPECT_FALSE(rig.states.back().safety.host_lost);
    EXPECT_EQ(rig.states.back().force[0], 0.0f);
}

TEST(RuntimePipeline, ReleasingTheHostFadesItsForcesOutThenAcksAndStopsEverything) {
    RuntimeConfig config = quiet_config();
    config.report_rate_hz = 1000;
    Rig rig(config);
    HostLink& host = rig.host();
    const CommandAck created = rig.ok(host.create(constant_x(4000)));
    rig.ok(host.start_effect(created.effect));
    rig.run(5);
    ASSERT_EQ(rig.pipeline().motor_force()[0], 4000.0f);
    // The release, then a command behind it: neither is acked before the 50 ms fade ends.
    constexpr uint32_t kReleaseSequence = 0x7000'0000;
    ASSERT_TRUE(host.send(make_release_host(kReleaseSequence)));
    const std::optional<uint32_t> after = host.keep_alive();
    ASSERT_TRUE(after.has_value());
    const int64_t fade_us = config.safety.host_fade_out_us;
    const int64_t tick_us = 1'000'000 / config.loop_rate_hz;
    rig.run(1);
    const int64_t released_at = rig.t_us() - tick_us;  // the tick that took the release: H = 1
    bool acked = false;
    while (!acked) {
        const int64_t t = rig.t_us() - tick_us;  // the tick just run
        ASSERT_LE(t, released_at + fade_us + 2 * tick_us) << "no ack after the fade";
        const double expected =
            4000.0 * std::max(0.0, 1.0 - static_cast<double>(t - released_at) / static_cast<double>(fade_us));
        ASSERT_NEAR(rig.pipeline().motor_force()[0], expected, 0.5) << t;
        for (const CommandAck& a : rig.acks) {
            if (a.sequence == kReleaseSequence) {
                acked = true;
            } else if (a.sequence == *after) {
                ASSERT_TRUE(acked) << "a command behind the release was applied first";
            }
        }
        if (!acked) rig.run(1);
    }
    EXPECT_GT(rig.t_us() - tick_us, released_at + fade_us - tick_us);
    const CommandAck status = rig.ok(host.status(created.effect));
    EXPECT_EQ(status.status.state, EffectState::stopped);
    EXPECT_EQ(rig.pipeline().motor_force()[0], 0.0f);
}

TEST(RuntimePipeline, ReleasingTheHostWithNoForceIsAckedAtOnce) {
    Rig rig(quiet_config());
    rig.run(2);
    ASSERT_TRUE(rig.host().send(make_release_host(77)));
    rig.run(1);
    ASSERT_EQ(rig.acks.size(), 1u);
    EXPECT_EQ(rig.acks[0].sequence, 77u);
    EXPECT_EQ(rig.acks[0].command, CommandKind::release_host);
    EXPECT_FALSE(rig.pipeline().safety().state().host_lost);
}

// --- IDF ---------------------------------------------------------------------------------------

// RMS deviation of the reported position from where the hand aims, over [from, to).
double report_jitter(const std::vector<StateReport>& states, int64_t from_us, int64_t to_us, double x, double y) {
    double sum = 0;
    int n = 0;
    for (const StateReport& s : states) {
        if (s.t_us < from_us || s.t_us >= to_us) continue;
        sum += (s.position[0] - x) * (s.position[0] - x) + (s.position[1] - y) * (s.position[1] - y);
        ++n;
    }
    return n ? std::sqrt(sum / n) : -1;
}

TEST(RuntimePipeline, IdfSteadiesTheReportedPosition) {
    // A firm hand aims at (1500, -800) under a full-force 20 Hz vibration. The thorough test
    // is idf_closed_loop_test; this one checks the runtime wires IDF in.
    EffectParams vibration;
    vibration.type = EffectType::sine;
    vibration.axis_count = 2;
    vibration.axes[0] = Axis::x;
    vibration.axes[1] = Axis::y;
    vibration.direction.kind = DirectionKind::polar;
    vibration.direction.value[0] = 3000;
    vibration.periodic.magnitude = 10000;
    vibration.periodic.period_us = 50'000;
    double jitter[2] = {};
    for (int on = 0; on < 2; ++on) {
        RuntimeConfig config = quiet_config();
        config.report_rate_hz = 1000;
        Rig rig(config, joystick(), sim::Grip::firm, sim::TargetMotion::hold_at({1500, -800}));
        rig.ok(rig.host().set_idf(IdfSettings{.periodic = on == 1, .impulse = on == 1}));
        rig.ok(rig.host().start_effect(rig.ok(rig.host().create(vibration)).effect));
        rig.run_until(1'500'000);
        jitter[on] = report_jitter(rig.states, 500'000, 1'500'000, 1500, -800);
        // The motors got the whole vibration either way: rendering uses the sensed position.
        EXPECT_GT(std::abs(rig.pipeline().last_output().force[0]) + std::abs(rig.pipeline().last_output().force[1]), 0.0f);
    }
    std::printf("reported jitter, 20 Hz vibration: IDF off %.1f, on %.1f (%.0fx)\n", jitter[0], jitter[1],
                jitter[0] / jitter[1]);
    EXPECT_GT(jitter[0], 5 * jitter[1]);
}

TEST(RuntimePipeline, ClippingWallsHoldTheReportedPosition) {
    // The hand pushes the handle to +4000 on x into a clipping wall at +2000: the host sees
    // the wall's surface, the handle is where the hand put it (§3.7).
    EffectParams wall;
    wall.type = EffectType::axis_wall;
    wall.axis_count = 1;
    wall.axes[0] = Axis::x;
    wall.wall = {2000, WallSense::positive, 2000, OffsetMode::absolute, 0, 0, 0, true};
    Rig rig(quiet_config(), joystick(), sim::Grip::kinematic, sim::TargetMotion::hold_at({4000, 0}));
    rig.ok(rig.host().start_effect(rig.ok(rig.host().create(wall)).effect));
    rig.run(50);
    EXPECT_NEAR(rig.pipeline().last_input().position[0], 4000, 5);
    EXPECT_NEAR(rig.pipeline().reported_position()[0], 2000, 5);
    EXPECT_NEAR(rig.states.back().position[0], 2000, 5);
}

// --- reports ------------------------------------------------------------------------------------

TEST(RuntimePipeline, StateReportsComeAtTheConfiguredRate) {
    RuntimeConfig config = quiet_config();
    config.report_rate_hz = 300;
    Rig rig(config);
    rig.run(1000);  // one second at 1 kHz
    // Report k is due at ceil(k·10^6/300) µs and goes out at the first tick at or after it.
    ASSERT_EQ(rig.states.size(), 300u);
    for (size_t k = 0; k < rig.states.size(); ++k) {
        const int64_t due = (static_cast<int64_t>(k) * 1'000'000 + 299) / 300;
        const int64_t tick_at = (due + kTickUs - 1) / kTickUs * kTickUs;
        ASSERT_EQ(rig.states[k].t_us, tick_at) << k;
        ASSERT_EQ(rig.states[k].report_number, k);
    }

    // A new rate by command, from the tick that applies it.
    const CommandAck a = rig.ok(rig.host().set_report_rate(1000));
    const size_t before = rig.states.size();
    EXPECT_EQ(rig.states[before - 1].t_us, a.t_us);  // the acking tick reported at once
    rig.run(499);
    ASSERT_EQ(rig.states.size() - before, 499u);     // and then every tick
    for (size_t i = before; i < rig.states.size(); ++i) EXPECT_EQ(rig.states[i].t_us - rig.states[i - 1].t_us, kTickUs);
    EXPECT_EQ(rig.pipeline().report_rate_hz(), 1000);
}

TEST(RuntimePipeline, ReportRatesAreValidatedAgainstTheLoop) {
    RuntimeConfig config = quiet_config();
    config.loop_rate_hz = 500;
    config.report_rate_hz = 600;
    EXPECT_EQ(check_runtime_config(config).message(), "report_rate_hz = 600 is out of range (allowed 100..500)");
    config.report_rate_hz = 100;
    ASSERT_TRUE(check_runtime_config(config).ok());
    Rig rig(config);
    EXPECT_EQ(rig.ack(rig.host().set_report_rate(501)).error.message(),
              "report_rate_hz = 501 is out of range (allowed 100..500)");
    rig.run(500);
    // Ticks at 0, 2, ..., 1000 ms (the refusing tick and 500 more), a report every 10 ms.
    EXPECT_EQ(rig.states.size(), 101u);
}

TEST(RuntimePipeline, EffectStatesAndPagesInStateReports) {
    RuntimeConfig config = quiet_config();
    config.engine.max_effects = 40;
    config.report_rate_hz = 1000;
    Rig rig(config);
    HostLink& host = rig.host();
    EffectParams delayed = constant_x(1000, 100'000);
    delayed.start_delay_us = 20'000;
    const EffectId d = rig.ok(host.create(delayed)).effect;
    std::vector<EffectId> ids{d};
    for (int i = 1; i < 35; ++i) ids.push_back(rig.ok(host.create(constant_x(10))).effect);
    rig.ok(host.start_effect(d));
    rig.ok(host.start_effect(ids[1]));
    rig.states.clear();
    rig.run(1);
    // 35 resident effects: two pages of one round.
    ASSERT_EQ(rig.states.size(), 2u);
    const StateReport& p0 = rig.states[0];
    const StateReport& p1 = rig.states[1];
    EXPECT_EQ(p0.pages, 2);
    EXPECT_EQ(p0.page, 0);
    EXPECT_EQ(p1.page, 1);
    EXPECT_EQ(p0.report_number, p1.report_number);
    EXPECT_EQ(p0.effect_count, 32);
    EXPECT_EQ(p1.effect_count, 3);
    EXPECT_EQ(p0.resident_effects, 35);
    EXPECT_EQ(p0.effects[0].id, d);
    EXPECT_EQ(p0.effects[0].state, ReportedEffectState::delayed);
    EXPECT_EQ(p0.effects[1].state, ReportedEffectState::playing);
    EXPECT_EQ(p0.effects[2].state, ReportedEffectState::stopped);
    EXPECT_EQ(p1.effects[2].id, ids[34]);

    // The first page of the last round.
    auto page0 = [&]() -> const StateReport& {
        EXPECT_EQ(rig.states.back().page, 1);
        return rig.states[rig.states.size() - 2];
    };
    // Out of its delay: playing; to its end: stopped.
    rig.run_until(rig.t_us() + 30'000);
    EXPECT_EQ(page0().effects[0].state, ReportedEffectState::playing);
    rig.run_until(rig.t_us() + 100'000);
    EXPECT_EQ(page0().effects[0].state, ReportedEffectState::stopped);
    // Started while paused: reported playing (it begins at resume).
    rig.ok(host.control(DeviceControl::pause));
    rig.ok(host.start_effect(ids[2]));
    EXPECT_EQ(page0().effects[2].state, ReportedEffectState::playing);
    EXPECT_TRUE(page0().paused);
    EXPECT_TRUE(rig.states.back().paused);
}

TEST(RuntimePipeline, AFullReportQueueDropsStateReportsNeverAcks) {
    RuntimeConfig config = quiet_config();
    config.report_rate_hz = 1000;
    config.report_capacity = 40;
    config.max_commands_per_tick = 8;
    Rig rig(config);
    rig.set_draining(false);  // the host reads nothing for a while
    rig.run(100);
    // State reports filled the queue up to the places kept for acks.
    EXPECT_EQ(rig.pipeline().reports().size_approx(), 40u - 8u);
    EXPECT_EQ(rig.pipeline().counters().dropped_state_reports, 100 - 32);
    std::vector<uint32_t> sent;
    for (int i = 0; i < 20; ++i) sent.push_back(*rig.host().keep_alive());
    rig.run(10);
    // Eight acks fit; twelve commands wait for room.
    EXPECT_EQ(rig.pipeline().counters().commands, 8);
    EXPECT_GT(rig.pipeline().counters().command_stalls, 0);
    // The host reads again: every ack arrives, in order.
    rig.set_draining(true);
    rig.drain();
    rig.run(5);
    ASSERT_EQ(rig.acks.size(), 20u);
    for (size_t i = 0; i < sent.size(); ++i) EXPECT_EQ(rig.acks[i].sequence, sent[i]);
    EXPECT_EQ(rig.states.back().dropped_reports, static_cast<uint64_t>(rig.pipeline().counters().dropped_state_reports));
}

TEST(RuntimePipeline, ADynamicsFinalReportReachesTheHost) {
    // A mass kicked off the handle on a tether, ending after two half cycles (§5, §8.4):
    // the engine stops it and its final report comes through the report queue.
    EffectParams law;
    law.type = EffectType::dynamic_control_law;
    law.duration_us = kInfiniteUs;
    law.axis_count = 1;
    law.axes[0] = Axis::x;
    law.dynamic.control_law[0] = {2000, 3000, 3000, 300, 5000, 0, 2, 0, 0, 0};
    law.dynamic.interim_reporting = true;
    Rig rig(quiet_config());
    const EffectId id = rig.ok(rig.host().create(law)).effect;
    rig.ok(rig.host().start_effect(id));
    for (int i = 0; i < 3000 && std::none_of(rig.dynamics.begin(), rig.dynamics.end(), [](const DynamicReport& r) {
                        return r.kind == DynamicReport::Kind::final;
                    });
         ++i) {
        rig.run(1);
    }
    ASSERT_FALSE(rig.dynamics.empty());
    const DynamicReport& last = rig.dynamics.back();
    ASSERT_EQ(last.kind, DynamicReport::Kind::final);
    EXPECT_EQ(last.effect, id);
    EXPECT_EQ(last.axis_count, 1);
    EXPECT_GE(rig.dynamics.size(), 2u);  // interim reports came before it
    for (size_t i = 0; i + 1 < rig.dynamics.size(); ++i) EXPECT_EQ(rig.dynamics[i].kind, DynamicReport::Kind::interim);
    const CommandAck status = rig.ok(rig.host().status(id));
    EXPECT_EQ(status.status.state, EffectState::stopped);
    EXPECT_EQ(status.status.last_end, PlayEnd::finished);
    EXPECT_EQ(rig.pipeline().counters().dynamic_reports, static_cast<int64_t>(rig.dynamics.size()));
}

// --- construction and ticks ---------------------------------------------------------------------

TEST(RuntimePipeline, BadConfigurationsAreRefusedWithTheField) {
    RuntimeConfig c = quiet_config();
    c.loop_rate_hz = 50;
    EXPECT_EQ(check_runtime_config(c).message(), "loop_rate_hz = 50 is out of range (allowed 100..20000)");
    c = quiet_config();
    c.report_rate_hz = 1001;
    EXPECT_EQ(check_runtime_config(c).message(), "report_rate_hz = 1001 is out of range (allowed 100..1000)");
    c = quiet_config();
    c.idf.axis_count = 3;
    EXPECT_EQ(check_runtime_config(c).message(), "idf.axis_count = 3 is out of range (allowed 2..2)");
    c = quiet_config();
    c.safety.hands_off.window_us = 500;
    EXPECT_EQ(check_runtime_config(c).message(),
              "safety.hands_off.window_us = 500 is out of range (allowed 1000..100000)");
    c = quiet_config();
    c.report_capacity = 33;
    EXPECT_EQ(check_runtime_config(c).message(), "report_capacity = 33 is out of range (allowed 34..1048576)");
    c = quiet_config();
    c.max_commands_per_tick = 0;
    EXPECT_EQ(check_runtime_config(c).message(), "max_commands_per_tick = 0 is out of range (allowed 1..1024)");

    c = quiet_config();
    c.loop_rate_hz = 50;
    try {
        RuntimePipeline p(c, std::make_unique<SimBackend>(joystick(), sim::Grip::firm, sim::TargetMotion::hold_at({0})));
        ADD_FAILURE() << "a 50 Hz loop was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "runtime config: loop_rate_hz = 50 is out of range (allowed 100..20000)");
    }
    // A backend of another device.
    const sim::DeviceProfile& wheel = *sim::find_device_profile("wheel");
    EXPECT_THROW(RuntimePipeline(quiet_config(), std::make_unique<SimBackend>(wheel, sim::Grip::firm,
                                                                              sim::TargetMotion::hold_at({0}))),
                 std::invalid_argument);
    EXPECT_THROW(RuntimePipeline(quiet_config(), nullptr), std::invalid_argument);
}

TEST(RuntimePipeline, TimeComesFromTheTickIndex) {
    Rig rig(quiet_config());
    RuntimePipeline& p = rig.pipeline();
    p.tick(0);
    p.tick(1);
    p.tick(1);  // not increasing: ignored
    EXPECT_EQ(p.counters().rejected_ticks, 1);
    EXPECT_EQ(p.counters().ticks, 2);
    p.tick(10);  // skipped ticks: the device's time jumps with the index
    EXPECT_EQ(p.counters().t_us, 10 * kTickUs);
    EXPECT_EQ(p.last_input().t_us, 10 * kTickUs);
    EXPECT_DOUBLE_EQ(rig.sim().device().time_s(), 0.010);  // the handle lived through the gap
    EXPECT_EQ(p.next_tick_index(), 11);
}

}  // namespace
}  // namespace feel::runtime::test
