// Every integer parameter of every §8 wrapper, at each end of its range and one step
// beyond: at the ends the effect is built and the engine's validate_effect accepts it;
// beyond, the wrapper throws std::invalid_argument naming itself, the parameter, the value
// and the range. The ranges below are copied from §8's tables (and, where the wrapper
// documents that the engine's range wins, from units.hpp), not from the wrappers' code.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "feel/iforce.hpp"
#include "iforce_test_util.hpp"

namespace feel::iforce {
namespace {

using test::engine_accepts;
using test::throws_message;

struct Param {
    std::string name;
    int64_t min;
    int64_t max;
    int64_t valid;            // a value inside the range used while other parameters vary
    std::string suffix = "";  // appended to the range in the message (durations)
};

struct WrapperCase {
    std::string name;
    std::vector<Param> params;
    std::function<EffectParams(const std::vector<int64_t>&)> call;
};

int32_t i32(int64_t v) { return static_cast<int32_t>(v); }

// §8.2
const Param kK(const std::string& n) { return {n, -10000, 10000, 1000}; }
const Param kOffset(const std::string& n) { return {n, -10000, 10000, 0}; }
const Param kSat(const std::string& n) { return {n, 0, 10000, 10000}; }
const Param kDeadband(const std::string& n) { return {n, 0, 10000, 0}; }
const Param kAngle(const std::string& n) { return {n, 0, 35999, 9000}; }
const Param kPositive(const std::string& n) { return {n, 1, 10000, 5000}; }
const Param kLevel(const std::string& n) { return {n, 0, 10000, 3000}; }
// §8.3
const Param kMagnitude{"magnitude", 1, 10000, 5000};
const Param kWaveOffset{"offset", 0, 10000, 0};
const Param kPhase{"phase", 0, 35999, 0};
const Param kPeriod{"period_us", 1, 65000000, 10000};
const Param kFiniteDuration{"duration_us", 1, 65000000, 500000};
const Param kAnyDuration{"duration_us", 1, 65000000, 500000, ", or kInfiniteUs for no end"};
const Param kRepeat{"trigger_repeat_interval_us", 0, 65000000, 0};
const Param kImpulse{"impulse_level", 0, 10000, 8000};
const Param kSettle{"settle_time_us", 1, 65000000, 20000};
const Param kFade{"fade_level", 0, 10000, 0};
const Param kFadeTime{"fade_time_us", 1, 65000000, 20000};
// §8.4
const Param kMass(const std::string& n) { return {n, 1, 10000, 5000}; }
const Param kStiff(const std::string& n) { return {n, 1, 10000, 5000}; }
const Param kDamp(const std::string& n) { return {n, 0, 10000, 500}; }
const Param kSigned(const std::string& n) { return {n, -10000, 10000, 2000}; }

std::vector<WrapperCase> cases() {
    using V = const std::vector<int64_t>&;
    const std::vector<Param> one_axis = {kK("k_pos"), kK("k_neg"), kOffset("offset"),
                                         kSat("pos_saturation"), kSat("neg_saturation"), kDeadband("deadband")};
    const std::vector<Param> one_damper = {kK("b_pos"), kK("b_neg"), kOffset("offset"),
                                           kSat("pos_saturation"), kSat("neg_saturation"), kDeadband("deadband")};
    auto two_axes = [](const char* c) {
        std::vector<Param> ps;
        for (const char* a : {"x_", "y_"}) {
            const std::string p(a);
            ps.insert(ps.end(), {kK(p + c + "_pos"), kK(p + c + "_neg"), kOffset(p + "offset"),
                                 kSat(p + "pos_saturation"), kSat(p + "neg_saturation"), kDeadband(p + "deadband")});
        }
        return ps;
    };
    std::vector<Param> angle_spring_params = one_axis;
    angle_spring_params.push_back(kAngle("angle"));
    const std::vector<Param> symmetric = {kK("k"), kSat("saturation"), kDeadband("deadband")};
    const std::vector<Param> inertia_params = {{"mass", 1, 10000, 100}, {"saturation", 1, 10000, 10000}};

    return {
        // §8.2
        {"x_spring", one_axis, [](V a) { return x_spring(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5])); }},
        {"y_spring", one_axis, [](V a) { return y_spring(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5])); }},
        {"spring", two_axes("k"),
         [](V a) {
             return spring(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5]), i32(a[6]), i32(a[7]),
                           i32(a[8]), i32(a[9]), i32(a[10]), i32(a[11]));
         }},
        {"angle_spring", angle_spring_params,
         [](V a) { return angle_spring(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5]), i32(a[6])); }},
        {"center_spring", symmetric, [](V a) { return center_spring(i32(a[0]), i32(a[1]), i32(a[2])); }},
        {"spring_at_current_location", symmetric,
         [](V a) { return spring_at_current_location(i32(a[0]), i32(a[1]), i32(a[2])); }},
        {"x_damper", one_damper, [](V a) { return x_damper(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5])); }},
        {"y_damper", one_damper, [](V a) { return y_damper(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5])); }},
        {"damper", two_axes("b"),
         [](V a) {
             return damper(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5]), i32(a[6]), i32(a[7]),
                           i32(a[8]), i32(a[9]), i32(a[10]), i32(a[11]));
         }},
        {"x_inertia", inertia_params, [](V a) { return x_inertia(i32(a[0]), i32(a[1])); }},
        {"y_inertia", inertia_params, [](V a) { return y_inertia(i32(a[0]), i32(a[1])); }},
        {"inertia", inertia_params, [](V a) { return inertia(i32(a[0]), i32(a[1])); }},
        {"friction", {kLevel("f")}, [](V a) { return friction(i32(a[0])); }},
        {"x_friction", {kLevel("f_pos"), kLevel("f_neg")}, [](V a) { return x_friction(i32(a[0]), i32(a[1])); }},
        {"y_friction", {kLevel("f_pos"), kLevel("f_neg")}, [](V a) { return y_friction(i32(a[0]), i32(a[1])); }},
        {"texture", {kPositive("roughness"), kPositive("spacing"), kPositive("density"), kAngle("angle")},
         [](V a) { return texture(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3])); }},
        {"x_texture", {kPositive("roughness"), kPositive("spacing"), kPositive("density")},
         [](V a) { return x_texture(i32(a[0]), i32(a[1]), i32(a[2])); }},
        {"x_texture",
         {kPositive("pos_roughness"), kPositive("neg_roughness"), kPositive("spacing"), kPositive("density")},
         [](V a) { return x_texture(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3])); }},
        {"y_texture",
         {kPositive("pos_roughness"), kPositive("neg_roughness"), kPositive("spacing"), kPositive("density")},
         [](V a) { return y_texture(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3])); }},
        {"wall", {kK("hardness"), kOffset("offset"), kAngle("angle")},
         [](V a) { return wall(i32(a[0]), WallSense::positive, i32(a[1]), i32(a[2])); }},
        {"horizontal_wall", {kK("hardness"), kOffset("offset"), kLevel("surface_friction"), kLevel("surface_texture")},
         [](V a) { return horizontal_wall(i32(a[0]), WallSense::negative, i32(a[1]), i32(a[2]), i32(a[3]), true); }},
        {"vertical_wall", {kK("hardness"), kOffset("offset"), kLevel("surface_friction"), kLevel("surface_texture")},
         [](V a) { return vertical_wall(i32(a[0]), WallSense::positive, i32(a[1]), i32(a[2]), i32(a[3]), false); }},
        {"barrier", {kK("pos_hardness"), kK("neg_hardness"), kPositive("thickness"), kOffset("offset"), kAngle("angle")},
         [](V a) { return barrier(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4])); }},
        {"horizontal_barrier",
         {kK("pos_hardness"), kK("neg_hardness"), kPositive("thickness"), kOffset("offset"), kLevel("surface_friction"),
          kLevel("surface_texture")},
         [](V a) { return horizontal_barrier(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5])); }},
        {"vertical_barrier",
         {kK("pos_hardness"), kK("neg_hardness"), kPositive("thickness"), kOffset("offset"), kLevel("surface_friction"),
          kLevel("surface_texture")},
         [](V a) { return vertical_barrier(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5])); }},
        // §8.3
        {"vector_force", {kMagnitude, kAnyDuration, kAngle("direction")},
         [](V a) { return vector_force(i32(a[0]), a[1], i32(a[2])); }},
        {"constant_force", {kMagnitude, kFiniteDuration, kAngle("direction")},
         [](V a) { return constant_force(i32(a[0]), a[1], i32(a[2])); }},
        {"constant_force_trigger", {kMagnitude, kFiniteDuration, kAngle("direction"), kRepeat},
         [](V a) { return constant_force_trigger(i32(a[0]), a[1], i32(a[2]), button_trigger(1), a[3]); }},
        {"envelope_constant",
         {kMagnitude, kAnyDuration, kAngle("direction"), kImpulse, kSettle, kFade, kFadeTime, kRepeat},
         [](V a) {
             return envelope_constant(i32(a[0]), a[1], i32(a[2]), i32(a[3]), a[4], i32(a[5]), a[6], hat_trigger(4), a[7]);
         }},
        {"ramp", {kLevel("start"), kLevel("end"), kFiniteDuration, kAngle("direction"), kRepeat},
         [](V a) { return ramp(i32(a[0]), i32(a[1]), a[2], i32(a[3]), button_trigger(2), a[4]); }},
        {"ramp_envelope",
         {kLevel("start"), kLevel("end"), kFiniteDuration, kAngle("direction"), kImpulse, kSettle, kFade, kFadeTime,
          kRepeat},
         [](V a) {
             return ramp_envelope(i32(a[0]), i32(a[1]), a[2], i32(a[3]), i32(a[4]), a[5], i32(a[6]), a[7],
                                  button_trigger(2), a[8]);
         }},
        {"periodic", {kMagnitude, kWaveOffset, kPhase, kPeriod, kAnyDuration, kAngle("angle"), kRepeat},
         [](V a) {
             return periodic(Waveform::sine, i32(a[0]), i32(a[1]), i32(a[2]), a[3], a[4], i32(a[5]),
                             button_trigger(1), a[6]);
         }},
        {"envelope_periodic",
         {kMagnitude, kWaveOffset, kPhase, kPeriod, kAnyDuration, kAngle("angle"), kImpulse, kSettle, kFade, kFadeTime,
          kRepeat},
         [](V a) {
             return envelope_periodic(Waveform::square, i32(a[0]), i32(a[1]), i32(a[2]), a[3], a[4], i32(a[5]),
                                      i32(a[6]), a[7], i32(a[8]), a[9], button_trigger(1), a[10]);
         }},
        {"delayed_periodic",
         {{"pause_us", 0, 65000000, 1000}, kMagnitude, kWaveOffset, kPhase, kPeriod, kAnyDuration, kAngle("angle"),
          kRepeat},
         [](V a) {
             return delayed_periodic(a[0], Waveform::triangle, i32(a[1]), i32(a[2]), i32(a[3]), a[4], a[5], i32(a[6]),
                                     hat_trigger(1), a[7]);
         }},
        {"sweep_periodic",
         {kAngle("start_angle"), kAngle("stop_angle"), kMagnitude, kWaveOffset, kPeriod, kPhase, kFiniteDuration},
         [](V a) {
             return sweep_periodic(i32(a[0]), i32(a[1]), SweepSense::clockwise, Waveform::saw_up, i32(a[2]),
                                   i32(a[3]), a[4], i32(a[5]), a[6]);
         }},
        // §8.4
        {"dynamic_recoil",
         {kAngle("blast_direction"), kSigned("blast_intensity"), kMass("dynamic_mass"), kStiff("blast_resonance"),
          kDamp("blast_decay")},
         [](V a) { return dynamic_recoil(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4])); }},
        {"dynamic_impact",
         {kAngle("impact_direction"), kSigned("impact_intensity"), kMass("dynamic_mass"), kStiff("elasticity"),
          kDamp("collision_absorption")},
         [](V a) { return dynamic_impact(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4])); }},
        {"dynamic_liquid", {kMass("density"), kStiff("settle"), kDamp("viscosity")},
         [](V a) { return dynamic_liquid(i32(a[0]), i32(a[1]), i32(a[2])); }},
        {"dynamic_inertia", {kMass("inertia"), kDamp("play")},
         [](V a) { return dynamic_inertia(i32(a[0]), i32(a[1])); }},
        {"dynamic_center_drift", {kStiff("stiffness"), kDamp("drift_resistance")},
         [](V a) { return dynamic_center_drift(i32(a[0]), i32(a[1])); }},
        {"dynamic_sling",
         {kMass("ball_mass"), kDamp("string_length"), kStiff("string_compliance"), kDamp("ball_damping")},
         [](V a) { return dynamic_sling(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), true); }},
        {"dynamic_paddle",
         {kMass("ball_mass"), kSigned("initial_velocity"), kAngle("initial_velocity_direction"),
          kStiff("paddle_compliance"), kDamp("paddle_damping"), kSigned("gravity")},
         [](V a) { return dynamic_paddle(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5]), true); }},
        {"dynamic_control_law",
         {kMass("mass"), kStiff("k_pos"), kStiff("k_neg"), kDamp("b"), kSigned("vel_init"), kSigned("pos_init"),
          {"half_cycles", 0, 10000, 0}, kDamp("length"), kDamp("drag"), kSigned("gravity")},
         [](V a) {
             return dynamic_control_law(i32(a[0]), i32(a[1]), i32(a[2]), i32(a[3]), i32(a[4]), i32(a[5]), i32(a[6]),
                                        i32(a[7]), i32(a[8]), i32(a[9]), false, Axis::y);
         }},
    };
}

std::vector<int64_t> valid_args(const WrapperCase& w) {
    std::vector<int64_t> a;
    for (const Param& p : w.params) a.push_back(p.valid);
    return a;
}

std::string expected_message(const WrapperCase& w, const Param& p, int64_t value) {
    return w.name + ": " + p.name + " = " + std::to_string(value) + " is out of range (allowed " +
           std::to_string(p.min) + ".." + std::to_string(p.max) + ")" + p.suffix;
}

TEST(WrapperRanges, EveryWrapperIsCovered) {
    // The 42 names of the brief's list (x_texture twice: both overloads).
    EXPECT_EQ(cases().size(), 43u);
}

TEST(WrapperRanges, EveryWrapperBuildsAnEffectTheEngineAcceptsAtEachEndOfEveryRange) {
    for (const WrapperCase& w : cases()) {
        SCOPED_TRACE(w.name);
        EXPECT_TRUE(engine_accepts(w.call(valid_args(w))));
        for (size_t i = 0; i < w.params.size(); ++i) {
            const Param& p = w.params[i];
            for (int64_t v : {p.min, p.max}) {
                SCOPED_TRACE(p.name + " = " + std::to_string(v));
                std::vector<int64_t> a = valid_args(w);
                a[i] = v;
                EffectParams out;
                ASSERT_NO_THROW(out = w.call(a));
                EXPECT_TRUE(engine_accepts(out));
            }
        }
    }
}

TEST(WrapperRanges, EveryParameterOutOfRangeNamesTheWrapperItselfAndItsRange) {
    int checked = 0;
    for (const WrapperCase& w : cases()) {
        for (size_t i = 0; i < w.params.size(); ++i) {
            const Param& p = w.params[i];
            for (int64_t v : {p.min - 1, p.max + 1}) {
                std::vector<int64_t> a = valid_args(w);
                a[i] = v;
                EXPECT_TRUE(throws_message([&] { (void)w.call(a); }, expected_message(w, p, v)));
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 300);
}

TEST(WrapperRanges, TheBriefsExampleMessage) {
    EXPECT_TRUE(throws_message([] { (void)x_spring(1000, 1000, 0, 10000, 10000, 12000); },
                               "x_spring: deadband = 12000 is out of range (allowed 0..10000)"));
}

TEST(WrapperRanges, EnumsOutsideTheirValuesAreNamed) {
    EXPECT_TRUE(throws_message([] { (void)wall(1, static_cast<WallSense>(7), 0, 0); },
                               "wall: sense must be WallSense::positive or WallSense::negative"));
    EXPECT_TRUE(throws_message([] { (void)horizontal_wall(1, static_cast<WallSense>(7), 0, 0, 0, false); },
                               "horizontal_wall: sense must be WallSense::positive or WallSense::negative"));
    EXPECT_TRUE(throws_message(
        [] { (void)sweep_periodic(0, 1, static_cast<SweepSense>(5), Waveform::sine, 1, 0, 1, 0, 1); },
        "sweep_periodic: sense must be SweepSense::clockwise or SweepSense::counterclockwise"));
    EXPECT_TRUE(throws_message(
        [] { (void)dynamic_control_law(1, 1, 1, 0, 0, 0, 0, 0, 0, 0, false, static_cast<Axis>(6)); },
        "dynamic_control_law: axis = 6 is out of range (allowed 0..5)"));
}

}  // namespace
}  // namespace feel::iforce
