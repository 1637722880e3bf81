// validate_effect(): every range of the primer (§6.3, §6.6, §8) and every cross-field
// rule. Expected ranges are written as the primer prints them, not taken from
// units.hpp, so a wrong constant there fails here.
#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "feel/effect_validation.hpp"
#include "support/valid_effects.hpp"

namespace feel {
namespace {

static_assert(noexcept(validate_effect(EffectParams{}, {})), "the validator runs on the real-time path");

using test::kFourSamples;
using test::set_axes;

// A small valid effect of each type.
EffectParams valid(EffectType t) { return test::valid_effect(t); }

std::span<const int16_t> samples_for(const EffectParams& p) {
    if (p.type == EffectType::force_profile) return kFourSamples;
    return {};
}

Error check(const EffectParams& p) { return validate_effect(p, samples_for(p)); }

// A range case: mutate a valid effect of `type`; expect `field` = value out of min..max.
struct RangeCase {
    const char* what;
    EffectType type;
    std::function<void(EffectParams&)> mutate;
    const char* field;
    int64_t value;
    int64_t min;
    int64_t max;
};

void expect_range_error(const RangeCase& c) {
    SCOPED_TRACE(c.what);
    EffectParams p = valid(c.type);
    c.mutate(p);
    const Error e = check(p);
    ASSERT_FALSE(e.ok()) << "accepted";
    EXPECT_EQ(e.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(e.field, c.field);
    ASSERT_TRUE(e.has_range) << e.message();
    EXPECT_EQ(e.value, c.value);
    EXPECT_EQ(e.allowed.min, c.min);
    EXPECT_EQ(e.allowed.max, c.max);
}

// A rule case: the error names `field` and its rule sentence contains `words`.
struct RuleCase {
    const char* what;
    EffectType type;
    std::function<void(EffectParams&)> mutate;
    const char* field;
    const char* words;
};

void expect_rule_error(const RuleCase& c) {
    SCOPED_TRACE(c.what);
    EffectParams p = valid(c.type);
    c.mutate(p);
    const Error e = check(p);
    ASSERT_FALSE(e.ok()) << "accepted";
    EXPECT_EQ(e.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(e.field, c.field);
    EXPECT_FALSE(e.has_range);
    EXPECT_NE(std::string(e.rule).find(c.words), std::string::npos) << "rule: " << e.rule;
}

constexpr EffectType kAllTypes[] = {
    EffectType::spring,         EffectType::damper,          EffectType::inertia,
    EffectType::friction,       EffectType::angle_spring,    EffectType::axis_barrier,
    EffectType::angle_barrier,  EffectType::axis_wall,       EffectType::angle_wall,
    EffectType::texture,        EffectType::vector_force,    EffectType::constant,
    EffectType::smart_pop,      EffectType::sine,            EffectType::square,
    EffectType::triangle,       EffectType::saw_up,          EffectType::saw_down,
    EffectType::sweep_sine,     EffectType::sweep_square,    EffectType::sweep_triangle,
    EffectType::sweep_saw_up,   EffectType::sweep_saw_down,  EffectType::force_profile,
    EffectType::ramp,           EffectType::dynamic_recoil,  EffectType::dynamic_impact,
    EffectType::dynamic_liquid, EffectType::dynamic_inertia, EffectType::dynamic_center_drift,
    EffectType::dynamic_control_law, EffectType::dynamic_sling, EffectType::dynamic_paddle,
};
static_assert(std::size(kAllTypes) == kEffectTypeCount);

TEST(EffectValidation, AValidEffectOfEveryTypePasses) {
    for (EffectType t : kAllTypes) {
        const Error e = check(valid(t));
        EXPECT_TRUE(e.ok()) << effect_type_name(t) << ": " << e.message();
    }
}

TEST(EffectValidation, EveryRangeEdgeIsInclusive) {
    // The primer's ranges are inclusive at both ends (§6.3, §6.6).
    EffectParams p = valid(EffectType::sine);
    p.duration_us = 65'000'000;
    p.start_delay_us = 65'000'000;
    p.gain = 0;
    p.iterations = 255;
    p.periodic = {10000, -10000, 65'000'000, 35999};
    p.trigger = {TriggerKind::button, 32};
    p.trigger_repeat_interval_us = 65'000'000;
    p.has_envelope = true;
    p.envelope = {10000, 65'000'000, 10000, 65'000'000};
    EXPECT_TRUE(check(p).ok()) << check(p).message();
    p.duration_us = 1;
    p.iterations = 1;
    p.periodic = {0, 10000, 1, 0};
    p.trigger = {TriggerKind::hat, 4};
    p.trigger_repeat_interval_us = 1;
    p.envelope = {0, 0, 0, 0};
    EXPECT_TRUE(check(p).ok()) << check(p).message();
}

TEST(EffectValidation, InfiniteDurationAndIterations) {
    EffectParams p = valid(EffectType::sine);
    p.duration_us = kInfiniteUs;
    p.iterations = kInfiniteIterations;
    EXPECT_TRUE(check(p).ok());
    // vector_force is endless by nature (§8.3 "a force of indefinite duration").
    EXPECT_TRUE(check([] { auto q = valid(EffectType::vector_force); q.duration_us = kInfiniteUs; return q; }()).ok());
}

TEST(EffectValidation, EffectStructureRanges) {
    const RangeCase cases[] = {
        // §6.3: Duration 1 to 65 million microseconds (or INFINITE).
        {"zero duration", EffectType::sine, [](auto& p) { p.duration_us = 0; }, "duration_us", 0, 1, 65'000'000},
        {"long duration", EffectType::sine, [](auto& p) { p.duration_us = 65'000'001; }, "duration_us", 65'000'001, 1, 65'000'000},
        {"negative duration", EffectType::sine, [](auto& p) { p.duration_us = -2; }, "duration_us", -2, 1, 65'000'000},
        // §6.6.i: Start Delay 0 to 65 million.
        {"negative delay", EffectType::sine, [](auto& p) { p.start_delay_us = -1; }, "start_delay_us", -1, 0, 65'000'000},
        {"long delay", EffectType::sine, [](auto& p) { p.start_delay_us = 65'000'001; }, "start_delay_us", 65'000'001, 0, 65'000'000},
        // Gain scales by 0..10000 of full (DirectX dwGain, §7.5 "10000 maximum gain").
        {"negative gain", EffectType::sine, [](auto& p) { p.gain = -1; }, "gain", -1, 0, 10000},
        {"gain above full", EffectType::sine, [](auto& p) { p.gain = 10001; }, "gain", 10001, 0, 10000},
        {"zero iterations", EffectType::sine, [](auto& p) { p.iterations = 0; }, "iterations", 0, 1, 255},
        {"256 iterations", EffectType::sine, [](auto& p) { p.iterations = 256; }, "iterations", 256, 1, 255},
        {"iterations -2", EffectType::sine, [](auto& p) { p.iterations = -2; }, "iterations", -2, 1, 255},
        {"no axes", EffectType::sine, [](auto& p) { p.axis_count = 0; }, "axes", 0, 1, 6},
        {"seven axes", EffectType::sine, [](auto& p) { p.axis_count = 7; }, "axes", 7, 1, 6},
        {"not an axis", EffectType::sweep_sine, [](auto& p) { p.axes[1] = static_cast<Axis>(6); }, "axes[1]", 6, 0, 5},
        // §6.3 Trigger Button; the reflex table of §1.2.c uses buttons and hat switches.
        {"button 0", EffectType::sine, [](auto& p) { p.trigger = {TriggerKind::button, 0}; }, "trigger_button", 0, 1, 32},
        {"button 33", EffectType::sine, [](auto& p) { p.trigger = {TriggerKind::button, 33}; }, "trigger_button", 33, 1, 32},
        {"hat 5", EffectType::sine, [](auto& p) { p.trigger = {TriggerKind::hat, 5}; }, "trigger_button", 5, 1, 4},
        {"hat 0", EffectType::sine, [](auto& p) { p.trigger = {TriggerKind::hat, 0}; }, "trigger_button", 0, 1, 4},
        // §6.3: Trigger Repeat Interval 0 to 65 million.
        {"negative repeat", EffectType::sine,
         [](auto& p) { p.trigger = {TriggerKind::button, 1}; p.trigger_repeat_interval_us = -1; },
         "trigger_repeat_interval_us", -1, 0, 65'000'000},
        {"long repeat", EffectType::sine,
         [](auto& p) { p.trigger = {TriggerKind::button, 1}; p.trigger_repeat_interval_us = 65'000'001; },
         "trigger_repeat_interval_us", 65'000'001, 0, 65'000'000},
        {"bad type", EffectType::sine, [](auto& p) { p.type = static_cast<EffectType>(33); }, "type", 33, 0, 32},
    };
    for (const RangeCase& c : cases) expect_range_error(c);
}

TEST(EffectValidation, EnvelopeRanges) {
    // §6.3 Envelope Struct: levels 0 to 10000, times 0 to 65 million.
    auto with_envelope = [](Envelope env) {
        return [env](EffectParams& p) {
            p.has_envelope = true;
            p.envelope = env;
        };
    };
    const RangeCase cases[] = {
        {"impulse above full", EffectType::sine, with_envelope({10001, 0, 0, 0}), "envelope.impulse_level", 10001, 0, 10000},
        {"negative impulse", EffectType::square, with_envelope({-1, 0, 0, 0}), "envelope.impulse_level", -1, 0, 10000},
        {"negative settle", EffectType::constant, with_envelope({0, -1, 0, 0}), "envelope.settle_time_us", -1, 0, 65'000'000},
        {"long settle", EffectType::ramp, with_envelope({0, 65'000'001, 0, 0}), "envelope.settle_time_us", 65'000'001, 0, 65'000'000},
        {"fade above full", EffectType::force_profile, with_envelope({0, 0, 10001, 0}), "envelope.fade_level", 10001, 0, 10000},
        {"negative fade", EffectType::sweep_sine, with_envelope({0, 0, 0, -1}), "envelope.fade_time_us", -1, 0, 65'000'000},
    };
    for (const RangeCase& c : cases) expect_range_error(c);
}

TEST(EffectValidation, EnvelopeOnlyOnTypesThatSupportIt) {
    // §6.4: only the wave types marked YES take an envelope; smart_pop is marked NO.
    for (EffectType t : kAllTypes) {
        EffectParams p = valid(t);
        p.has_envelope = true;
        p.envelope = {8000, 30'000, 0, 0};
        const Error e = check(p);
        const bool expected = effect_class(t) == EffectClass::wave && t != EffectType::smart_pop;
        EXPECT_EQ(e.ok(), expected) << effect_type_name(t) << ": " << e.message();
        if (!expected) {
            EXPECT_STREQ(e.field, "envelope");
        }
    }
}

TEST(EffectValidation, CommonRules) {
    const RuleCase cases[] = {
        {"ramp needs a finite duration", EffectType::ramp, [](auto& p) { p.duration_us = kInfiniteUs; }, "duration_us", "finite"},
        {"smart_pop needs a finite duration", EffectType::smart_pop, [](auto& p) { p.duration_us = kInfiniteUs; }, "duration_us", "finite"},
        {"sweeps need a finite duration", EffectType::sweep_triangle, [](auto& p) { p.duration_us = kInfiniteUs; }, "duration_us", "finite"},
        {"axes distinct", EffectType::sweep_sine, [](auto& p) { p.axes[1] = Axis::x; }, "axes[1]", "only once"},
        {"repeat needs a trigger", EffectType::sine, [](auto& p) { p.trigger_repeat_interval_us = 100'000; },
         "trigger_repeat_interval_us", "trigger"},
        {"trigger kind", EffectType::sine, [](auto& p) { p.trigger.kind = static_cast<TriggerKind>(9); }, "trigger_button", "kind"},
        {"envelope on a spring", EffectType::spring, [](auto& p) { p.has_envelope = true; }, "envelope", "§6.4"},
        {"samples on a sine", EffectType::sine, [](auto&) {}, "custom.samples", "only force_profile"},
    };
    for (const RuleCase& c : cases) {
        if (std::string(c.what) == "samples on a sine") {
            // samples_for() gives none to a sine: pass some explicitly.
            const Error e = validate_effect(valid(EffectType::sine), kFourSamples);
            EXPECT_STREQ(e.field, "custom.samples");
            EXPECT_NE(std::string(e.rule).find(c.words), std::string::npos);
            continue;
        }
        expect_rule_error(c);
    }
}

TEST(EffectValidation, DirectionRangesAndForms) {
    auto polar = [](int32_t a) {
        return [a](EffectParams& p) {
            set_axes(p, {Axis::x, Axis::y});
            p.direction = {DirectionKind::polar, {a, 0, 0}};
        };
    };
    auto spherical = [](int32_t az, int32_t el) {
        return [az, el](EffectParams& p) {
            set_axes(p, {Axis::x, Axis::y, Axis::z});
            p.direction = {DirectionKind::spherical, {az, el, 0}};
        };
    };
    const RangeCase ranges[] = {
        // §6.5.b / §8.3 Direction 0 to 35999 hundredths of a degree.
        {"polar 36000", EffectType::sine, polar(36000), "direction.polar", 36000, 0, 35999},
        {"polar -1", EffectType::constant, polar(-1), "direction.polar", -1, 0, 35999},
        // §6.5.c: azimuth in the XY plane, elevation 0 (from +z) to 90 (in the plane) and on to 180.
        {"azimuth 36000", EffectType::sine, spherical(36000, 9000), "direction.spherical[0]", 36000, 0, 35999},
        {"elevation 18001", EffectType::sine, spherical(0, 18001), "direction.spherical[1]", 18001, 0, 18000},
        {"elevation -1", EffectType::sine, spherical(0, -1), "direction.spherical[1]", -1, 0, 18000},
        {"cartesian component", EffectType::ramp,
         [](auto& p) { set_axes(p, {Axis::x, Axis::y}); p.direction = {DirectionKind::cartesian, {1, 10001, 0}}; },
         "direction.cartesian[1]", 10001, -10000, 10000},
        {"moments component", EffectType::sine,
         [](auto& p) { set_axes(p, {Axis::rx, Axis::rz}); p.direction = {DirectionKind::moments, {-10001, 1, 0}}; },
         "direction.moments[0]", -10001, -10000, 10000},
    };
    for (const RangeCase& c : ranges) expect_range_error(c);

    const RuleCase rules[] = {
        {"multi-axis wave needs a direction", EffectType::sine, [](auto& p) { set_axes(p, {Axis::x, Axis::y}); },
         "direction", "needs a direction"},
        {"polar needs x and y", EffectType::sine,
         [](auto& p) { set_axes(p, {Axis::x, Axis::z}); p.direction = {DirectionKind::polar, {0, 0, 0}}; },
         "direction.polar", "x and y"},
        {"polar on one axis", EffectType::constant, [](auto& p) { p.direction = {DirectionKind::polar, {0, 0, 0}}; },
         "direction.polar", "x and y"},
        {"spherical needs x, y, z", EffectType::sine,
         [](auto& p) { set_axes(p, {Axis::x, Axis::y}); p.direction = {DirectionKind::spherical, {0, 9000, 0}}; },
         "direction.spherical", "x, y and z"},
        {"cartesian zero vector", EffectType::sine,
         [](auto& p) { set_axes(p, {Axis::x, Axis::y}); p.direction = {DirectionKind::cartesian, {0, 0, 7}}; },
         "direction.cartesian", "zero vector"},
        {"cartesian on rotational axes", EffectType::sine,
         [](auto& p) { set_axes(p, {Axis::x, Axis::rz}); p.direction = {DirectionKind::cartesian, {1, 1, 0}}; },
         "direction.cartesian", "moments"},
        {"moments on translational axes", EffectType::sine,
         [](auto& p) { set_axes(p, {Axis::y}); p.direction = {DirectionKind::moments, {1, 0, 0}}; },
         "direction.moments", "rotational"},
        {"cartesian on four mixed axes", EffectType::sine,
         [](auto& p) {
             set_axes(p, {Axis::x, Axis::y, Axis::z, Axis::rx});
             p.direction = {DirectionKind::cartesian, {1, 1, 1}};
         },
         "direction.cartesian", "use moments for rx, ry, rz"},
        {"unknown direction kind", EffectType::sine,
         [](auto& p) { p.direction.kind = static_cast<DirectionKind>(9); }, "direction", "kind"},
    };
    for (const RuleCase& c : rules) expect_rule_error(c);
}

TEST(EffectValidation, ValidDirectionForms) {
    EffectParams p = valid(EffectType::sine);
    p.direction = {DirectionKind::cartesian, {-1, 0, 0}};  // one axis, one component
    EXPECT_TRUE(check(p).ok());
    set_axes(p, {Axis::y, Axis::x});  // polar takes x and y in either order
    p.direction = {DirectionKind::polar, {35999, 0, 0}};
    EXPECT_TRUE(check(p).ok());
    set_axes(p, {Axis::z, Axis::x, Axis::y});
    p.direction = {DirectionKind::spherical, {0, 18000, 0}};
    EXPECT_TRUE(check(p).ok());
    set_axes(p, {Axis::rx, Axis::ry, Axis::rz});
    p.direction = {DirectionKind::moments, {0, 0, -10000}};
    EXPECT_TRUE(check(p).ok());
}

TEST(EffectValidation, PeriodicRanges) {
    const RangeCase cases[] = {
        // §6.6.b Periodic Struct: Magnitude 0 to 10,000, Offset ±10,000, Period, Phase 0 to 35999.
        {"phase 36000", EffectType::sine, [](auto& p) { p.periodic.phase = 36000; }, "periodic.phase", 36000, 0, 35999},
        {"negative phase", EffectType::square, [](auto& p) { p.periodic.phase = -1; }, "periodic.phase", -1, 0, 35999},
        {"negative magnitude", EffectType::triangle, [](auto& p) { p.periodic.magnitude = -1; }, "periodic.magnitude", -1, 0, 10000},
        {"magnitude above full", EffectType::saw_up, [](auto& p) { p.periodic.magnitude = 10001; }, "periodic.magnitude", 10001, 0, 10000},
        {"offset", EffectType::saw_down, [](auto& p) { p.periodic.offset = -10001; }, "periodic.offset", -10001, -10000, 10000},
        // A zero period has no frequency: 1 to 65 million (§8.3 Period 1 to 65 million).
        {"zero period", EffectType::sine, [](auto& p) { p.periodic.period_us = 0; }, "periodic.period_us", 0, 1, 65'000'000},
        {"long period", EffectType::sine, [](auto& p) { p.periodic.period_us = 65'000'001; }, "periodic.period_us", 65'000'001, 1, 65'000'000},
        // §6.6.i Advanced Periodic Struct: Magnitude -10000 to 10000, sweep angles 0 to 35999.
        {"sweep magnitude", EffectType::sweep_sine, [](auto& p) { p.periodic.magnitude = -10001; }, "periodic.magnitude", -10001, -10000, 10000},
        {"sweep offset", EffectType::sweep_square, [](auto& p) { p.periodic.offset = 10001; }, "periodic.offset", 10001, -10000, 10000},
        {"sweep period", EffectType::sweep_triangle, [](auto& p) { p.periodic.period_us = 0; }, "periodic.period_us", 0, 1, 65'000'000},
        {"sweep phase", EffectType::sweep_saw_up, [](auto& p) { p.periodic.phase = 36000; }, "periodic.phase", 36000, 0, 35999},
        {"sweep start", EffectType::sweep_saw_down, [](auto& p) { p.periodic.sweep_start_angle = 36000; }, "periodic.sweep_start_angle", 36000, 0, 35999},
        {"sweep end", EffectType::sweep_sine, [](auto& p) { p.periodic.sweep_end_angle = -1; }, "periodic.sweep_end_angle", -1, 0, 35999},
    };
    for (const RangeCase& c : cases) expect_range_error(c);

    EffectParams sweep = valid(EffectType::sweep_sine);
    sweep.periodic.magnitude = -10000;  // signed for sweeps (§6.6.i)
    EXPECT_TRUE(check(sweep).ok());
    EffectParams sine = valid(EffectType::sine);
    sine.periodic.sweep_start_angle = 99999;  // not read by a sine
    EXPECT_TRUE(check(sine).ok());
}

TEST(EffectValidation, SweepRules) {
    const RuleCase cases[] = {
        {"sweep on one axis", EffectType::sweep_sine, [](auto& p) { set_axes(p, {Axis::x}); }, "axes", "x and y"},
        {"sweep on x and z", EffectType::sweep_square, [](auto& p) { set_axes(p, {Axis::x, Axis::z}); }, "axes", "x and y"},
        {"sweep with a direction", EffectType::sweep_triangle,
         [](auto& p) { p.direction = {DirectionKind::polar, {0, 0, 0}}; }, "direction", "sweep angles"},
        {"sweep sense", EffectType::sweep_saw_up, [](auto& p) { p.periodic.sweep_sense = static_cast<SweepSense>(2); },
         "periodic.sweep_sense", "clockwise or counterclockwise"},
    };
    for (const RuleCase& c : cases) expect_rule_error(c);
}

TEST(EffectValidation, ConstantAndRampRanges) {
    const RangeCase cases[] = {
        // §6.6.c Constant Struct: Magnitude -10,000 to 10,000.
        {"vector force", EffectType::vector_force, [](auto& p) { p.constant.magnitude = 10001; }, "constant.magnitude", 10001, -10000, 10000},
        {"constant", EffectType::constant, [](auto& p) { p.constant.magnitude = -10001; }, "constant.magnitude", -10001, -10000, 10000},
        {"smart pop", EffectType::smart_pop, [](auto& p) { p.constant.magnitude = 20000; }, "constant.magnitude", 20000, -10000, 10000},
        // §6.6.e Ramp Struct: Start, End -10000 to 10000.
        {"ramp start", EffectType::ramp, [](auto& p) { p.ramp.start = -10001; }, "ramp.start", -10001, -10000, 10000},
        {"ramp end", EffectType::ramp, [](auto& p) { p.ramp.end = 10001; }, "ramp.end", 10001, -10000, 10000},
    };
    for (const RangeCase& c : cases) expect_range_error(c);
}

TEST(EffectValidation, ForceProfileRanges) {
    const RangeCase cases[] = {
        // §6.6.d Custom Struct: Channels (axes, a device has at most 6), Sample Period, Samples.
        {"no channels", EffectType::force_profile, [](auto& p) { p.custom.channels = 0; }, "custom.channels", 0, 1, 6},
        {"seven channels", EffectType::force_profile, [](auto& p) { p.custom.channels = 7; }, "custom.channels", 7, 1, 6},
        {"zero sample period", EffectType::force_profile, [](auto& p) { p.custom.sample_period_us = 0; },
         "custom.sample_period_us", 0, 1, 65'000'000},
        {"long sample period", EffectType::force_profile, [](auto& p) { p.custom.sample_period_us = 65'000'001; },
         "custom.sample_period_us", 65'000'001, 1, 65'000'000},
        {"no samples", EffectType::force_profile, [](auto& p) { p.custom.sample_count = 0; }, "custom.sample_count", 0, 1, 65535},
        {"too many samples", EffectType::force_profile, [](auto& p) { p.custom.sample_count = 65536; },
         "custom.sample_count", 65536, 1, 65535},
    };
    for (const RangeCase& c : cases) expect_range_error(c);
}

TEST(EffectValidation, ForceProfileSamplesAndChannels) {
    EffectParams p = valid(EffectType::force_profile);
    std::vector<int16_t> samples(16, 0);
    p.custom.sample_count = 16;
    samples[12] = 10001;  // a sample is a force, ±10000 of full scale
    Error e = validate_effect(p, samples);
    EXPECT_STREQ(e.field, "custom.samples[12]");
    EXPECT_EQ(e.value, 10001);
    EXPECT_EQ(e.allowed.min, -10000);
    EXPECT_EQ(e.allowed.max, 10000);
    samples[12] = -10001;
    e = validate_effect(p, samples);
    EXPECT_STREQ(e.field, "custom.samples[12]");
    EXPECT_EQ(e.value, -10001);
    samples[12] = -10000;
    EXPECT_TRUE(validate_effect(p, samples).ok());

    // The count passed must be the count declared.
    e = validate_effect(p, std::span<const int16_t>(samples).first(15));
    EXPECT_STREQ(e.field, "custom.samples");
    EXPECT_NE(std::string(e.rule).find("custom.sample_count"), std::string::npos);

    // §6.6.d: "It must be an integral multiple of the Channels".
    set_axes(p, {Axis::x, Axis::y});
    p.custom.channels = 2;
    p.custom.sample_count = 3;
    e = validate_effect(p, std::span<const int16_t>(samples).first(3));
    EXPECT_STREQ(e.field, "custom.sample_count");
    EXPECT_NE(std::string(e.rule).find("multiple of custom.channels"), std::string::npos);

    p.custom.sample_count = 16;
    EXPECT_TRUE(validate_effect(p, samples).ok()) << validate_effect(p, samples).message();

    const RuleCase rules[] = {
        {"channels must match axes", EffectType::force_profile,
         [](auto& q) { set_axes(q, {Axis::x, Axis::y, Axis::z}); q.custom.channels = 2; }, "custom.channels",
         "equal the number of axes"},
        {"multi-channel takes no direction", EffectType::force_profile,
         [](auto& q) {
             set_axes(q, {Axis::x, Axis::y});
             q.custom.channels = 2;
             q.direction = {DirectionKind::polar, {0, 0, 0}};
         },
         "direction", "no direction"},
        {"one channel on two axes needs a direction", EffectType::force_profile,
         [](auto& q) { set_axes(q, {Axis::x, Axis::y}); }, "direction", "needs a direction"},
    };
    for (const RuleCase& c : rules) expect_rule_error(c);
}

TEST(EffectValidation, ConditionRanges) {
    // §6.6.a Condition Struct, checked on the second axis to prove the index is reported.
    const RangeCase cases[] = {
        {"pos coefficient", EffectType::spring, [](auto& p) { p.conditions[1].pos_coefficient = 10001; },
         "conditions[1].pos_coefficient", 10001, -10000, 10000},
        {"neg coefficient", EffectType::damper, [](auto& p) { p.conditions[1].neg_coefficient = -10001; },
         "conditions[1].neg_coefficient", -10001, -10000, 10000},
        {"offset", EffectType::inertia, [](auto& p) { p.conditions[1].offset = 10001; }, "conditions[1].offset", 10001, -10000, 10000},
        {"pos saturation", EffectType::friction, [](auto& p) { p.conditions[1].pos_saturation = -1; },
         "conditions[1].pos_saturation", -1, 0, 10000},
        {"neg saturation", EffectType::spring, [](auto& p) { p.conditions[1].neg_saturation = 10001; },
         "conditions[1].neg_saturation", 10001, 0, 10000},
        {"deadband", EffectType::spring, [](auto& p) { p.conditions[1].deadband = 10001; }, "conditions[1].deadband", 10001, 0, 10000},
        {"negative deadband", EffectType::damper, [](auto& p) { p.conditions[0].deadband = -1; }, "conditions[0].deadband", -1, 0, 10000},
        {"angle spring block", EffectType::angle_spring, [](auto& p) { p.conditions[0].pos_saturation = 10001; },
         "conditions[0].pos_saturation", 10001, 0, 10000},
        {"angle spring angle", EffectType::angle_spring, [](auto& p) { p.direction.value[0] = 36000; }, "direction.polar", 36000, 0, 35999},
    };
    for (const RangeCase& c : cases) expect_range_error(c);

    EffectParams p = valid(EffectType::spring);
    p.conditions[2].deadband = -5;  // beyond the effect's two axes: not read
    EXPECT_TRUE(check(p).ok());
}

TEST(EffectValidation, ConditionRules) {
    const RuleCase cases[] = {
        // §3.1 "for multi-axis conditions, you can define a direction": one block along it.
        {"condition on one axis with a direction", EffectType::damper,
         [](auto& p) { set_axes(p, {Axis::x}); p.direction = {DirectionKind::cartesian, {1, 0, 0}}; },
         "direction", "on one axis acts along that axis"},
        {"directed spring with a second block", EffectType::spring,
         [](auto& p) { p.direction = {DirectionKind::polar, {0, 0, 0}}; p.conditions[1].pos_coefficient = 1000; },
         "conditions[1]", "one block, conditions[0]"},
        {"directed friction with a direction that does not fit", EffectType::friction,
         [](auto& p) { p.direction = {DirectionKind::spherical, {0, 9000, 0}}; }, "direction.spherical", "x, y and z"},
        {"relative offset on a directed damper", EffectType::damper,
         [](auto& p) {
             p.direction = {DirectionKind::polar, {0, 0, 0}};
             p.conditions[0].offset_mode = OffsetMode::relative;
             p.conditions[1] = {};
         },
         "conditions[0].offset_mode", "only springs"},
        {"barrier offset mode", EffectType::axis_barrier, [](auto& p) { p.barrier.offset_mode = static_cast<OffsetMode>(2); },
         "barrier.offset_mode", "absolute or relative"},
        {"angle spring on one axis", EffectType::angle_spring, [](auto& p) { set_axes(p, {Axis::x}); }, "axes", "x and y"},
        {"angle spring without its angle", EffectType::angle_spring, [](auto& p) { p.direction.kind = DirectionKind::none; },
         "direction", "polar direction"},
        {"angle spring with a cartesian direction", EffectType::angle_spring,
         [](auto& p) { p.direction = {DirectionKind::cartesian, {1, 0, 0}}; }, "direction", "polar direction"},
        {"relative offset on a damper", EffectType::damper,
         [](auto& p) { p.conditions[0].offset_mode = OffsetMode::relative; }, "conditions[0].offset_mode", "only springs"},
        {"relative offset on friction", EffectType::friction,
         [](auto& p) { p.conditions[1].offset_mode = OffsetMode::relative; }, "conditions[1].offset_mode", "only springs"},
        {"texture on one axis with a direction", EffectType::texture,
         [](auto& p) { p.direction = {DirectionKind::cartesian, {1, 0, 0}}; }, "direction", "no direction"},
        {"texture on two axes without one", EffectType::texture, [](auto& p) { set_axes(p, {Axis::x, Axis::y}); },
         "direction", "needs a direction"},
        {"texture with a bad polar", EffectType::texture,
         [](auto& p) { set_axes(p, {Axis::x, Axis::z}); p.direction = {DirectionKind::polar, {0, 0, 0}}; },
         "direction.polar", "x and y"},
        {"axis wall on two axes", EffectType::axis_wall, [](auto& p) { set_axes(p, {Axis::x, Axis::y}); }, "axes", "exactly one axis"},
        {"axis barrier on two axes", EffectType::axis_barrier, [](auto& p) { set_axes(p, {Axis::x, Axis::y}); }, "axes", "exactly one axis"},
        {"axis wall with a direction", EffectType::axis_wall,
         [](auto& p) { p.direction = {DirectionKind::cartesian, {1, 0, 0}}; }, "direction", "no direction"},
        {"axis wall with an angle", EffectType::axis_wall, [](auto& p) { p.wall.angle = 9000; }, "wall.angle", "angle_wall"},
        {"axis barrier with an angle", EffectType::axis_barrier, [](auto& p) { p.barrier.angle = 9000; }, "barrier.angle", "angle_barrier"},
        {"angle wall on x and z", EffectType::angle_wall, [](auto& p) { set_axes(p, {Axis::x, Axis::z}); }, "axes", "x and y"},
        {"angle barrier on one axis", EffectType::angle_barrier, [](auto& p) { set_axes(p, {Axis::y}); }, "axes", "x and y"},
        {"angle wall with a direction", EffectType::angle_wall,
         [](auto& p) { p.direction = {DirectionKind::polar, {0, 0, 0}}; }, "direction", "from their block"},
        {"wall sense", EffectType::axis_wall, [](auto& p) { p.wall.sense = static_cast<WallSense>(2); }, "wall.sense", "positive or negative"},
        {"wall offset mode", EffectType::angle_wall, [](auto& p) { p.wall.offset_mode = static_cast<OffsetMode>(2); },
         "wall.offset_mode", "absolute or relative"},
    };
    for (const RuleCase& c : cases) expect_rule_error(c);

    for (EffectType t : {EffectType::spring, EffectType::damper, EffectType::inertia, EffectType::friction}) {
        EffectParams directed = valid(t);  // one block along the direction, the others left alone
        set_axes(directed, {Axis::x, Axis::y, Axis::z});
        directed.direction = {DirectionKind::spherical, {4500, 6000, 0}};
        directed.conditions[1] = {};
        directed.conditions[2] = {};
        EXPECT_TRUE(check(directed).ok()) << effect_type_name(t) << ": " << check(directed).message();
        directed.direction = {DirectionKind::cartesian, {3, -4, 1}};
        EXPECT_TRUE(check(directed).ok()) << effect_type_name(t) << ": " << check(directed).message();
    }
    EffectParams relative_barrier = valid(EffectType::angle_barrier);  // §3.8 "same as the wall"
    relative_barrier.barrier.offset_mode = OffsetMode::relative;
    EXPECT_TRUE(check(relative_barrier).ok()) << check(relative_barrier).message();

    EffectParams texture = valid(EffectType::texture);  // §7.5: a texture on x, y felt along polar 0
    set_axes(texture, {Axis::x, Axis::y});
    texture.direction = {DirectionKind::polar, {0, 0, 0}};
    EXPECT_TRUE(check(texture).ok());
}

TEST(EffectValidation, TextureWallBarrierRanges) {
    const RangeCase cases[] = {
        // §6.6.j Texture Struct: all four 1 to 10000.
        {"pos roughness", EffectType::texture, [](auto& p) { p.texture.pos_roughness = 0; }, "texture.pos_roughness", 0, 1, 10000},
        {"neg roughness", EffectType::texture, [](auto& p) { p.texture.neg_roughness = 10001; }, "texture.neg_roughness", 10001, 1, 10000},
        {"spacing", EffectType::texture, [](auto& p) { p.texture.spacing = 0; }, "texture.spacing", 0, 1, 10000},
        {"density", EffectType::texture, [](auto& p) { p.texture.density = 10001; }, "texture.density", 10001, 1, 10000},
        // §6.6.h Wall Struct.
        {"wall hardness", EffectType::axis_wall, [](auto& p) { p.wall.hardness = -10001; }, "wall.hardness", -10001, -10000, 10000},
        {"wall offset", EffectType::axis_wall, [](auto& p) { p.wall.offset = 10001; }, "wall.offset", 10001, -10000, 10000},
        {"wall angle", EffectType::angle_wall, [](auto& p) { p.wall.angle = 36000; }, "wall.angle", 36000, 0, 35999},
        {"wall friction", EffectType::angle_wall, [](auto& p) { p.wall.surface_friction = -1; }, "wall.surface_friction", -1, 0, 10000},
        {"wall texture", EffectType::axis_wall, [](auto& p) { p.wall.surface_texture = 10001; }, "wall.surface_texture", 10001, 0, 10000},
        // §6.6.g Barrier Struct.
        {"barrier pos hardness", EffectType::axis_barrier, [](auto& p) { p.barrier.pos_hardness = 10001; },
         "barrier.pos_hardness", 10001, -10000, 10000},
        {"barrier neg hardness", EffectType::angle_barrier, [](auto& p) { p.barrier.neg_hardness = -10001; },
         "barrier.neg_hardness", -10001, -10000, 10000},
        {"barrier thickness", EffectType::axis_barrier, [](auto& p) { p.barrier.thickness = 0; }, "barrier.thickness", 0, 1, 10000},
        {"barrier offset", EffectType::axis_barrier, [](auto& p) { p.barrier.offset = -10001; }, "barrier.offset", -10001, -10000, 10000},
        {"barrier angle", EffectType::angle_barrier, [](auto& p) { p.barrier.angle = -1; }, "barrier.angle", -1, 0, 35999},
        {"barrier friction", EffectType::axis_barrier, [](auto& p) { p.barrier.surface_friction = 10001; },
         "barrier.surface_friction", 10001, 0, 10000},
        {"barrier texture", EffectType::angle_barrier, [](auto& p) { p.barrier.surface_texture = -1; },
         "barrier.surface_texture", -1, 0, 10000},
    };
    for (const RangeCase& c : cases) expect_range_error(c);
}

TEST(EffectValidation, DynamicRanges) {
    using T = EffectType;
    // §8.4: each wrapper parameter has the range of the control-law parameter it maps to.
    const RangeCase cases[] = {
        {"blast direction", T::dynamic_recoil, [](auto& p) { p.dynamic.blast_direction = 36000; }, "dynamic.blast_direction", 36000, 0, 35999},
        {"blast intensity", T::dynamic_recoil, [](auto& p) { p.dynamic.blast_intensity = 10001; }, "dynamic.blast_intensity", 10001, -10000, 10000},
        {"recoil mass", T::dynamic_recoil, [](auto& p) { p.dynamic.dynamic_mass = 0; }, "dynamic.dynamic_mass", 0, 1, 10000},
        {"blast resonance", T::dynamic_recoil, [](auto& p) { p.dynamic.blast_resonance = 0; }, "dynamic.blast_resonance", 0, 1, 10000},
        {"blast decay", T::dynamic_recoil, [](auto& p) { p.dynamic.blast_decay = 10001; }, "dynamic.blast_decay", 10001, 0, 10000},
        {"impact direction", T::dynamic_impact, [](auto& p) { p.dynamic.impact_direction = -1; }, "dynamic.impact_direction", -1, 0, 35999},
        {"impact intensity", T::dynamic_impact, [](auto& p) { p.dynamic.impact_intensity = -10001; }, "dynamic.impact_intensity", -10001, -10000, 10000},
        {"impact mass", T::dynamic_impact, [](auto& p) { p.dynamic.dynamic_mass = 10001; }, "dynamic.dynamic_mass", 10001, 1, 10000},
        {"elasticity", T::dynamic_impact, [](auto& p) { p.dynamic.elasticity = 0; }, "dynamic.elasticity", 0, 1, 10000},
        {"absorption", T::dynamic_impact, [](auto& p) { p.dynamic.collision_absorption = -1; }, "dynamic.collision_absorption", -1, 0, 10000},
        {"density", T::dynamic_liquid, [](auto& p) { p.dynamic.density = 0; }, "dynamic.density", 0, 1, 10000},
        {"settle", T::dynamic_liquid, [](auto& p) { p.dynamic.settle = 10001; }, "dynamic.settle", 10001, 1, 10000},
        {"viscosity", T::dynamic_liquid, [](auto& p) { p.dynamic.viscosity = -1; }, "dynamic.viscosity", -1, 0, 10000},
        {"inertia", T::dynamic_inertia, [](auto& p) { p.dynamic.inertia = 0; }, "dynamic.inertia", 0, 1, 10000},
        {"play", T::dynamic_inertia, [](auto& p) { p.dynamic.play = 10001; }, "dynamic.play", 10001, 0, 10000},
        {"stiffness", T::dynamic_center_drift, [](auto& p) { p.dynamic.stiffness = 0; }, "dynamic.stiffness", 0, 1, 10000},
        {"drift resistance", T::dynamic_center_drift, [](auto& p) { p.dynamic.drift_resistance = -1; }, "dynamic.drift_resistance", -1, 0, 10000},
        {"sling mass", T::dynamic_sling, [](auto& p) { p.dynamic.ball_mass = 0; }, "dynamic.ball_mass", 0, 1, 10000},
        {"string length", T::dynamic_sling, [](auto& p) { p.dynamic.string_length = -1; }, "dynamic.string_length", -1, 0, 10000},
        {"string compliance", T::dynamic_sling, [](auto& p) { p.dynamic.string_compliance = 0; }, "dynamic.string_compliance", 0, 1, 10000},
        {"ball damping", T::dynamic_sling, [](auto& p) { p.dynamic.ball_damping = 10001; }, "dynamic.ball_damping", 10001, 0, 10000},
        {"paddle mass", T::dynamic_paddle, [](auto& p) { p.dynamic.ball_mass = 10001; }, "dynamic.ball_mass", 10001, 1, 10000},
        {"initial velocity", T::dynamic_paddle, [](auto& p) { p.dynamic.initial_velocity = 10001; }, "dynamic.initial_velocity", 10001, -10000, 10000},
        {"velocity direction", T::dynamic_paddle, [](auto& p) { p.dynamic.initial_velocity_direction = 36000; },
         "dynamic.initial_velocity_direction", 36000, 0, 35999},
        {"paddle compliance", T::dynamic_paddle, [](auto& p) { p.dynamic.paddle_compliance = 0; }, "dynamic.paddle_compliance", 0, 1, 10000},
        {"paddle damping", T::dynamic_paddle, [](auto& p) { p.dynamic.paddle_damping = -1; }, "dynamic.paddle_damping", -1, 0, 10000},
        {"paddle gravity", T::dynamic_paddle, [](auto& p) { p.dynamic.gravity = -10001; }, "dynamic.gravity", -10001, -10000, 10000},
        // §8.4 DynamicControlLaw parameters, on the second axis.
        {"law mass", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].mass = 0; }, "dynamic.control_law[1].mass", 0, 1, 10000},
        {"law k_pos", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].k_pos = 0; }, "dynamic.control_law[1].k_pos", 0, 1, 10000},
        {"law k_neg", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].k_neg = 10001; }, "dynamic.control_law[1].k_neg", 10001, 1, 10000},
        {"law b", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].b = -1; }, "dynamic.control_law[1].b", -1, 0, 10000},
        {"law vel_init", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].vel_init = 10001; },
         "dynamic.control_law[1].vel_init", 10001, -10000, 10000},
        {"law pos_init", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].pos_init = -10001; },
         "dynamic.control_law[1].pos_init", -10001, -10000, 10000},
        {"law half_cycles", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].half_cycles = 10001; },
         "dynamic.control_law[1].half_cycles", 10001, 0, 10000},
        {"law length", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].length = -1; },
         "dynamic.control_law[1].length", -1, 0, 10000},
        {"law drag", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].drag = 10001; },
         "dynamic.control_law[1].drag", 10001, 0, 10000},
        {"law gravity", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[1].gravity = 10001; },
         "dynamic.control_law[1].gravity", 10001, -10000, 10000},
        {"law on the first axis", T::dynamic_control_law, [](auto& p) { p.dynamic.control_law[0].mass = 10001; },
         "dynamic.control_law[0].mass", 10001, 1, 10000},
    };
    for (const RangeCase& c : cases) expect_range_error(c);

    // A named dynamic reads only its own parameters.
    EffectParams liquid = valid(T::dynamic_liquid);
    liquid.dynamic.blast_resonance = 0;
    liquid.dynamic.control_law[0].mass = 0;
    EXPECT_TRUE(check(liquid).ok());
}

TEST(EffectValidation, DynamicRules) {
    using T = EffectType;
    const RuleCase cases[] = {
        {"dynamics take no direction", T::dynamic_liquid, [](auto& p) { p.direction = {DirectionKind::cartesian, {1, 0, 0}}; },
         "direction", "no direction"},
        {"recoil on one axis: the sign aims it", T::dynamic_recoil,
         [](auto& p) { set_axes(p, {Axis::x}); p.dynamic.blast_direction = 9000; }, "dynamic.blast_direction", "the angle must be 0"},
        {"recoil on one axis takes no direction", T::dynamic_recoil,
         [](auto& p) { set_axes(p, {Axis::x}); p.dynamic.blast_direction = 0; p.direction = {DirectionKind::cartesian, {1, 0, 0}}; },
         "direction", "sign of its intensity"},
        {"impact on x, y, z needs a spherical direction", T::dynamic_impact,
         [](auto& p) { set_axes(p, {Axis::x, Axis::y, Axis::z}); p.dynamic.impact_direction = 0; }, "direction", "spherical"},
        {"impact on x, y, z: the direction aims it", T::dynamic_impact,
         [](auto& p) { set_axes(p, {Axis::x, Axis::y, Axis::z}); p.dynamic.impact_direction = 100; p.direction = {DirectionKind::spherical, {0, 9000, 0}}; },
         "dynamic.impact_direction", "the angle must be 0"},
        {"impact on two axes aims in x-y", T::dynamic_impact, [](auto& p) { set_axes(p, {Axis::y, Axis::z}); }, "axes", "x and y"},
        {"paddle stays 2D", T::dynamic_paddle, [](auto& p) { set_axes(p, {Axis::x, Axis::y, Axis::z}); }, "axes", "2D only"},
    };
    for (const RuleCase& c : cases) expect_rule_error(c);
}

TEST(EffectValidation, MessagesQuoteFieldValueAndRange) {
    EffectParams p = valid(EffectType::sine);
    p.periodic.phase = 36000;
    EXPECT_EQ(check(p).message(), "periodic.phase = 36000 is out of range (allowed 0..35999)");
}

}  // namespace
}  // namespace feel
