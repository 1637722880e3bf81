// §8.3 wave wrappers against §8.3's definitions and §8.5's SineWave / ImpulseSquareWave:
// cAxes 2 (x, y), rglDirection[0] = the angle (polar), dwDuration, dwTriggerButton,
// dwTriggerRepeatInterval, the DIENVELOPE and DIPERIODIC fields.
#include <gtest/gtest.h>

#include "feel/iforce.hpp"
#include "iforce_test_util.hpp"

namespace feel::iforce {
namespace {

using test::engine_accepts;
using test::throws_message;

void expect_polar_xy(const EffectParams& p, int32_t angle) {
    ASSERT_EQ(p.axis_count, 2);
    EXPECT_EQ(p.axes[0], Axis::x);
    EXPECT_EQ(p.axes[1], Axis::y);
    EXPECT_EQ(p.direction.kind, DirectionKind::polar);
    EXPECT_EQ(p.direction.value[0], angle);
    EXPECT_EQ(p.gain, 10000);
    EXPECT_EQ(p.iterations, 1);
}

TEST(WaveWrappers, VectorForceHasNoEndOfItsOwn) {
    // §8.3: "a force of indefinite duration".
    const EffectParams p = vector_force(6000, kInfiniteUs, 9000);
    EXPECT_EQ(p.type, EffectType::vector_force);
    expect_polar_xy(p, 9000);
    EXPECT_EQ(p.duration_us, kInfiniteUs);
    EXPECT_EQ(p.constant.magnitude, 6000);
    EXPECT_EQ(p.start_delay_us, 0);
    EXPECT_FALSE(p.has_envelope);
    EXPECT_EQ(p.trigger.kind, TriggerKind::none);
    EXPECT_TRUE(engine_accepts(p));
    // It may still be given one.
    EXPECT_EQ(vector_force(6000, 250000, 0).duration_us, 250000);
}

TEST(WaveWrappers, ConstantForceLastsTheDurationGiven) {
    // §8.3: "a force of a defined duration".
    const EffectParams p = constant_force(7500, 30000, 0);
    EXPECT_EQ(p.type, EffectType::constant);
    expect_polar_xy(p, 0);
    EXPECT_EQ(p.duration_us, 30000);
    EXPECT_EQ(p.constant.magnitude, 7500);
    EXPECT_TRUE(engine_accepts(p));
    EXPECT_TRUE(throws_message([] { (void)constant_force(7500, kInfiniteUs, 0); },
                               "constant_force: duration_us must be finite here (allowed 1..65000000 µs, "
                               "not kInfiniteUs)"));
}

TEST(WaveWrappers, ConstantForceTriggerIsAReflex) {
    const EffectParams p = constant_force_trigger(7500, 30000, 0, hat_trigger(2), 0);
    EXPECT_EQ(p.type, EffectType::constant);
    EXPECT_EQ(p.trigger, (Trigger{TriggerKind::hat, 2}));
    EXPECT_EQ(p.trigger_repeat_interval_us, 0);
    EXPECT_TRUE(engine_accepts(p));

    const EffectParams rep = constant_force_trigger(7500, 30000, 0, button_trigger(1), 100000);
    EXPECT_EQ(rep.trigger, (Trigger{TriggerKind::button, 1}));
    EXPECT_EQ(rep.trigger_repeat_interval_us, 100000);
    EXPECT_TRUE(engine_accepts(rep));

    EXPECT_TRUE(throws_message([] { (void)constant_force_trigger(7500, 30000, 0, kNoTrigger, 0); },
                               "constant_force_trigger: trigger is none; this wrapper plays on a button "
                               "press: pass button_trigger(1..32) or hat_trigger(1..4)"));
}

TEST(WaveWrappers, EnvelopeConstantShapesTheForce) {
    // §8.5 ImpulseSquareWave: dwAttackLevel = ImpulseLevel, dwAttackTime = SettleTime,
    // dwFadeLevel = FadeLevel, dwFadeTime = FadeTime.
    const EffectParams p = envelope_constant(2000, 500000, 9000, 9000, 40000, 1000, 100000, button_trigger(3), 0);
    EXPECT_EQ(p.type, EffectType::constant);
    expect_polar_xy(p, 9000);
    EXPECT_EQ(p.duration_us, 500000);
    EXPECT_EQ(p.constant.magnitude, 2000);
    ASSERT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope, (Envelope{9000, 40000, 1000, 100000}));
    EXPECT_EQ(p.trigger, (Trigger{TriggerKind::button, 3}));
    EXPECT_TRUE(engine_accepts(p));
}

TEST(WaveWrappers, RampGoesFromStartToEndOverItsDuration) {
    const EffectParams p = ramp(0, 6000, 2000000, 18000, kNoTrigger, 0);
    EXPECT_EQ(p.type, EffectType::ramp);
    expect_polar_xy(p, 18000);
    EXPECT_EQ(p.duration_us, 2000000);
    EXPECT_EQ(p.ramp, (RampBlock{0, 6000}));
    EXPECT_FALSE(p.has_envelope);
    EXPECT_TRUE(engine_accepts(p));

    const EffectParams e = ramp_envelope(10000, 0, 1000000, 27000, 0, 1, 5000, 200000, button_trigger(32), 65000000);
    EXPECT_EQ(e.type, EffectType::ramp);
    expect_polar_xy(e, 27000);
    EXPECT_EQ(e.ramp, (RampBlock{10000, 0}));
    ASSERT_TRUE(e.has_envelope);
    EXPECT_EQ(e.envelope, (Envelope{0, 1, 5000, 200000}));
    EXPECT_EQ(e.trigger_repeat_interval_us, 65000000);
    EXPECT_TRUE(engine_accepts(e));
}

TEST(WaveWrappers, PeriodicTakesItsTypeFromTheWaveform) {
    const struct {
        Waveform waveform;
        EffectType type;
    } cases[] = {{Waveform::sine, EffectType::sine},
                 {Waveform::square, EffectType::square},
                 {Waveform::triangle, EffectType::triangle},
                 {Waveform::saw_up, EffectType::saw_up},
                 {Waveform::saw_down, EffectType::saw_down}};
    for (const auto& c : cases) {
        // §8.5 SineWave: dwMagnitude, lOffset, dwPhase, dwPeriod, dwDuration, the angle,
        // dwTriggerButton, dwTriggerRepeatInterval.
        const EffectParams p = periodic(c.waveform, 2000, 500, 9000, 10000, 2000000, 9000, button_trigger(4), 0);
        EXPECT_EQ(p.type, c.type);
        expect_polar_xy(p, 9000);
        EXPECT_EQ(p.periodic.magnitude, 2000);
        EXPECT_EQ(p.periodic.offset, 500);
        EXPECT_EQ(p.periodic.phase, 9000);
        EXPECT_EQ(p.periodic.period_us, 10000);
        EXPECT_EQ(p.duration_us, 2000000);
        EXPECT_EQ(p.trigger, (Trigger{TriggerKind::button, 4}));
        EXPECT_FALSE(p.has_envelope);
        EXPECT_EQ(p.start_delay_us, 0);
        EXPECT_TRUE(engine_accepts(p));
    }
    EXPECT_EQ(periodic(Waveform::sine, 1, 0, 0, 1, kInfiniteUs, 0, kNoTrigger, 0).duration_us, kInfiniteUs);
}

TEST(WaveWrappers, EnvelopePeriodicAddsTheImpulseEnvelope) {
    const EffectParams p = envelope_periodic(Waveform::square, 7000, 0, 0, 100000, 500000, 0, 10000, 20000, 0,
                                             50000, button_trigger(1), 500000);
    EXPECT_EQ(p.type, EffectType::square);
    expect_polar_xy(p, 0);
    EXPECT_EQ(p.periodic.magnitude, 7000);
    EXPECT_EQ(p.periodic.period_us, 100000);
    ASSERT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope, (Envelope{10000, 20000, 0, 50000}));
    EXPECT_EQ(p.trigger_repeat_interval_us, 500000);
    EXPECT_TRUE(engine_accepts(p));
}

TEST(WaveWrappers, DelayedPeriodicStartsAfterThePause) {
    const EffectParams p = delayed_periodic(250000, Waveform::triangle, 3000, 0, 0, 40000, 1000000, 4500, kNoTrigger, 0);
    EXPECT_EQ(p.type, EffectType::triangle);
    EXPECT_EQ(p.start_delay_us, 250000);
    expect_polar_xy(p, 4500);
    EXPECT_EQ(p.duration_us, 1000000);
    EXPECT_TRUE(engine_accepts(p));
    EXPECT_EQ(delayed_periodic(0, Waveform::sine, 1, 0, 0, 1, 1, 0, kNoTrigger, 0).start_delay_us, 0);
}

TEST(WaveWrappers, SweepPeriodicTurnsBetweenItsAngles) {
    // §8.3 order: StartAngle, StopAngle, Sense, WaveForm, Magnitude, Offset, Period, Phase, Duration.
    const EffectParams p =
        sweep_periodic(27000, 9000, SweepSense::clockwise, Waveform::square, 5000, 100, 100000, 4500, 1500000);
    EXPECT_EQ(p.type, EffectType::sweep_square);
    ASSERT_EQ(p.axis_count, 2);
    EXPECT_EQ(p.axes[0], Axis::x);
    EXPECT_EQ(p.axes[1], Axis::y);
    EXPECT_EQ(p.direction.kind, DirectionKind::none);  // the sweep angles give the direction
    EXPECT_EQ(p.periodic.sweep_start_angle, 27000);
    EXPECT_EQ(p.periodic.sweep_end_angle, 9000);
    EXPECT_EQ(p.periodic.sweep_sense, SweepSense::clockwise);
    EXPECT_EQ(p.periodic.magnitude, 5000);
    EXPECT_EQ(p.periodic.offset, 100);
    EXPECT_EQ(p.periodic.period_us, 100000);
    EXPECT_EQ(p.periodic.phase, 4500);
    EXPECT_EQ(p.duration_us, 1500000);
    EXPECT_TRUE(engine_accepts(p));

    const EffectType sweeps[] = {EffectType::sweep_sine, EffectType::sweep_square, EffectType::sweep_triangle,
                                 EffectType::sweep_saw_up, EffectType::sweep_saw_down};
    const Waveform waves[] = {Waveform::sine, Waveform::square, Waveform::triangle, Waveform::saw_up,
                              Waveform::saw_down};
    for (int i = 0; i < 5; ++i) {
        const EffectParams s = sweep_periodic(0, 18000, SweepSense::counterclockwise, waves[i], 1, 0, 1, 0, 1);
        EXPECT_EQ(s.type, sweeps[i]);
        EXPECT_EQ(s.periodic.sweep_sense, SweepSense::counterclockwise);
        EXPECT_TRUE(engine_accepts(s));
    }
    EXPECT_TRUE(throws_message(
        [] { (void)sweep_periodic(0, 9000, SweepSense::clockwise, Waveform::sine, 1, 0, 1, 0, kInfiniteUs); },
        "sweep_periodic: duration_us must be finite here (allowed 1..65000000 µs, not kInfiniteUs)"));
}

TEST(WaveWrappers, ARepeatIntervalNeedsATrigger) {
    EXPECT_TRUE(throws_message([] { (void)periodic(Waveform::sine, 1, 0, 0, 1, 1, 0, kNoTrigger, 1000); },
                               "periodic: trigger_repeat_interval_us = 1000 needs a trigger to repeat on "
                               "(the trigger is none); pass 0"));
}

TEST(WaveWrappers, TriggersAreCheckedAgainstTheirRange) {
    EXPECT_TRUE(throws_message([] { (void)ramp(0, 1, 1, 0, button_trigger(33), 0); },
                               "ramp: trigger button = 33 is out of range (allowed 1..32)"));
    EXPECT_TRUE(throws_message([] { (void)ramp(0, 1, 1, 0, hat_trigger(0), 0); },
                               "ramp: trigger hat = 0 is out of range (allowed 1..4)"));
    EXPECT_TRUE(throws_message([] { (void)ramp(0, 1, 1, 0, button_trigger(1), 65000001); },
                               "ramp: trigger_repeat_interval_us = 65000001 is out of range (allowed 0..65000000)"));
}

TEST(WaveWrappers, AnUnknownWaveformIsNamed) {
    const auto bad = static_cast<Waveform>(9);
    EXPECT_TRUE(throws_message([&] { (void)periodic(bad, 1, 0, 0, 1, 1, 0, kNoTrigger, 0); },
                               "periodic: waveform must be sine, square, triangle, saw_up or saw_down"));
}

}  // namespace
}  // namespace feel::iforce
