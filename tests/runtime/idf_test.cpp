// IdfFilter on synthetic signals, and Engine::activity.
//
// The truth is physics computed independently of the filter: the displacement a known force
// causes on a mass-spring-damper, integrated by fine-step RK4 with the force held over each
// tick (as a motor holds it), added to a deliberate motion the test writes down. The filter
// must report exactly the deliberate motion. Friction cases check the laws of dry friction
// (a push below the friction force does not move the handle). Engine::activity is checked
// against the engine's own output force and the primer's definitions of the two disturbances.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "feel/engine.hpp"
#include "feel/runtime/idf.hpp"
#include "feel/sim/device_profile.hpp"
#include "runtime_tick.hpp"

namespace feel::test {
namespace {

using runtime::IdfConfig;
using runtime::IdfFilter;
using runtime::IdfPlant;
using runtime::IdfSettings;

constexpr double kPi = std::numbers::pi;
using test_support::kTickS;
using test_support::kTickUs;

// The joystick held firmly, in normalized units (hand-computed from docs/simulated-device.md:
// 0.15 kg stick + 0.15 kg of hand, 0.5 + 6 N·s/m, 400 N/m; times 0.05 m / 4.45 N).
constexpr IdfPlant kFirm{.mass = 0.30 * 0.05 / 4.45, .damping = 6.5 * 0.05 / 4.45, .stiffness = 400 * 0.05 / 4.45};

// The displacement a held force causes, by RK4 on 20 substeps per tick.
class TruePlant {
public:
    explicit TruePlant(IdfPlant p) : p_(p) {}
    // Advances one tick with `force` held; returns the displacement at the tick's end.
    double step(double force) {
        const double h = kTickS / 20;
        auto accel = [&](double x, double v) { return (force - p_.damping * v - p_.stiffness * x) / p_.mass; };
        for (int i = 0; i < 20; ++i) {
            const double k1x = v_, k1v = accel(x_, v_);
            const double k2x = v_ + h / 2 * k1v, k2v = accel(x_ + h / 2 * k1x, v_ + h / 2 * k1v);
            const double k3x = v_ + h / 2 * k2v, k3v = accel(x_ + h / 2 * k2x, v_ + h / 2 * k2v);
            const double k4x = v_ + h * k3v, k4v = accel(x_ + h * k3x, v_ + h * k3v);
            x_ += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
            v_ += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        }
        return x_;
    }
    [[nodiscard]] double x() const { return x_; }

private:
    IdfPlant p_;
    double x_ = 0, v_ = 0;
};

IdfConfig linear_config(IdfPlant plant, bool adapt = false) {
    IdfConfig c;
    c.axis_count = 1;
    c.plant[0] = plant;
    c.plant[0].coulomb = 0;
    c.adapt = adapt;
    c.settings = IdfSettings{.periodic = true, .impulse = true};
    return c;
}

EngineActivity activity_of(double periodic, double impulse, double other = 0) {
    EngineActivity a;
    a.class_force[static_cast<int>(DisturbanceClass::periodic)][0] = static_cast<float>(periodic);
    a.class_force[static_cast<int>(DisturbanceClass::impulse)][0] = static_cast<float>(impulse);
    a.class_force[static_cast<int>(DisturbanceClass::other)][0] = static_cast<float>(other);
    return a;
}

// The deliberate motion the hand makes in these tests: a slow sine about an offset.
double deliberate(double t_s) { return 1000 + 2000 * std::sin(2 * kPi * 0.7 * t_s); }

// Runs `ticks` ticks: the force at tick n is force(n) (periodic, impulse); the sensed position
// is the deliberate motion plus the true displacement of the forces held so far. Returns the
// largest |reported − deliberate| after `settle` ticks, and the largest true displacement.
struct Residual {
    double worst = 0;
    double largest_displacement = 0;
};
template <class Force>
Residual run_linear(IdfFilter& idf, IdfPlant truth, int ticks, Force force, bool subtract_periodic = true,
                    bool subtract_impulse = true) {
    TruePlant all(truth), periodic_only(truth), impulse_only(truth);
    double held_p = 0, held_i = 0;
    Residual r;
    for (int n = 0; n < ticks; ++n) {
        const double t = n * kTickS;
        const double d_all = n == 0 ? 0 : all.step(held_p + held_i);
        const double d_p = n == 0 ? 0 : periodic_only.step(held_p);
        const double d_i = n == 0 ? 0 : impulse_only.step(held_i);
        const auto [fp, fi] = force(n);
        held_p = fp;
        held_i = fi;
        const float sensed[kMaxAxes] = {static_cast<float>(deliberate(t) + d_all)};
        float reported[kMaxAxes];
        idf.filter(n * kTickUs, sensed, activity_of(fp, fi), reported);
        // What the host should get: the deliberate motion plus what the player keeps.
        const double expected = deliberate(t) + (subtract_periodic ? 0 : d_p) + (subtract_impulse ? 0 : d_i);
        r.worst = std::max(r.worst, std::fabs(reported[0] - expected));
        r.largest_displacement = std::max(r.largest_displacement, std::fabs(d_all));
    }
    return r;
}

struct Forces {
    double periodic, impulse;
};

TEST(Idf, RemovesAKnownSineDisturbanceAndKeepsTheDeliberateMotion) {
    for (const double hz : {10.0, 25.0, 50.0}) {
        IdfFilter idf(linear_config(kFirm));
        ASSERT_TRUE(idf.error().ok()) << idf.error().message();
        const Residual r = run_linear(idf, kFirm, 2000, [&](int n) {
            return Forces{8000 * std::sin(2 * kPi * hz * n * kTickS), 0};
        });
        EXPECT_GT(r.largest_displacement, 25.0) << hz << " Hz";  // the vibration moves the handle
        // Float positions carry ~1e-4 relative error; the rest is the model, exact here.
        EXPECT_LT(r.worst, 0.05) << hz << " Hz";
    }
}

TEST(Idf, ExactForEveryDampingRegime) {
    // Underdamped (the hand), critically damped (the series branch), overdamped (cosh/sinh).
    const double critical = 2 * std::sqrt(kFirm.stiffness * kFirm.mass);
    for (const double damping : {kFirm.damping, critical, 20 * critical}) {
        IdfPlant p = kFirm;
        p.damping = damping;
        IdfFilter idf(linear_config(p));
        const Residual r = run_linear(idf, p, 1500, [&](int n) {
            // A square wave and a 30 ms jolt: steps excite every mode.
            const double square = (n / 25) % 2 == 0 ? 6000 : -6000;
            return Forces{square, n >= 400 && n < 430 ? 10000.0 : 0.0};
        });
        EXPECT_GT(r.largest_displacement, 50.0) << "damping " << damping;
        EXPECT_LT(r.worst, 0.05) << "damping " << damping;
    }
}

TEST(Idf, EachClassIsThePlayersChoice) {
    auto forces = [](int n) {
        return Forces{5000 * std::sin(2 * kPi * 20 * n * kTickS), (n % 300) < 30 ? 9000.0 : 0.0};
    };
    for (int choice = 0; choice < 4; ++choice) {
        const bool periodic = choice & 1, impulse = choice & 2;
        IdfConfig c = linear_config(kFirm);
        c.settings = IdfSettings{.periodic = periodic, .impulse = impulse};
        IdfFilter idf(c);
        const Residual r = run_linear(idf, kFirm, 1500, forces, periodic, impulse);
        EXPECT_LT(r.worst, 0.05) << "periodic " << periodic << " impulse " << impulse;
    }
}

TEST(Idf, WithoutEffectsTheReportIsTheSensedPositionExactly) {
    IdfFilter idf(runtime::idf_config_for(*sim::find_device_profile("joystick")));
    idf.set_settings({.periodic = true, .impulse = true});
    EngineActivity none;
    for (int n = 0; n < 3000; ++n) {
        const double t = n * kTickS;
        // Quantized like a sensor, with steps, reversals and a flick.
        const double x = std::round((deliberate(t) + (n > 1500 && n < 1520 ? 800 : 0)) / 4.8828125) * 4.8828125;
        const float sensed[kMaxAxes] = {static_cast<float>(x), static_cast<float>(-x / 2)};
        float reported[kMaxAxes];
        idf.filter(n * kTickUs, sensed, none, reported);
        ASSERT_EQ(reported[0], sensed[0]) << "tick " << n;
        ASSERT_EQ(reported[1], sensed[1]) << "tick " << n;
    }
    // No effect ever played, so nothing was learnt.
    EXPECT_EQ(idf.plant(0).stiffness, runtime::idf_config_for(*sim::find_device_profile("joystick")).plant[0].stiffness);
}

TEST(Idf, SwitchingAClassFadesItsCorrection) {
    IdfConfig c = linear_config(kFirm);
    c.settings = {};
    c.blend_us = 40'000;
    IdfFilter idf(c);
    TruePlant truth(kFirm);
    double held = 0;
    double previous_report = 0;
    double largest_step = 0;
    for (int n = 0; n < 1000; ++n) {
        const double t = n * kTickS;
        const double d = n == 0 ? 0 : truth.step(held);
        held = 8000 * std::sin(2 * kPi * 15 * t);
        if (n == 500) idf.set_settings({.periodic = true, .impulse = false});
        const float sensed[kMaxAxes] = {static_cast<float>(1000 + d)};
        float reported[kMaxAxes];
        idf.filter(n * kTickUs, sensed, activity_of(held, 0), reported);
        const double w = idf.blend(DisturbanceClass::periodic);
        // Linear in time from the switch, 0 before, 1 after blend_us.
        const double expected_w = std::clamp((n - 499) * 1000.0 / 40'000.0, 0.0, 1.0);
        ASSERT_NEAR(w, n < 500 ? 0.0 : expected_w, 1e-9) << "tick " << n;
        ASSERT_NEAR(reported[0], 1000 + d - w * d, 0.05) << "tick " << n;
        if (n > 0) largest_step = std::max(largest_step, std::fabs(reported[0] - previous_report));
        previous_report = reported[0];
    }
    // The sensed vibration moves up to 2π·15 Hz·|d|·1 ms per tick; the fade adds at most
    // |d|/40 per tick: never a jump.
    EXPECT_LT(largest_step, 60.0);
}

TEST(Idf, DryFrictionHoldsAPushSmallerThanItself) {
    // Static friction: a handle at rest pushed by less than the friction force does not
    // move at all; pushed by more, it comes to rest where the spring takes the excess,
    // d = (F − F_c)/k (approached from below, it sticks the moment it stops).
    IdfConfig c = linear_config(kFirm);
    c.plant[0].coulomb = 500;
    c.plant[0].damping = 4 * std::sqrt(kFirm.stiffness * kFirm.mass);  // no overshoot
    IdfFilter idf(c);
    const float still[kMaxAxes] = {100};
    float reported[kMaxAxes];
    for (int n = 0; n < 500; ++n) idf.filter(n * kTickUs, still, activity_of(0, 400), reported);
    EXPECT_NEAR(idf.predicted_displacement(DisturbanceClass::impulse, 0), 0.0, 1e-6);
    EXPECT_NEAR(reported[0], 100.0f, 1e-4);

    IdfFilter pushed(c);
    for (int n = 0; n < 3000; ++n) pushed.filter(n * kTickUs, still, activity_of(0, 2500), reported);
    const double rest = (2500.0 - 500.0) / kFirm.stiffness;
    EXPECT_NEAR(pushed.predicted_displacement(DisturbanceClass::impulse, 0), rest, 0.02 * rest);
    EXPECT_LE(pushed.predicted_displacement(DisturbanceClass::impulse, 0), rest + 1e-9);
}

TEST(Idf, IdentifiesAHandOtherThanThePrior) {
    // The hand is three times stiffer and 30% heavier than the prior assumes. A train of jolts
    // (broadband) while the hand drifts slowly: after a few seconds the identified plant
    // responds like the true one and the jolts' residue falls far below what the prior left.
    IdfPlant truth{.mass = kFirm.mass * 1.3, .damping = kFirm.damping * 2, .stiffness = kFirm.stiffness * 3};
    IdfConfig c = linear_config(kFirm, /*adapt=*/true);
    IdfFilter learning(c);
    IdfFilter fixed(linear_config(kFirm, false));
    TruePlant plant(truth);
    double held = 0;
    double err_learning = 0, err_fixed = 0, disturbance = 0;
    int counted = 0;
    for (int n = 0; n < 6000; ++n) {
        const double t = n * kTickS;
        const double d = n == 0 ? 0 : plant.step(held);
        held = (n % 250) < 30 ? 10000.0 : 0.0;
        const float sensed[kMaxAxes] = {static_cast<float>(deliberate(t) + d)};
        float a[kMaxAxes], b[kMaxAxes];
        learning.filter(n * kTickUs, sensed, activity_of(0, held), a);
        fixed.filter(n * kTickUs, sensed, activity_of(0, held), b);
        if (n >= 5000) {
            err_learning += std::pow(a[0] - deliberate(t), 2);
            err_fixed += std::pow(b[0] - deliberate(t), 2);
            disturbance += d * d;
            ++counted;
        }
    }
    const double rms_learning = std::sqrt(err_learning / counted);
    const double rms_fixed = std::sqrt(err_fixed / counted);
    const double rms_disturbance = std::sqrt(disturbance / counted);
    EXPECT_LT(rms_learning, rms_disturbance / 10) << "learnt " << rms_learning << ", jolts move " << rms_disturbance;
    EXPECT_LT(rms_learning, rms_fixed / 5) << "learnt " << rms_learning << ", prior " << rms_fixed;
    // The response at the jolts' main frequencies matches the truth's: |H(jω)| within 10%.
    const IdfPlant& p = learning.plant(0);
    for (const double hz : {2.0, 8.0, 20.0}) {
        const double w = 2 * kPi * hz;
        auto gain = [w](const IdfPlant& q) { return 1 / std::hypot(q.stiffness - q.mass * w * w, q.damping * w); };
        EXPECT_NEAR(gain(p) / gain(truth), 1.0, 0.1) << hz << " Hz";
    }
}

TEST(Idf, NonFiniteInputsNeverPoisonTheReport) {
    IdfFilter idf(linear_config(kFirm, true));
    float reported[kMaxAxes];
    for (int n = 0; n < 2000; ++n) {
        const double t = n * kTickS;
        float sensed[kMaxAxes] = {static_cast<float>(deliberate(t))};
        EngineActivity a = activity_of(3000 * std::sin(2 * kPi * 20 * t), 0);
        if (n == 700) sensed[0] = std::nanf("");
        if (n == 900) a.class_force[0][0] = std::numeric_limits<float>::infinity();
        idf.filter(n * kTickUs, sensed, a, reported);
        if (n == 700) {
            EXPECT_TRUE(std::isnan(reported[0]));  // what was sensed, unchanged
        } else {
            ASSERT_TRUE(std::isfinite(reported[0])) << "tick " << n;
        }
    }
    EXPECT_TRUE(std::isfinite(idf.plant(0).mass));
}

TEST(Idf, AGapInTheTicksStartsTheModelOver) {
    IdfFilter idf(linear_config(kFirm));
    float reported[kMaxAxes];
    const float sensed[kMaxAxes] = {500};
    for (int n = 0; n < 100; ++n) idf.filter(n * kTickUs, sensed, activity_of(0, 8000), reported);
    EXPECT_GT(std::fabs(idf.predicted_displacement(DisturbanceClass::impulse, 0)), 10.0);
    // One second with no tick: the handle's motion then is unknown, so nothing is subtracted.
    idf.filter(1'100'000, sensed, activity_of(0, 0), reported);
    EXPECT_EQ(idf.predicted_displacement(DisturbanceClass::impulse, 0), 0.0);
    EXPECT_EQ(reported[0], 500.0f);
}

TEST(Idf, ConfigFromTheProfile) {
    const sim::DeviceProfile& joystick = *sim::find_device_profile("joystick");
    const IdfConfig c = runtime::idf_config_for(joystick);
    ASSERT_TRUE(runtime::check_idf_config(c).ok());
    EXPECT_EQ(c.axis_count, 2);
    for (int a = 0; a < 2; ++a) {
        EXPECT_NEAR(c.plant[a].mass, kFirm.mass, 1e-12);
        EXPECT_NEAR(c.plant[a].damping, kFirm.damping, 1e-12);
        EXPECT_NEAR(c.plant[a].stiffness, kFirm.stiffness, 1e-12);
        EXPECT_NEAR(c.plant[a].coulomb, 0.15 / 4.45 * 10000, 1e-9);  // 0.15 N of gear friction
    }
    EXPECT_NEAR(c.sensor_step, 20000.0 / 4096, 1e-12);
    const IdfConfig stiff = runtime::idf_config_for(joystick, joystick.stiff);
    EXPECT_NEAR(stiff.plant[0].stiffness, 1500 * 0.05 / 4.45, 1e-12);
    EXPECT_NEAR(stiff.plant[0].mass, 0.45 * 0.05 / 4.45, 1e-12);
}

TEST(Idf, BadConfigNamesTheFieldAndPassesPositionsThrough) {
    struct Case {
        const char* field;
        void (*spoil)(IdfConfig&);
    };
    const Case cases[] = {
        {"axis_count", [](IdfConfig& c) { c.axis_count = 0; }},
        {"axis_count", [](IdfConfig& c) { c.axis_count = 7; }},
        {"plant[1].mass", [](IdfConfig& c) { c.plant[1].mass = 0; }},
        {"plant[0].damping", [](IdfConfig& c) { c.plant[0].damping = std::nan(""); }},
        {"plant[1].stiffness", [](IdfConfig& c) { c.plant[1].stiffness = -1; }},
        {"plant[0].coulomb", [](IdfConfig& c) { c.plant[0].coulomb = -0.5; }},
        {"adaptation_time_s", [](IdfConfig& c) { c.adaptation_time_s = 0; }},
        {"adaptation_noise", [](IdfConfig& c) { c.adaptation_noise = 0; }},
        {"adaptation_range", [](IdfConfig& c) { c.adaptation_range = 0.5; }},
        {"sensor_step", [](IdfConfig& c) { c.sensor_step = INFINITY; }},
        {"separation_hz", [](IdfConfig& c) { c.separation_hz = 200; }},
        {"blend_us", [](IdfConfig& c) { c.blend_us = -1; }},
    };
    for (const Case& k : cases) {
        IdfConfig c = runtime::idf_config_for(*sim::find_device_profile("joystick"));
        k.spoil(c);
        const Error e = runtime::check_idf_config(c);
        ASSERT_FALSE(e.ok()) << k.field;
        EXPECT_EQ(std::string(e.field), k.field);
        EXPECT_NE(e.message().find(k.field), std::string::npos) << e.message();
        IdfFilter idf(c);
        EXPECT_FALSE(idf.error().ok());
        const float sensed[kMaxAxes] = {123, -45};
        float reported[kMaxAxes];
        idf.filter(0, sensed, activity_of(5000, 5000), reported);
        idf.filter(1000, sensed, activity_of(5000, 5000), reported);
        EXPECT_EQ(reported[0], 123.0f);
        EXPECT_EQ(reported[1], -45.0f);
    }
}

TEST(Idf, ScaleActivityScalesEveryForce) {
    EngineActivity a = activity_of(1000, -2000, 300);
    a.count = 1;
    a.effects[0].force[0] = 1000;
    runtime::scale_activity(a, 0.25f);
    EXPECT_FLOAT_EQ(a.class_force[0][0], 250);
    EXPECT_FLOAT_EQ(a.class_force[1][0], -500);
    EXPECT_FLOAT_EQ(a.class_force[2][0], 75);
    EXPECT_FLOAT_EQ(a.effects[0].force[0], 250);
    runtime::scale_activity(a, std::nanf(""));  // a broken factor means no force, not NaN
    EXPECT_EQ(a.class_force[0][0], 0.0f);
}

// --- Engine::activity ---------------------------------------------------------------------

EffectParams on_x(EffectType type, int64_t duration_us) {
    EffectParams p;
    p.type = type;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.duration_us = duration_us;
    return p;
}

class EngineActivityTest : public ::testing::Test {
protected:
    EngineActivityTest() {
        EngineConfig c;
        c.axis_count = 2;
        c.max_effects = 64;
        engine_ = std::make_unique<Engine>(c);
    }
    EffectId play(const EffectParams& p, std::span<const int16_t> samples = {}) {
        const CreateResult r = engine_->create(p, samples);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        EXPECT_TRUE(engine_->start(r.id).ok());
        return r.id;
    }
    TickOutput tick() {
        TickInput in;
        in.t_us = t_us_;
        t_us_ += kTickUs;
        TickOutput out;
        engine_->tick(in, out);
        return out;
    }
    std::unique_ptr<Engine> engine_;
    int64_t t_us_ = 0;
};

TEST_F(EngineActivityTest, ClassifiesByThePrimersTwoDisturbances) {
    EffectParams sine = on_x(EffectType::sine, kInfiniteUs);
    sine.periodic.magnitude = 3000;
    sine.periodic.period_us = 40'000;
    sine.periodic.phase = 9000;  // starts at its peak, so the first tick has force
    EffectParams jolt = on_x(EffectType::constant, 30'000);
    jolt.constant.magnitude = -4000;
    EffectParams push = on_x(EffectType::constant, 2'000'000);  // a steady push, not a jolt
    push.constant.magnitude = 1000;
    EffectParams pop = on_x(EffectType::smart_pop, 50'000);
    pop.constant.magnitude = 2000;
    EffectParams ramp = on_x(EffectType::ramp, 100'000);
    ramp.ramp.start = 500;
    ramp.ramp.end = 1500;
    EffectParams spring = on_x(EffectType::spring, kInfiniteUs);  // a condition: not listed
    spring.conditions[0].pos_coefficient = spring.conditions[0].neg_coefficient = 5000;
    const EffectId ids[] = {play(sine), play(jolt), play(push), play(pop), play(ramp)};
    play(spring);
    tick();
    const TickOutput out = tick();
    EngineActivity a;
    engine_->activity(a);

    EXPECT_EQ(a.t_us, 1000);
    ASSERT_EQ(a.count, 5);
    EXPECT_EQ(a.omitted, 0);
    const DisturbanceClass want[] = {DisturbanceClass::periodic, DisturbanceClass::impulse, DisturbanceClass::other,
                                     DisturbanceClass::impulse, DisturbanceClass::impulse};
    for (int i = 0; i < 5; ++i) {
        EXPECT_EQ(a.effects[i].id, ids[i]) << i;
        EXPECT_EQ(a.effects[i].kind, want[i]) << i;
    }
    EXPECT_EQ(a.effects[0].period_us, 40'000);
    EXPECT_EQ(a.effects[1].period_us, 0);
    // Each force from its definition at τ = 1 ms.
    EXPECT_NEAR(a.effects[0].force[0], 3000 * std::sin(2 * kPi * (1.0 / 40 + 0.25)), 0.01);
    EXPECT_NEAR(a.effects[1].force[0], -4000, 1e-3);
    EXPECT_NEAR(a.effects[2].force[0], 1000, 1e-3);
    EXPECT_NEAR(a.effects[3].force[0], 2000 * std::sin(kPi * 1.0 / 50), 0.01);
    EXPECT_NEAR(a.effects[4].force[0], 500 + 1000 * (1.0 / 100), 0.01);
    // The class totals, and with the spring's share the engine's output.
    const float periodic = a.class_force[0][0], impulse = a.class_force[1][0], other = a.class_force[2][0];
    EXPECT_NEAR(periodic, a.effects[0].force[0], 1e-3);
    EXPECT_NEAR(impulse, a.effects[1].force[0] + a.effects[3].force[0] + a.effects[4].force[0], 1e-3);
    EXPECT_NEAR(other, 1000, 1e-3);
    // The handle sits at the spring's offset, so the spring adds nothing to the output.
    EXPECT_NEAR(out.force[0], periodic + impulse + other, 0.01);
    EXPECT_EQ(a.class_force[0][1], 0.0f);  // nothing on y
}

TEST_F(EngineActivityTest, ForcesAreAfterEffectAndDeviceGain) {
    EffectParams jolt = on_x(EffectType::vector_force, 40'000);
    jolt.axis_count = 2;
    jolt.axes[1] = Axis::y;
    jolt.direction.kind = DirectionKind::polar;
    jolt.direction.value[0] = 9000;  // from +x: pushes toward −x
    jolt.constant.magnitude = 8000;
    jolt.gain = 5000;
    play(jolt);
    ASSERT_TRUE(engine_->set_gain(5000).ok());
    const TickOutput out = tick();
    EngineActivity a;
    engine_->activity(a);
    ASSERT_EQ(a.count, 1);
    EXPECT_NEAR(a.effects[0].force[0], -8000 * 0.5 * 0.5, 1e-2);
    EXPECT_NEAR(a.effects[0].force[1], 0, 1e-2);
    EXPECT_NEAR(a.class_force[1][0], out.force[0], 1e-2);
}

TEST_F(EngineActivityTest, LoopingProfilesArePeriodicAndOneShotsAreJolts) {
    const std::vector<int16_t> samples = {1000, 3000, -2000, 500};
    EffectParams loop = on_x(EffectType::force_profile, kInfiniteUs);
    loop.custom.channels = 1;
    loop.custom.sample_period_us = 5000;
    loop.custom.sample_count = 4;
    EffectParams shot = loop;
    shot.duration_us = 20'000;  // exactly one pass of the samples
    EffectParams long_shot = loop;
    long_shot.custom.sample_period_us = 100'000;
    long_shot.duration_us = 400'000;  // one pass, but longer than a jolt
    play(loop, samples);
    play(shot, samples);
    play(long_shot, samples);
    tick();
    EngineActivity a;
    engine_->activity(a);
    ASSERT_EQ(a.count, 3);
    EXPECT_EQ(a.effects[0].kind, DisturbanceClass::periodic);
    EXPECT_EQ(a.effects[0].period_us, 20'000);  // 4 samples of 5 ms
    EXPECT_EQ(a.effects[1].kind, DisturbanceClass::impulse);
    EXPECT_EQ(a.effects[2].kind, DisturbanceClass::other);
    EXPECT_NEAR(a.effects[0].force[0], 1000, 1e-3);
}

TEST_F(EngineActivityTest, NothingWhilePausedOrBeforeTheFirstTick) {
    EngineActivity a;
    engine_->activity(a);
    EXPECT_EQ(a.count, 0);
    EffectParams jolt = on_x(EffectType::constant, 200'000);
    jolt.constant.magnitude = 5000;
    play(jolt);
    tick();
    engine_->activity(a);
    EXPECT_EQ(a.count, 1);
    engine_->pause();
    const TickOutput out = tick();
    EXPECT_EQ(out.force[0], 0.0f);
    engine_->activity(a);
    EXPECT_EQ(a.count, 0);
    EXPECT_EQ(a.class_force[1][0], 0.0f);
}

TEST_F(EngineActivityTest, MoreWavesThanEntriesStillCountInTheTotals) {
    const int n = kMaxActivityEffects + 5;
    for (int i = 0; i < n; ++i) {
        EffectParams jolt = on_x(EffectType::constant, 100'000);
        jolt.constant.magnitude = 100;
        play(jolt);
    }
    tick();
    EngineActivity a;
    engine_->activity(a);
    EXPECT_EQ(a.count, kMaxActivityEffects);
    EXPECT_EQ(a.omitted, 5);
    EXPECT_NEAR(a.class_force[1][0], 100.0 * n, 1e-2);
}

}  // namespace
}  // namespace feel::test
