// Capabilities and device classes (issue 5 §10; primer §5.1, §6.2, §7.4).
//
// The truth the tests hold the code to: the profile's own data (capabilities report what
// the profile says, and the engine enforces it), the primer's master set of §6.4 (10
// Conditions, 15 Waves, 8 Dynamics; an I-FORCE 1.x core has no Dynamics, §5.1), the pool
// cost table of docs/runtime.md summed by hand, and geometry (a sensor step is the travel
// over the counts).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "feel/engine.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/realtime_loop.hpp"
#include "feel/sim/device_profile.hpp"
#include "support/valid_effects.hpp"

namespace feel::runtime {
namespace {

const sim::DeviceProfile& profile(const char* name) {
    const sim::DeviceProfile* p = sim::find_device_profile(name);
    EXPECT_NE(p, nullptr) << name;
    return *p;
}

using test::valid_effect;

CreateResult create(Engine& engine, const EffectParams& p) {
    if (p.type == EffectType::force_profile) return engine.create(p, test::kFourSamples);
    return engine.create(p);
}

// An enveloped sine on x: effect 14 + envelope 14 + periodic 12 = 40 bytes
// (docs/runtime.md, the pool cost table).
EffectParams enveloped_sine() {
    EffectParams p = valid_effect(EffectType::sine);
    p.has_envelope = true;
    p.envelope = {10000, 20'000, 0, 20'000};
    return p;
}
constexpr int32_t kEnvelopedSineBytes = 14 + 14 + 12;

// --- capabilities follow the profile -----------------------------------------------------

TEST(Capabilities, EveryBuiltInReportsItsProfilesData) {
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        SCOPED_TRACE(std::string(p.name));
        const Capabilities c = capabilities_for(p);
        EXPECT_EQ(c.device, p.name);
        EXPECT_EQ(c.description, p.description);
        EXPECT_EQ(c.device_class, p.device_class);
        EXPECT_EQ(c.class_name, sim::device_class_name(p.device_class));
        ASSERT_EQ(c.axis_count, p.axis_count);
        for (int i = 0; i < p.axis_count; ++i) {
            EXPECT_EQ(c.axes[i].axis, p.axes[i].axis);
            EXPECT_EQ(c.axes[i].kind, p.axes[i].kind);
            EXPECT_EQ(c.axes[i].half_travel, p.axes[i].half_travel);
            EXPECT_EQ(c.axes[i].max_force, p.axes[i].max_force);
            EXPECT_EQ(c.axes[i].sensor_counts, p.axes[i].sensor_counts);
            // A step is the full travel over the counts.
            EXPECT_DOUBLE_EQ(c.axes[i].resolution * p.axes[i].sensor_counts, 2 * p.axes[i].half_travel);
        }
        EXPECT_EQ(c.button_count, p.button_count);
        EXPECT_EQ(c.hat_count, p.hat_count);
        EXPECT_EQ(c.dead_man_switch, p.dead_man_switch);
        EXPECT_EQ(c.max_force_normalized, 10000);
        EXPECT_EQ(c.supported_types, p.supported_types);
        EXPECT_EQ(c.effect_slots, p.effect_slots);
        EXPECT_EQ(c.pool_bytes, p.pool_bytes);
        EXPECT_EQ(c.sample_memory, p.sample_memory);
        EXPECT_EQ(c.local_reflexes, p.local_reflexes);
        EXPECT_EQ(c.loop_rate_hz, p.default_loop_rate_hz);
        EXPECT_EQ(c.max_loop_rate_hz, p.max_loop_rate_hz);
        EXPECT_EQ(c.firmware_version, p.firmware_version);
        EXPECT_EQ(c.firmware_version, "feel-sim 0.1.0");
        EXPECT_EQ(c.protocol_version, "HID PID 1.0 + feel vendor 2");
    }
}

TEST(Capabilities, TheEngineEnforcesWhatTheDeviceReports) {
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        const Capabilities c = capabilities_for(p);
        Engine engine(sim::engine_config_for(p));
        const PoolInfo pool = engine.pool();
        EXPECT_EQ(pool.max_effects, c.effect_slots) << p.name;
        EXPECT_EQ(pool.total_bytes, c.pool_bytes) << p.name;
        EXPECT_EQ(pool.total_samples, c.sample_memory) << p.name;
        for (int i = 0; i < kEffectTypeCount; ++i) {
            const auto t = static_cast<EffectType>(i);
            const EffectParams e = valid_effect(t);
            bool fits = true;  // the wheel has no y axis for the two-axis examples
            for (int a = 0; a < e.axis_count; ++a) fits = fits && axis_index(e.axes[a]) < p.axis_count;
            if (!fits) continue;
            const CreateResult r = create(engine, e);
            if (c.supports(t)) {
                EXPECT_TRUE(r.error.ok()) << p.name << " " << effect_type_name(t) << ": " << r.error.message();
                EXPECT_TRUE(engine.destroy(r.id).ok());
            } else {
                EXPECT_EQ(r.error.code, ErrorCode::not_supported) << p.name << " " << effect_type_name(t);
            }
        }
    }
}

TEST(Capabilities, AxesAreReportedInPhysicalUnits) {
    const Capabilities joystick = capabilities_for(profile("joystick"));
    // ±50 mm at the grip over 4096 counts: 100 mm / 4096 = 24.4 µm a step; 1 lbf.
    EXPECT_NEAR(joystick.axes[0].resolution, 0.1 / 4096, 1e-12);
    EXPECT_NEAR(joystick.axes[0].max_force, 4.4482, 0.01);
    EXPECT_EQ(travel_unit(joystick.axes[0].kind), "m");
    EXPECT_EQ(force_unit(joystick.axes[0].kind), "N");
    const Capabilities wheel = capabilities_for(profile("wheel"));
    EXPECT_NEAR(wheel.axes[0].half_travel * 180 / std::numbers::pi, 450.0, 1e-9);
    EXPECT_EQ(travel_unit(wheel.axes[0].kind), "rad");
    EXPECT_EQ(force_unit(wheel.axes[0].kind), "N·m");
}

TEST(Capabilities, TheLoopRatesAreOnesTheRuntimeCanRun) {
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        const Capabilities c = capabilities_for(p);
        EXPECT_EQ(c.loop_rate_hz, kDefaultLoopRateHz) << p.name;  // 1 kHz, §2.2
        EXPECT_GE(c.max_loop_rate_hz, c.loop_rate_hz) << p.name;
        EXPECT_LE(c.max_loop_rate_hz, kMaxLoopRateHz) << p.name;
        if (c.device_class == sim::DeviceClass::iforce2) {
            EXPECT_GE(c.max_loop_rate_hz, 10000) << p.name;  // issue 5 §1: at least 10 kHz
        }
    }
}

// --- the two classes ---------------------------------------------------------------------

TEST(DeviceClasses, EveryBuiltInHasAClassAndBothClassesHaveAProfile) {
    EXPECT_EQ(sim::device_class_name(sim::DeviceClass::iforce1), "I-FORCE 1.x");
    EXPECT_EQ(sim::device_class_name(sim::DeviceClass::iforce2), "I-FORCE 2.0");
    EXPECT_EQ(profile("iforce1").device_class, sim::DeviceClass::iforce1);
    for (const char* name : {"joystick", "wheel", "3axis", "iforce2"}) {
        EXPECT_EQ(profile(name).device_class, sim::DeviceClass::iforce2) << name;
    }
}

TEST(DeviceClasses, Iforce1PlaysConditionsAndWavesButNoDynamics) {
    // §5.1: "I-FORCE 1.1 supported the basic notions of Conditions and Waves but did not
    // enable Dynamic Sensations". The master set of §6.4 has 10 Conditions, 15 Waves (with
    // constant) and 8 Dynamics.
    const Capabilities c = capabilities_for(profile("iforce1"));
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto t = static_cast<EffectType>(i);
        EXPECT_EQ(c.supports(t), effect_class(t) != EffectClass::dynamic) << effect_type_name(t);
    }
    EXPECT_TRUE(c.supports(EffectClass::condition));
    EXPECT_TRUE(c.supports(EffectClass::wave));
    EXPECT_FALSE(c.supports(EffectClass::dynamic));
    EXPECT_EQ(c.supported_type_count(), 10 + 15);
    EXPECT_FALSE(c.interim_reports);
    EXPECT_EQ(c.interim_report_hz, 0.0f);
}

TEST(DeviceClasses, Iforce1HasFewerSlotsAndLessMemoryAndNoLocalReflexes) {
    const Capabilities one = capabilities_for(profile("iforce1"));
    const Capabilities two = capabilities_for(profile("iforce2"));
    EXPECT_EQ(one.effect_slots, 16);
    EXPECT_EQ(one.pool_bytes, 4096);
    EXPECT_EQ(one.sample_memory, 4096 / 2);  // the whole pool at 2 bytes a sample
    EXPECT_LT(one.effect_slots, two.effect_slots);
    EXPECT_LT(one.pool_bytes, two.pool_bytes);
    EXPECT_FALSE(one.local_reflexes);  // §1.2.c: the host emulates them
    EXPECT_TRUE(two.local_reflexes);
    EXPECT_EQ(one.max_loop_rate_hz, 1000);
}

TEST(DeviceClasses, Iforce2PlaysAll33TypesOfTheMasterSet) {
    const Capabilities c = capabilities_for(profile("iforce2"));
    EXPECT_EQ(c.supported_types, kAllEffectTypes);
    EXPECT_EQ(c.supported_type_count(), 33);
    EXPECT_EQ(std::popcount(kAllEffectTypes), 33);
    for (EffectClass cls : {EffectClass::condition, EffectClass::wave, EffectClass::dynamic}) {
        EXPECT_TRUE(c.supports(cls)) << effect_class_label(cls);
    }
    Engine engine(sim::engine_config_for(profile("iforce2")));
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto t = static_cast<EffectType>(i);
        const CreateResult r = create(engine, valid_effect(t));
        ASSERT_TRUE(r.error.ok()) << effect_type_name(t) << ": " << r.error.message();
        ASSERT_TRUE(engine.destroy(r.id).ok());
    }
    // Dynamics report their mass at the primer's 60 Hz (§5.2).
    EXPECT_TRUE(c.interim_reports);
    EXPECT_EQ(c.interim_report_hz, 60.0f);
}

TEST(DeviceClasses, Iforce2IsTheJoystickWithItsClassNamed) {
    // iforce1 and iforce2 share the joystick's mechanics, so only the processor differs.
    const sim::DeviceProfile& stick = profile("joystick");
    for (const char* name : {"iforce1", "iforce2"}) {
        const sim::DeviceProfile& p = profile(name);
        ASSERT_EQ(p.axis_count, stick.axis_count) << name;
        for (int i = 0; i < p.axis_count; ++i) {
            EXPECT_EQ(p.axes[i].half_travel, stick.axes[i].half_travel) << name;
            EXPECT_EQ(p.axes[i].max_force, stick.axes[i].max_force) << name;
            EXPECT_EQ(p.axes[i].mass, stick.axes[i].mass) << name;
            EXPECT_EQ(p.axes[i].sensor_counts, stick.axes[i].sensor_counts) << name;
        }
        EXPECT_EQ(p.button_count, stick.button_count) << name;
        EXPECT_EQ(p.hat_count, stick.hat_count) << name;
        EXPECT_EQ(p.dead_man_switch, stick.dead_man_switch) << name;
    }
}

// --- the engine refuses what the device lacks --------------------------------------------

TEST(DeviceClasses, Iforce1RefusesEveryDynamicNamingTheTypeAndTheClassAndChangesNothing) {
    Engine engine(sim::engine_config_for(profile("iforce1")));
    ASSERT_TRUE(engine.create(valid_effect(EffectType::spring)).error.ok());
    const PoolInfo before = engine.pool();
    for (EffectType t : {EffectType::dynamic_recoil, EffectType::dynamic_impact, EffectType::dynamic_liquid,
                         EffectType::dynamic_inertia, EffectType::dynamic_center_drift,
                         EffectType::dynamic_control_law, EffectType::dynamic_sling, EffectType::dynamic_paddle}) {
        const CreateResult r = engine.create(valid_effect(t));
        EXPECT_EQ(r.error.code, ErrorCode::not_supported) << effect_type_name(t);
        EXPECT_FALSE(r.id.valid());
        const std::string message = r.error.message();
        EXPECT_NE(message.find(effect_type_name(t)), std::string::npos) << message;
        EXPECT_NE(message.find("I-FORCE 1.x"), std::string::npos) << message;
        EXPECT_NE(message.find("not supported"), std::string::npos) << message;
    }
    const PoolInfo after = engine.pool();
    EXPECT_EQ(after.free_bytes, before.free_bytes);
    EXPECT_EQ(after.free_effects, before.free_effects);
}

TEST(DeviceClasses, Iforce1HoldsSixteenEffectsThenIsFull) {
    Engine engine(sim::engine_config_for(profile("iforce1")));
    for (int i = 0; i < 16; ++i) ASSERT_TRUE(engine.create(enveloped_sine()).error.ok()) << i;
    EXPECT_EQ(engine.pool().free_bytes, 4096 - 16 * kEnvelopedSineBytes);
    EXPECT_EQ(engine.pool().free_effects, 0);
    EXPECT_EQ(engine.create(enveloped_sine()).error.code, ErrorCode::device_full);
}

TEST(DeviceClasses, Iforce1sFourKiBAreTheLimitOfItsForceProfiles) {
    // 15 enveloped sines and one one-channel force profile: effect 14 + custom 8 + 2 bytes
    // a sample. The largest profile that fits is (4096 − 15·40 − 22) / 2 = 1737 samples.
    Engine engine(sim::engine_config_for(profile("iforce1")));
    for (int i = 0; i < 15; ++i) ASSERT_TRUE(engine.create(enveloped_sine()).error.ok()) << i;
    const int32_t fits = (4096 - 15 * kEnvelopedSineBytes - 14 - 8) / 2;
    ASSERT_EQ(fits, 1737);
    EffectParams force_profile = valid_effect(EffectType::force_profile);
    force_profile.custom.sample_count = fits + 1;
    const CreateResult too_big = engine.create(force_profile, std::vector<int16_t>(fits + 1, 100));
    EXPECT_EQ(too_big.error.code, ErrorCode::device_full) << too_big.error.message();
    force_profile.custom.sample_count = fits;
    ASSERT_TRUE(engine.create(force_profile, std::vector<int16_t>(fits, 100)).error.ok());
    // What every resident effect costs adds up to the pool: 15·40 + 14 + 8 + 2·1737 = 4096.
    const PoolInfo pool = engine.pool();
    EXPECT_EQ(pool.total_bytes - pool.free_bytes, 15 * kEnvelopedSineBytes + 14 + 8 + 2 * fits);
    EXPECT_EQ(pool.free_bytes, 0);
    EXPECT_EQ(pool.free_effects, 0);
}

TEST(EngineSupportedTypes, TheDefaultIsEveryTypeAndAMaskLimitsCreate) {
    EXPECT_EQ(EngineConfig{}.supported_types, kAllEffectTypes);
    EngineConfig config;
    config.supported_types = effect_type_bit(EffectType::sine);
    Engine engine(config);
    EXPECT_TRUE(engine.create(valid_effect(EffectType::sine)).error.ok());
    const CreateResult spring = engine.create(valid_effect(EffectType::spring));
    EXPECT_EQ(spring.error.code, ErrorCode::not_supported);
    const std::string message = spring.error.message();
    EXPECT_NE(message.find("spring"), std::string::npos) << message;
    EXPECT_NE(message.find("this device"), std::string::npos) << message;
}

TEST(EngineSupportedTypes, BitsBeyondTheTypesMakeAnInvalidConfig) {
    EngineConfig config;
    config.supported_types = kAllEffectTypes | (uint64_t{1} << kEffectTypeCount);
    Engine engine(config);
    const CreateResult r = engine.create(valid_effect(EffectType::sine));
    EXPECT_EQ(r.error.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(r.error.field, "supported_types");
}

TEST(EngineSupportedTypes, ALongDeviceClassIsCutNotOverflowed) {
    EngineConfig config;
    config.supported_types = 0;
    config.device_class = "a device class whose name is much longer than any error field can hold";
    Engine engine(config);
    const CreateResult r = engine.create(valid_effect(EffectType::dynamic_center_drift));
    EXPECT_EQ(r.error.code, ErrorCode::not_supported);
    const std::string field = r.error.field;
    EXPECT_EQ(field.size(), sizeof(r.error.field) - 1);
    EXPECT_EQ(field.rfind("type dynamic_center_drift on a device class", 0), 0u) << field;
}

// --- EnumEffects -------------------------------------------------------------------------

TEST(EnumEffects, VisitsTheSupportedTypesInTheOrderOfTheMasterSet) {
    const Capabilities c = capabilities_for(profile("iforce1"));
    std::vector<EffectType> seen;
    const int32_t n = enum_effects(c, [&](EffectType t) {
        seen.push_back(t);
        return true;
    });
    ASSERT_EQ(n, 25);
    ASSERT_EQ(seen.size(), 25u);
    EXPECT_EQ(seen.front(), EffectType::spring);
    EXPECT_EQ(seen.back(), EffectType::ramp);
    for (size_t i = 1; i < seen.size(); ++i) EXPECT_LT(seen[i - 1], seen[i]);
}

TEST(EnumEffects, FiltersByClassAndStopsWhenAsked) {
    const Capabilities c = capabilities_for(profile("iforce2"));
    std::vector<EffectType> dynamics;
    EXPECT_EQ(enum_effects(c, [&](EffectType t) { dynamics.push_back(t); return true; },
                           EffectClass::dynamic), 8);
    for (EffectType t : dynamics) EXPECT_EQ(effect_class(t), EffectClass::dynamic);
    EXPECT_EQ(enum_effects(c, [](EffectType) { return true; }, EffectClass::condition), 10);
    EXPECT_EQ(enum_effects(c, [](EffectType) { return true; }, EffectClass::wave), 15);
    int calls = 0;
    EXPECT_EQ(enum_effects(c, [&](EffectType) { return ++calls < 3; }), 3);
    EXPECT_EQ(calls, 3);
    const Capabilities one = capabilities_for(profile("iforce1"));
    EXPECT_EQ(enum_effects(one, [](EffectType) { return true; }, EffectClass::dynamic), 0);
}

// --- profiles that are not usable ---------------------------------------------------------

TEST(DeviceProfileProcessor, EveryBadFieldIsNamedWithItsRange) {
    const sim::DeviceProfile good = profile("iforce1");
    struct Case {
        void (*mutate)(sim::DeviceProfile&);
        const char* message;
    };
    const Case cases[] = {
        {[](sim::DeviceProfile& p) { p.hat_count = 5; }, "hat_count = 5 is out of range (allowed 0..4)"},
        {[](sim::DeviceProfile& p) { p.effect_slots = 0; }, "effect_slots = 0 is out of range (allowed 1..65535)"},
        {[](sim::DeviceProfile& p) { p.pool_bytes = 0; }, "pool_bytes = 0 is out of range (allowed 1..1073741824)"},
        {[](sim::DeviceProfile& p) { p.sample_memory = -1; },
         "sample_memory = -1 is out of range (allowed 0..16777216)"},
        {[](sim::DeviceProfile& p) { p.max_loop_rate_hz = 50000; },
         "max_loop_rate_hz = 50000 is out of range (allowed 100..20000)"},
        {[](sim::DeviceProfile& p) { p.default_loop_rate_hz = 2000; },
         "default_loop_rate_hz = 2000 is out of range (allowed 100..1000)"},
        {[](sim::DeviceProfile& p) { p.supported_types = 0; },
         "supported_types = 0x0 is out of range (allowed a non-empty set of the 33 effect types, bits 0..32)"},
        {[](sim::DeviceProfile& p) { p.supported_types = uint64_t{1} << 40; },
         "supported_types = 0x10000000000 is out of range (allowed a non-empty set of the 33 effect types, "
         "bits 0..32)"},
        {[](sim::DeviceProfile& p) { p.firmware_version = ""; },
         "firmware_version is empty (allowed a non-empty name)"},
    };
    for (const Case& c : cases) {
        sim::DeviceProfile p = good;
        c.mutate(p);
        EXPECT_EQ(sim::check_device_profile(p), c.message);
        try {
            (void)capabilities_for(p);
            ADD_FAILURE() << "capabilities_for accepted: " << c.message;
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()), std::string("device profile \"iforce1\": ") + c.message);
        }
    }
}

// --- the text form ------------------------------------------------------------------------

// The value of the line "KEY: value" (leading spaces of the key and the padding ignored);
// "" when there is no such line.
std::string value_of(const std::string& text, const std::string& key) {
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        const size_t start = line.find_first_not_of(' ');
        if (start == std::string::npos || line.compare(start, key.size() + 1, key + ":") != 0) continue;
        const size_t value = line.find_first_not_of(' ', start + key.size() + 1);
        return value == std::string::npos ? "" : line.substr(value);
    }
    return "";
}

TEST(PrintCapabilities, TellsTheFactsOfAnIforce1) {
    const std::string text = format_capabilities(capabilities_for(profile("iforce1")));
    EXPECT_EQ(value_of(text, "device"), "iforce1") << text;
    EXPECT_EQ(value_of(text, "class"), "I-FORCE 1.x") << text;
    EXPECT_EQ(value_of(text, "firmware"), "feel-sim 0.1.0") << text;
    EXPECT_EQ(value_of(text, "protocol"), "HID PID 1.0 + feel vendor 2") << text;
    EXPECT_EQ(value_of(text, "axes"), "2") << text;
    EXPECT_EQ(value_of(text, "buttons"), "4") << text;
    EXPECT_EQ(value_of(text, "hats"), "2") << text;
    EXPECT_EQ(value_of(text, "effect slots"), "16") << text;
    EXPECT_EQ(value_of(text, "parameter memory"), "4096 bytes") << text;
    EXPECT_EQ(value_of(text, "sample memory"), "2048 samples") << text;
    EXPECT_EQ(value_of(text, "local reflexes"), "no (the host emulates them)") << text;
    EXPECT_EQ(value_of(text, "loop rate"), "1000 Hz (max 1000 Hz)") << text;
    EXPECT_EQ(value_of(text, "interim reports"), "none (no Dynamics)") << text;
    EXPECT_EQ(value_of(text, "effect types"), "25 of 33") << text;
    EXPECT_EQ(value_of(text, "Dynamics"), "none") << text;
    EXPECT_EQ(value_of(text, "Conditions").rfind("(10) spring", 0), 0u) << text;
    EXPECT_EQ(value_of(text, "Waves").rfind("(15) vector_force", 0), 0u) << text;
    EXPECT_NE(value_of(text, "x").find("max force 4.45 N"), std::string::npos) << text;
    for (int i = 0; i < kEffectTypeCount; ++i) {
        const auto t = static_cast<EffectType>(i);
        const bool listed = text.find(" " + std::string(effect_type_name(t))) != std::string::npos;
        EXPECT_EQ(listed, effect_class(t) != EffectClass::dynamic) << effect_type_name(t);
    }
}

TEST(PrintCapabilities, AWheelShowsDegreesAndNewtonMetres) {
    const std::string text = format_capabilities(capabilities_for(profile("wheel")));
    for (const char* fact : {"rotary", "±450°", "2.5 N·m", "33 of 33", "60 Hz"}) {
        EXPECT_NE(text.find(fact), std::string::npos) << fact << " in\n" << text;
    }
}

}  // namespace
}  // namespace feel::runtime
