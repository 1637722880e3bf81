// IDF in closed loop (issue 5 §7, primer §1.2.d): the simulated joystick, held by a firm hand
// that aims at a fixed target, plays a vibration (10 to 50 Hz) or a train of jolts. The hand
// feels every effect; with IDF on, the position reported to the host must stay steady:
//
//   * jitter: the RMS deviation of the reported position from the hand's target falls by at
//     least 5x against IDF off (which reports the sensed position);
//   * tracking: when the hand moves on purpose (a slow sine, a ramp) under the same
//     disturbances, the reported position is no more than 20 ms late against the handle's
//     motion in the same run without any effect, by cross-correlation and by the time a
//     threshold is crossed.
//
// The loop is the runtime's pipeline reduced to what matters here: sense, engine tick,
// engine activity, IDF, motors. The motors get the engine's force computed from the sensed
// position; only the report is filtered, so one run gives IDF off (the sensed position) and
// IDF on (the filter's output) side by side. The truth is physical: the target the hand
// holds, and the same hand's motion without effects. The simulated device has what the model
// leaves out (dry friction with sticking, end stops, a quantizing sensor, a motor limit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "feel/engine.hpp"
#include "feel/runtime/idf.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/sim_device.hpp"
#include "runtime_tick.hpp"

namespace feel::test {
namespace {

using runtime::IdfConfig;
using runtime::IdfFilter;
using runtime::IdfSettings;

using test_support::kTickS;
using test_support::kTickUs;

const sim::DeviceProfile& joystick() { return *sim::find_device_profile("joystick"); }

// One sensor step of the joystick, position units.
constexpr double kSensorStep = 20000.0 / 4096;

EffectParams on_xy(EffectType type, int64_t duration_us, int32_t polar_angle) {
    EffectParams p;
    p.type = type;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = polar_angle;
    p.duration_us = duration_us;
    return p;
}

EffectParams vibration(EffectType type, double hz, int32_t magnitude = 10000) {
    EffectParams p = on_xy(type, kInfiniteUs, 3000);  // from 30°: both axes shake
    p.periodic.magnitude = magnitude;
    p.periodic.period_us = std::llround(1e6 / hz);
    return p;
}

// A jolt: one push of `magnitude` lasting `length_us`, from the north-east.
EffectParams jolt(EffectType type, int32_t magnitude, int64_t length_us) {
    EffectParams p = on_xy(type, length_us, 4500);
    p.constant.magnitude = magnitude;
    return p;
}

std::vector<int64_t> every(int64_t first_us, int64_t period_us, int64_t until_us) {
    std::vector<int64_t> starts;
    for (int64_t t = first_us; t < until_us; t += period_us) starts.push_back(t);
    return starts;
}

struct Played {
    EffectParams params;
    std::vector<int64_t> starts_us;  // the effect is (re)started at each of these ticks
};

struct Scenario {
    sim::Grip grip = sim::Grip::firm;
    sim::TargetMotion motion = sim::TargetMotion::hold_at({1500.0, -800.0});
    std::vector<Played> effects;
    double seconds = 1.5;
    IdfSettings settings{.periodic = true, .impulse = true};
    IdfConfig config = runtime::idf_config_for(joystick());  // a firm hand's prior
};

struct Trace {
    std::vector<double> t_s;
    std::vector<double> sensed[2];    // what IDF off reports
    std::vector<double> reported[2];  // what IDF on reports
    std::vector<double> target[2];    // where the hand aims
    std::vector<double> force[2];     // what the motors got
};

Trace run(const Scenario& sc) {
    const sim::DeviceProfile& profile = joystick();
    Engine engine(sim::engine_config_for(profile));
    sim::SimDevice device(profile, sc.grip, sc.motion);
    IdfConfig config = sc.config;
    config.settings = sc.settings;
    IdfFilter idf(config);
    EXPECT_TRUE(idf.error().ok()) << idf.error().message();

    std::vector<EffectId> ids;
    for (const Played& e : sc.effects) {
        const CreateResult r = engine.create(e.params);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        ids.push_back(r.id);
    }
    Trace trace;
    const int64_t ticks = std::llround(sc.seconds / kTickS);
    for (int64_t n = 0; n < ticks; ++n) {
        const int64_t t_us = n * kTickUs;
        for (size_t e = 0; e < ids.size(); ++e) {
            const std::vector<int64_t>& starts = sc.effects[e].starts_us;
            if (std::find(starts.begin(), starts.end(), t_us) != starts.end()) {
                EXPECT_TRUE(engine.start(ids[e]).ok());
            }
        }
        TickInput in;
        in.t_us = t_us;
        device.sense(in);
        TickOutput out;
        engine.tick(in, out);
        EngineActivity activity;
        engine.activity(activity);
        runtime::fit_activity_to_output(activity, out);  // the motor's limit clips big sums
        float reported[kMaxAxes];
        idf.filter(t_us, in.position, activity, reported);
        const sim::TargetMotion::Sample target = device.motion().at(device.time_s());
        trace.t_s.push_back(static_cast<double>(t_us) * 1e-6);
        for (int a = 0; a < 2; ++a) {
            trace.sensed[a].push_back(in.position[a]);
            trace.reported[a].push_back(reported[a]);
            trace.target[a].push_back(target.position[a]);
            trace.force[a].push_back(out.force[a]);
        }
        device.step(out.force, kTickS);
    }
    return trace;
}

using Series = std::vector<double>[2];

// RMS over both axes of (a − b) for t in [from_s, to_s).
double rms_between(const Trace& tr, const Series& a, const Series& b, double from_s, double to_s) {
    double sum = 0;
    int n = 0;
    for (size_t i = 0; i < tr.t_s.size(); ++i) {
        if (tr.t_s[i] < from_s || tr.t_s[i] >= to_s) continue;
        for (int ax = 0; ax < 2; ++ax) sum += (a[ax][i] - b[ax][i]) * (a[ax][i] - b[ax][i]);
        ++n;
    }
    return std::sqrt(sum / std::max(n, 1));
}

// RMS over both axes of (a − b) minus its centered mean over window_ticks: the fast part of
// the difference, the jitter, without slow drifts.
double jitter_between(const Trace& tr, const Series& a, const Series& b, double from_s, double to_s,
                      int window_ticks) {
    double sum = 0;
    int n = 0;
    const int half = window_ticks / 2;
    for (size_t i = half; i + half < tr.t_s.size(); ++i) {
        if (tr.t_s[i] < from_s || tr.t_s[i] >= to_s) continue;
        for (int ax = 0; ax < 2; ++ax) {
            double mean = 0;
            for (int k = -half; k <= half; ++k) mean += a[ax][i + k] - b[ax][i + k];
            mean /= 2 * half + 1;
            const double d = a[ax][i] - b[ax][i] - mean;
            sum += d * d;
        }
        ++n;
    }
    return std::sqrt(sum / std::max(n, 1));
}

// The delay of `signal` behind `reference` that best aligns them (least squares over shifts
// of whole ticks within ±max_shift, refined by a parabola through the best three), s.
double lag_s(const std::vector<double>& reference, const std::vector<double>& signal, size_t from, size_t to,
             int max_shift) {
    std::vector<double> cost;
    for (int shift = -max_shift; shift <= max_shift; ++shift) {
        double c = 0;
        for (size_t i = from; i < to; ++i) c += std::pow(signal[i + shift] - reference[i], 2);
        cost.push_back(c);
    }
    const size_t best = static_cast<size_t>(std::min_element(cost.begin(), cost.end()) - cost.begin());
    double refined = static_cast<double>(best);
    if (best > 0 && best + 1 < cost.size()) {
        const double a = cost[best - 1], b = cost[best], c = cost[best + 1];
        if (a - 2 * b + c > 0) refined += 0.5 * (a - c) / (a - 2 * b + c);
    }
    return (refined - max_shift) * kTickS;
}

// The first time at or after from_s that `signal` reaches `level` going up, s (linear
// interpolation between ticks); -1 if never.
double crossing_s(const Trace& tr, const std::vector<double>& signal, double level, double from_s) {
    for (size_t i = 1; i < tr.t_s.size(); ++i) {
        if (tr.t_s[i] < from_s) continue;
        if (signal[i - 1] < level && signal[i] >= level) {
            return tr.t_s[i - 1] + kTickS * (level - signal[i - 1]) / (signal[i] - signal[i - 1]);
        }
    }
    return -1;
}

// --- Jitter at a fixed target ---------------------------------------------------------------

struct VibrationCase {
    EffectType type;
    double hz;
};

class IdfVibration : public ::testing::TestWithParam<VibrationCase> {};

TEST_P(IdfVibration, JitterAtAFixedTargetFallsFiveFold) {
    const VibrationCase c = GetParam();
    Scenario sc;
    sc.effects = {{vibration(c.type, c.hz), {200'000}}};
    const Trace tr = run(sc);
    // From the vibration's onset on: the onset's transient counts too.
    const double off = rms_between(tr, tr.sensed, tr.target, 0.2, sc.seconds);
    const double on = rms_between(tr, tr.reported, tr.target, 0.2, sc.seconds);
    std::printf("[ IDF      ] %s %.0f Hz at a fixed target: jitter off %.2f, on %.2f, %.1fx\n",
                std::string(effect_type_name(c.type)).c_str(), c.hz, off, on, off / on);
    // The hand feels it: the handle really shakes, by several sensor steps.
    EXPECT_GT(off, 4 * kSensorStep);
    EXPECT_GE(off / on, 5.0) << "off " << off << ", on " << on;
}

INSTANTIATE_TEST_SUITE_P(TenToFiftyHz, IdfVibration,
                         ::testing::Values(VibrationCase{EffectType::sine, 10}, VibrationCase{EffectType::sine, 20},
                                           VibrationCase{EffectType::sine, 30}, VibrationCase{EffectType::sine, 40},
                                           VibrationCase{EffectType::sine, 50},
                                           VibrationCase{EffectType::square, 15},
                                           VibrationCase{EffectType::triangle, 25},
                                           VibrationCase{EffectType::saw_up, 45}),
                         [](const ::testing::TestParamInfo<VibrationCase>& p) {
                             return std::string(effect_type_name(p.param.type)) + "_" +
                                    std::to_string(static_cast<int>(p.param.hz)) + "Hz";
                         });

TEST(IdfClosedLoop, JitterUnderAJoltTrainFallsFiveFold) {
    struct Train {
        EffectType type;
        int64_t length_us, period_us;
    };
    for (const Train t : {Train{EffectType::constant, 30'000, 250'000}, Train{EffectType::smart_pop, 60'000, 300'000},
                          Train{EffectType::vector_force, 15'000, 120'000}}) {
        Scenario sc;
        sc.seconds = 2.2;
        sc.effects = {{jolt(t.type, 10000, t.length_us), every(200'000, t.period_us, 2'000'000)}};
        const Trace tr = run(sc);
        const double off = rms_between(tr, tr.sensed, tr.target, 0.2, sc.seconds);
        const double on = rms_between(tr, tr.reported, tr.target, 0.2, sc.seconds);
        std::printf("[ IDF      ] %s jolts of %lld ms every %lld ms: jitter off %.2f, on %.2f, %.1fx\n",
                    std::string(effect_type_name(t.type)).c_str(), static_cast<long long>(t.length_us / 1000),
                    static_cast<long long>(t.period_us / 1000), off, on, off / on);
        EXPECT_GT(off, 20 * kSensorStep);  // each jolt throws the handle far
        EXPECT_GE(off / on, 5.0) << effect_type_name(t.type);
    }
}

// --- Deliberate motion passes, in time ------------------------------------------------------

struct Disturbance {
    const char* name;
    std::vector<Played> effects;
};

std::vector<Disturbance> disturbances() {
    return {
        {"10 Hz sine", {{vibration(EffectType::sine, 10), {200'000}}}},
        {"30 Hz square", {{vibration(EffectType::square, 30), {200'000}}}},
        {"50 Hz sine", {{vibration(EffectType::sine, 50), {200'000}}}},
        {"jolt train", {{jolt(EffectType::constant, 10000, 30'000), every(200'000, 250'000, 3'000'000)}}},
    };
}

TEST(IdfClosedLoop, DeliberateMotionIsNotLate) {
    // A slow sine, the way a player sweeps the aim across the screen.
    Scenario base;
    base.motion = sim::TargetMotion::parse("sine:x:3000:1", 3, 2);
    base.seconds = 3;
    const Trace undisturbed = run(base);
    for (const Disturbance& d : disturbances()) {
        Scenario sc = base;
        sc.effects = d.effects;
        const Trace tr = run(sc);
        const double lag = lag_s(undisturbed.sensed[0], tr.reported[0], 300, 2900, 60);
        const double jitter_off = jitter_between(tr, tr.sensed, undisturbed.sensed, 0.3, 2.9, 100);
        const double jitter_on = jitter_between(tr, tr.reported, undisturbed.sensed, 0.3, 2.9, 100);
        std::printf("[ IDF      ] sweeping aim under %s: lag %.2f ms; jitter off %.2f, on %.2f, %.1fx\n", d.name,
                    lag * 1e3, jitter_off, jitter_on, jitter_off / jitter_on);
        EXPECT_LE(std::fabs(lag), 0.020) << d.name;
        // The sweep is reported without the shaking (a weaker bound than at a fixed target:
        // the moving handle's friction is only approximately modelled).
        EXPECT_GE(jitter_off / jitter_on, 2.5) << d.name;
    }
}

TEST(IdfClosedLoop, ARampCrossesItsMarkOnTime) {
    // A steady move from one side to the other: when does the report cross the middle?
    Scenario base;
    base.motion = sim::TargetMotion::parse("ramp:x:-3000:3000", 2, 2);
    base.seconds = 2;
    const Trace undisturbed = run(base);
    const double t_undisturbed = crossing_s(undisturbed, undisturbed.sensed[0], 0, 0.3);
    ASSERT_GT(t_undisturbed, 0);
    for (const Disturbance& d : disturbances()) {
        Scenario sc = base;
        sc.effects = d.effects;
        const Trace tr = run(sc);
        const double t_on = crossing_s(tr, tr.reported[0], 0, 0.3);
        std::printf("[ IDF      ] ramp under %s: crosses the middle %.2f ms after the undisturbed handle\n",
                    d.name, (t_on - t_undisturbed) * 1e3);
        ASSERT_GT(t_on, 0) << d.name;
        EXPECT_LE(t_on - t_undisturbed, 0.020) << d.name;
        EXPECT_GE(t_on - t_undisturbed, -0.020) << d.name;
    }
}

// --- The player's choice, per class ---------------------------------------------------------

TEST(IdfClosedLoop, EachClassIsFilteredOnItsOwn) {
    // A vibration and a jolt train together. Filtering one class must report the handle as
    // it moves under the other class alone (a separate run with only that class, IDF off).
    const Played shake{vibration(EffectType::sine, 25, 7000), {200'000}};
    const Played jolts{jolt(EffectType::constant, 8000, 30'000), every(200'000, 300'000, 2'000'000)};
    Scenario both;
    both.seconds = 2;
    both.effects = {shake, jolts};
    Scenario only_jolts = both;
    only_jolts.effects = {jolts};
    Scenario only_shake = both;
    only_shake.effects = {shake};
    const Trace jolts_alone = run(only_jolts);
    const Trace shake_alone = run(only_shake);

    both.settings = {.periodic = true, .impulse = false};
    const Trace keep_jolts = run(both);
    const double jolt_size = rms_between(jolts_alone, jolts_alone.sensed, jolts_alone.target, 0.2, 2);
    const double kept = rms_between(keep_jolts, keep_jolts.reported, jolts_alone.sensed, 0.2, 2);
    std::printf("[ IDF      ] periodic only: reported vs jolts alone %.2f (jolts move %.2f)\n", kept, jolt_size);
    EXPECT_LT(kept, jolt_size / 5);

    both.settings = {.periodic = false, .impulse = true};
    const Trace keep_shake = run(both);
    const double shake_size = rms_between(shake_alone, shake_alone.sensed, shake_alone.target, 0.2, 2);
    const double kept_shake = rms_between(keep_shake, keep_shake.reported, shake_alone.sensed, 0.2, 2);
    std::printf("[ IDF      ] impulse only: reported vs shake alone %.2f (shake moves %.2f)\n", kept_shake,
                shake_size);
    EXPECT_LT(kept_shake, shake_size / 5);

    // And the motors never see the filter: the same forces whatever the player chose.
    for (int a = 0; a < 2; ++a) EXPECT_EQ(keep_jolts.force[a], keep_shake.force[a]);
}

// --- Another hand than the prior ------------------------------------------------------------

TEST(IdfClosedLoop, LearnsALooseOrAStiffHand) {
    // The prior is a firm grip. A loose hand is a quarter as stiff, a braced one almost four
    // times stiffer and half again as heavy: the prior alone mispredicts their response.
    // After three seconds of disturbances the identified plant has caught up.
    struct Case {
        sim::Grip grip;
        bool jolts;
        bool five_fold;  // the bar; see below for the one case that does not reach it
    };
    for (const Case c : {Case{sim::Grip::stiff, false, true}, Case{sim::Grip::stiff, true, true},
                         Case{sim::Grip::loose, false, true}, Case{sim::Grip::loose, true, false}}) {
        Scenario sc;
        sc.grip = c.grip;
        sc.seconds = 4;
        sc.effects = c.jolts ? std::vector<Played>{{jolt(EffectType::constant, 5000, 30'000),
                                                    every(200'000, 250'000, 4'000'000)}}
                             : std::vector<Played>{{vibration(EffectType::square, 30, 8000), {200'000}}};
        const Trace tr = run(sc);
        const double off = rms_between(tr, tr.sensed, tr.target, 3, 4);
        const double on = rms_between(tr, tr.reported, tr.target, 3, 4);
        Scenario fixed = sc;
        fixed.config.adapt = false;
        const Trace prior_only = run(fixed);
        const double on_prior = rms_between(prior_only, prior_only.reported, prior_only.target, 3, 4);
        const std::string name = std::string(sim::grip_name(c.grip)) + (c.jolts ? " hand, jolts" : " hand, 30 Hz square");
        std::printf("[ IDF      ] %s: jitter off %.2f, learnt %.2f (%.1fx), prior only %.2f (%.1fx)\n", name.c_str(),
                    off, on, off / on, on_prior, off / on_prior);
        EXPECT_LT(on, on_prior / 2) << name;
        if (c.five_fold) {
            EXPECT_GE(off / on, 5.0) << name;
        }
    }
    // A loose hand's own resonance (about 3.5 Hz on the joystick) lies among deliberate
    // motions, below the identification's separation frequency, so jolts that mostly ring it
    // are learnt only in part. With the prior set for a light touch, the bar is met.
    Scenario loose;
    loose.grip = sim::Grip::loose;
    loose.seconds = 3;
    loose.config = runtime::idf_config_for(joystick(), joystick().loose);
    loose.effects = {{jolt(EffectType::constant, 5000, 30'000), every(200'000, 250'000, 3'000'000)}};
    const Trace tr = run(loose);
    const double off = rms_between(tr, tr.sensed, tr.target, 0.2, 3);
    const double on = rms_between(tr, tr.reported, tr.target, 0.2, 3);
    std::printf("[ IDF      ] loose hand, jolts, loose prior: jitter off %.2f, on %.2f (%.1fx)\n", off, on, off / on);
    EXPECT_GE(off / on, 5.0);
}

}  // namespace
}  // namespace feel::test
