// Each field of a struct ff_effect (linux/input.h) against the feel field it becomes, with
// the numbers worked by hand from the documented mapping (docs/real-devices.md, "evdev
// units and feel units": hid-pidff's arithmetic), and what the translation refuses.
#include "ff_translation.hpp"

#include <gtest/gtest.h>

#include <cerrno>

namespace feel::bridge {
namespace {

host::DeviceCaps stick(int32_t axes = 2) {
    host::DeviceCaps caps;
    caps.device = "test";
    caps.axis_count = axes;
    const Axis order[kMaxAxes] = {Axis::x, Axis::y, Axis::z, Axis::rx, Axis::ry, Axis::rz};
    for (int i = 0; i < axes; ++i) caps.axes[i].axis = order[i];
    caps.button_count = 4;
    caps.supported_types = kAllEffectTypes;
    caps.effect_slots = 16;
    return caps;
}

ff_effect base(uint16_t type) {
    ff_effect e{};
    e.type = type;
    e.id = -1;
    e.direction = 0x4000;
    e.replay.length = 2000;
    e.replay.delay = 250;
    return e;
}

EffectParams only(const Translation& t) {
    EXPECT_EQ(t.error, 0) << t.message;
    EXPECT_EQ(t.effects.size(), 1u);
    return t.effects.at(0);
}

TEST(FfTranslation, ConstantForceEveryField) {
    ff_effect e = base(FF_CONSTANT);
    e.u.constant.level = -16384;
    e.u.constant.envelope = {.attack_length = 100, .attack_level = 0x7fff, .fade_length = 300, .fade_level = 4096};
    const EffectParams p = only(translate_effect(e, stick()));
    EXPECT_EQ(p.type, EffectType::constant);
    EXPECT_EQ(p.constant.magnitude, -5000);  // -16384 * 10000 / 32768
    EXPECT_EQ(p.duration_us, 2'000'000);     // replay.length 2000 ms
    EXPECT_EQ(p.start_delay_us, 250'000);    // replay.delay 250 ms
    EXPECT_EQ(p.gain, 10000);                // evdev has no per-effect gain
    EXPECT_EQ(p.axis_count, 2);
    EXPECT_EQ(p.axes[0], Axis::x);
    EXPECT_EQ(p.axes[1], Axis::y);
    EXPECT_EQ(p.direction.kind, DirectionKind::polar);
    EXPECT_EQ(p.direction.value[0], 9000);   // 0x4000: a quarter turn
    EXPECT_TRUE(p.has_envelope);
    EXPECT_EQ(p.envelope.impulse_level, 10000);
    EXPECT_EQ(p.envelope.settle_time_us, 100'000);
    EXPECT_EQ(p.envelope.fade_level, 1250);  // 4096 * 10000 / 32767
    EXPECT_EQ(p.envelope.fade_time_us, 300'000);
    EXPECT_EQ(p.trigger.kind, TriggerKind::none);
}

TEST(FfTranslation, ZeroLengthIsEndlessAndNoEnvelopeIsNone) {
    ff_effect e = base(FF_CONSTANT);
    e.replay.length = 0;
    e.u.constant.level = 32767;
    const EffectParams p = only(translate_effect(e, stick()));
    EXPECT_EQ(p.duration_us, kInfiniteUs);
    EXPECT_FALSE(p.has_envelope);
    EXPECT_EQ(p.constant.magnitude, 10000);
}

TEST(FfTranslation, RampLevels) {
    ff_effect e = base(FF_RAMP);
    e.u.ramp.start_level = 16384;
    e.u.ramp.end_level = -16384;
    const EffectParams p = only(translate_effect(e, stick()));
    EXPECT_EQ(p.type, EffectType::ramp);
    EXPECT_EQ(p.ramp.start, 5000);
    EXPECT_EQ(p.ramp.end, -5000);
}

TEST(FfTranslation, PeriodicWaveformsAndFields) {
    const std::pair<uint16_t, EffectType> waves[] = {{FF_SQUARE, EffectType::square}, {FF_TRIANGLE, EffectType::triangle},
                                                     {FF_SINE, EffectType::sine}, {FF_SAW_UP, EffectType::saw_up},
                                                     {FF_SAW_DOWN, EffectType::saw_down}};
    for (auto [waveform, type] : waves) {
        ff_effect e = base(FF_PERIODIC);
        e.u.periodic.waveform = waveform;
        e.u.periodic.period = 20;
        e.u.periodic.magnitude = 24576;
        e.u.periodic.offset = -8192;
        e.u.periodic.phase = 0x4000;
        const EffectParams p = only(translate_effect(e, stick()));
        EXPECT_EQ(p.type, type);
        EXPECT_EQ(p.periodic.period_us, 20'000);
        EXPECT_EQ(p.periodic.magnitude, 7500);  // 24576 * 10000 / 32767 = 7500.2
        EXPECT_EQ(p.periodic.offset, -2500);
        EXPECT_EQ(p.periodic.phase, 9000);
    }
}

TEST(FfTranslation, NegativeMagnitudeIsTheWaveUpsideDown) {
    // sin(x + 180°) = -sin(x): a sine upside down is half a period on.
    ff_effect e = base(FF_PERIODIC);
    e.u.periodic.waveform = FF_SINE;
    e.u.periodic.period = 1000;
    e.u.periodic.magnitude = -8192;
    e.u.periodic.phase = 0x8000;  // 180°, plus the 180° of the sign: a whole turn
    const EffectParams p = only(translate_effect(e, stick()));
    EXPECT_EQ(p.type, EffectType::sine);
    EXPECT_EQ(p.periodic.magnitude, 2500);
    EXPECT_EQ(p.periodic.phase, 0);
    // A saw up upside down (1 - 2p instead of 2p - 1) is the saw down, same phase.
    e.u.periodic.waveform = FF_SAW_UP;
    e.u.periodic.phase = 0;
    const EffectParams saw = only(translate_effect(e, stick()));
    EXPECT_EQ(saw.type, EffectType::saw_down);
    EXPECT_EQ(saw.periodic.magnitude, 2500);
    EXPECT_EQ(saw.periodic.phase, 0);
}

TEST(FfTranslation, ConditionsOnePerAxis) {
    for (auto [type, feel_type] : {std::pair{FF_SPRING, EffectType::spring}, std::pair{FF_DAMPER, EffectType::damper},
                                   std::pair{FF_INERTIA, EffectType::inertia},
                                   std::pair{FF_FRICTION, EffectType::friction}}) {
        ff_effect e = base(static_cast<uint16_t>(type));
        e.u.condition[0] = {.right_saturation = 0xffff, .left_saturation = 0x8000, .right_coeff = 16384,
                            .left_coeff = -8192, .deadband = 0x8000, .center = 32767};
        e.u.condition[1] = {.right_saturation = 0, .left_saturation = 49152, .right_coeff = -32768,
                            .left_coeff = 0, .deadband = 0, .center = -16384};
        const EffectParams p = only(translate_effect(e, stick()));
        EXPECT_EQ(p.type, feel_type);
        EXPECT_EQ(p.direction.kind, DirectionKind::none);  // a condition acts on each axis
        ASSERT_EQ(p.axis_count, 2);
        EXPECT_EQ(p.conditions[0].pos_saturation, 10000);
        EXPECT_EQ(p.conditions[0].neg_saturation, 5000);
        EXPECT_EQ(p.conditions[0].pos_coefficient, 5000);
        EXPECT_EQ(p.conditions[0].neg_coefficient, -2500);
        EXPECT_EQ(p.conditions[0].deadband, 5000);
        EXPECT_EQ(p.conditions[0].offset, 10000);
        EXPECT_EQ(p.conditions[1].pos_saturation, 0);
        EXPECT_EQ(p.conditions[1].neg_saturation, 7500);
        EXPECT_EQ(p.conditions[1].pos_coefficient, -10000);
        EXPECT_EQ(p.conditions[1].neg_coefficient, 0);
        EXPECT_EQ(p.conditions[1].offset, -5000);
    }
}

TEST(FfTranslation, RumbleIsTwoSines) {
    ff_effect e = base(FF_RUMBLE);
    e.trigger.button = 0xff00;  // games leave these uninitialised: a rumble has neither
    e.direction = 0x6c5f;
    e.u.rumble.strong_magnitude = 0x8000;
    e.u.rumble.weak_magnitude = 0xffff;
    const Translation t = translate_effect(e, stick());
    ASSERT_EQ(t.error, 0) << t.message;
    ASSERT_EQ(t.effects.size(), 2u);
    const EffectParams& strong = t.effects[0];
    const EffectParams& weak = t.effects[1];
    for (const EffectParams* p : {&strong, &weak}) {
        EXPECT_EQ(p->type, EffectType::sine);
        EXPECT_EQ(p->axis_count, 1);
        EXPECT_EQ(p->axes[0], Axis::x);
        EXPECT_EQ(p->direction.kind, DirectionKind::none);
        EXPECT_EQ(p->trigger.kind, TriggerKind::none);
        EXPECT_EQ(p->duration_us, 2'000'000);
        EXPECT_EQ(p->start_delay_us, 250'000);
        EXPECT_EQ(p->periodic.offset, 0);
    }
    EXPECT_EQ(strong.periodic.magnitude, 5000);      // 0x8000 of 0xFFFF
    EXPECT_EQ(strong.periodic.period_us, 50'000);    // 20 Hz
    EXPECT_EQ(weak.periodic.magnitude, 10000);
    EXPECT_EQ(weak.periodic.period_us, 10'000);      // 100 Hz
}

TEST(FfTranslation, TriggerButtonsAndRepeat) {
    ff_effect e = base(FF_CONSTANT);
    e.trigger.button = BTN_TRIGGER + 2;  // BTN_THUMB2: the third button
    e.trigger.interval = 150;
    const EffectParams p = only(translate_effect(e, stick()));
    EXPECT_EQ(p.trigger.kind, TriggerKind::button);
    EXPECT_EQ(p.trigger.index, 3);
    EXPECT_EQ(p.trigger_repeat_interval_us, 150'000);
    EXPECT_EQ(button_of_key(BTN_TRIGGER_HAPPY1), 17);
    EXPECT_EQ(key_of_button(17), BTN_TRIGGER_HAPPY1);
    EXPECT_EQ(key_of_button(1), BTN_TRIGGER);
    EXPECT_EQ(button_of_key(KEY_A), 0);
}

TEST(FfTranslation, OneAxisDeviceTakesTheComponentAlongItsAxis) {
    ff_effect e = base(FF_CONSTANT);
    e.u.constant.level = 32767;
    e.direction = 0xc000;  // 270°: sin = -1
    const EffectParams p = only(translate_effect(e, stick(1)));
    EXPECT_EQ(p.axis_count, 1);
    EXPECT_EQ(p.direction.kind, DirectionKind::cartesian);
    EXPECT_EQ(p.direction.value[0], -10000);
    e.direction = 0;  // along the missing y axis
    const Translation t = translate_effect(e, stick(1));
    EXPECT_EQ(t.error, -EINVAL);
    EXPECT_NE(t.message.find("direction = 0x0000"), std::string::npos) << t.message;
}

void expect_refused(const ff_effect& e, const std::string& names, const host::DeviceCaps& caps = stick()) {
    const Translation t = translate_effect(e, caps);
    EXPECT_EQ(t.error, -EINVAL);
    EXPECT_TRUE(t.effects.empty());
    EXPECT_NE(t.message.find(names), std::string::npos) << t.message;
}

TEST(FfTranslation, RefusesWhatFeelCannotPlayNamingTheField) {
    ff_effect e = base(FF_PERIODIC);
    e.u.periodic.waveform = FF_SINE;
    e.u.periodic.period = 0;
    expect_refused(e, "u.periodic.period = 0 is out of range (allowed 1..65000 ms)");
    e.u.periodic.period = 65001;  // evdev's 16 bits reach past feel's 65 s
    expect_refused(e, "u.periodic.period = 65001 ms is out of range (allowed 0..65000 ms)");
    ff_effect long_one = base(FF_CONSTANT);
    long_one.replay.length = 65535;
    expect_refused(long_one, "replay.length = 65535 ms is out of range");
    e.u.periodic.period = 10;
    e.u.periodic.waveform = FF_CUSTOM;
    expect_refused(e, "u.periodic.waveform = 0x005d is not offered");
    e.u.periodic.waveform = FF_SINE;
    e.u.periodic.envelope.attack_level = 0x8000;
    expect_refused(e, "envelope.attack_level = 32768 is out of range (allowed 0..32767)");
    ff_effect t = base(FF_CONSTANT);
    t.trigger.button = 0x6269;
    expect_refused(t, "trigger.button = 0x6269 is not a joystick button");
    ff_effect endless_ramp = base(FF_RAMP);
    endless_ramp.replay.length = 0;
    expect_refused(endless_ramp, "replay.length = 0 (endless) leaves a ramp no end");
    ff_effect unknown = base(0x4f);
    expect_refused(unknown, "type = 0x004f");
    host::DeviceCaps no_ramp = stick();
    no_ramp.supported_types &= ~effect_type_bit(EffectType::ramp);
    expect_refused(base(FF_RAMP), "does not play ramp", no_ramp);
}

TEST(FfTranslation, CapabilitiesFollowTheDevice) {
    host::DeviceCaps caps = stick();
    FfCapabilities all = ff_capabilities(caps);
    for (int bit : {FF_CONSTANT, FF_PERIODIC, FF_RAMP, FF_SPRING, FF_DAMPER, FF_INERTIA, FF_FRICTION, FF_RUMBLE,
                    FF_GAIN, FF_AUTOCENTER, FF_SQUARE, FF_TRIANGLE, FF_SINE, FF_SAW_UP, FF_SAW_DOWN}) {
        EXPECT_NE(std::find(all.bits.begin(), all.bits.end(), bit), all.bits.end()) << bit;
    }
    EXPECT_TRUE(all.missing.empty());
    caps.supported_types = effect_type_bit(EffectType::constant);
    FfCapabilities few = ff_capabilities(caps);
    EXPECT_EQ(few.bits, (std::vector<uint16_t>{FF_CONSTANT, FF_GAIN}));
    EXPECT_FALSE(few.missing.empty());
}

TEST(FfTranslation, DescribesWhatTheGameAskedInEvdevTerms) {
    ff_effect e = base(FF_CONSTANT);
    e.id = 1;
    e.u.constant.level = 8192;
    EXPECT_EQ(describe_ff_effect(e),
              "FF_CONSTANT id 1: length 2000 ms, delay 250 ms, direction 0x4000, level 8192, envelope 0 ms 0 / 0 ms 0");
    ff_effect r = base(FF_RUMBLE);
    r.u.rumble.strong_magnitude = 100;
    EXPECT_EQ(describe_ff_effect(r), "FF_RUMBLE id -1: length 2000 ms, delay 250 ms, strong 100, weak 0");
}

TEST(FfTranslation, PlayCountsAndAutocenter) {
    EXPECT_EQ(iterations_of_count(1), 1);
    EXPECT_EQ(iterations_of_count(254), 254);
    EXPECT_EQ(iterations_of_count(255), kInfiniteIterations);
    EXPECT_EQ(iterations_of_count(0x7fffffff), kInfiniteIterations);  // SDL_HAPTIC_INFINITY
    const EffectParams s = autocenter_spring(0x8000, stick());
    EXPECT_EQ(s.type, EffectType::spring);
    EXPECT_EQ(s.axis_count, 2);
    EXPECT_EQ(s.duration_us, kInfiniteUs);
    EXPECT_EQ(s.conditions[0].pos_coefficient, 5000);
    EXPECT_EQ(s.conditions[1].neg_coefficient, 5000);
    EXPECT_EQ(s.conditions[0].offset, 0);
}

}  // namespace
}  // namespace feel::bridge
