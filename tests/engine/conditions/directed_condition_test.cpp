// Conditions with a direction (§3.1: "for multi-axis conditions, you can define a
// direction"), against DirectInput's rule: a single DICONDITION "defines the condition in
// the specified direction". So the force lies along the direction's unit vector u, its
// component across u is zero, and along u it is the 1-D Condition Struct law of the
// handle's position, velocity or acceleration projected onto u. Where the form coincides
// with the angle_spring (a spring with a polar direction), both give the same force vector.
#include <cstring>
#include <vector>

#include "condition_fixture.hpp"

namespace feel::test {
namespace {

using DirectedCondition = ConditionFixture;

// The Condition Struct's profile (DirectInput's DICONDITION) over an input d measured from
// the offset: zero within the deadband, beyond it the coefficient of that side times the
// distance past the band's edge, restoring, capped by that side's saturation.
double law(double input, const ConditionBlock& b) {
    const double d = input - b.offset;
    if (d > b.deadband) return -std::clamp(b.pos_coefficient * (d - b.deadband) / 10000, -1.0 * b.pos_saturation,
                                           1.0 * b.pos_saturation);
    if (d < -b.deadband) return std::clamp(b.neg_coefficient * (-d - b.deadband) / 10000, -1.0 * b.neg_saturation,
                                           1.0 * b.neg_saturation);
    return 0;
}

EffectParams directed(EffectType type, std::initializer_list<Axis> axes, const ConditionBlock& b,
                      DirectionKind kind, std::initializer_list<int32_t> value) {
    EffectParams p = condition(type, axes, {b});
    p.direction.kind = kind;
    int i = 0;
    for (int32_t v : value) p.direction.value[i++] = v;
    return p;
}

struct Vec3 {
    double x = 0, y = 0, z = 0;
};
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 force_of(const TickOutput& out) { return {out.force[0], out.force[1], out.force[2]}; }

// The force, split into its component along u and the rest.
void expect_along_only(const TickOutput& out, const Vec3& u, double along, double tolerance, int k) {
    const Vec3 f = force_of(out);
    const double f_u = dot(f, u);
    const Vec3 across{f.x - f_u * u.x, f.y - f_u * u.y, f.z - f_u * u.z};
    ASSERT_NEAR(std::sqrt(dot(across, across)), 0, 1e-3) << "tick " << k << ": force across the direction";
    ASSERT_NEAR(f_u, along, tolerance) << "tick " << k << ": force along the direction";
}

TEST_F(DirectedCondition, APolarSpringIsTheAngleSpringOfTheSameAngle) {
    // Same block, same compass angle: the same force vector on every tick of a path that
    // crosses the line in every direction.
    const ConditionBlock b = block(5000, 2500, 1000, 3500, 9000, 400);
    auto path = [](int k) { return Point{8000 * std::cos(2 * kPi * k / 1000.0), 6000 * std::sin(2 * kPi * k / 700.0)}; };
    for (int32_t angle : {0, 3000, 9000, 13500, 25000}) {
        SCOPED_TRACE(angle);
        Engine angle_engine(config_);
        const CreateResult a = angle_engine.create(angle_spring(angle, b));
        ASSERT_TRUE(a.error.ok()) << a.error.message();
        ASSERT_TRUE(angle_engine.start(a.id).ok());
        reset(config_);
        play(directed(EffectType::spring, {Axis::x, Axis::y}, b, DirectionKind::polar, {angle}));
        for (int k = 0; k < 1500; ++k) {
            TickInput in;
            in.t_us = t_us_;
            in.position[0] = static_cast<float>(path(k).x);
            in.position[1] = static_cast<float>(path(k).y);
            TickOutput want;
            angle_engine.tick(in, want);
            const TickOutput got = tick_at(path(k).x, path(k).y);
            ASSERT_NEAR(got.force[0], want.force[0], 1e-2) << "tick " << k;
            ASSERT_NEAR(got.force[1], want.force[1], 1e-2) << "tick " << k;
        }
    }
}

TEST_F(DirectedCondition, ACartesianSpringActsAlongItsVectorOnly) {
    // cartesian (3, 4) on x, y: u = (0.6, 0.8), the side u points to is the positive side.
    const ConditionBlock b = block(6000, 3000, -800, 4000, 2500, 300);
    play(directed(EffectType::spring, {Axis::x, Axis::y}, b, DirectionKind::cartesian, {3, 4}));
    const Vec3 u{0.6, 0.8, 0};
    for (int k = 0; k < 2000; ++k) {
        const double x = 9000 * std::sin(2 * kPi * k / 900.0), y = -7000 * std::cos(2 * kPi * k / 1300.0);
        expect_along_only(tick_at(x, y), u, law(0.6 * x + 0.8 * y, b), 1e-2, k);
    }
}

TEST_F(DirectedCondition, AMotionAcrossTheDirectionFeelsNoSpring) {
    // The handle slides along the line s = 2000 (across u): the force is the same constant
    // push all along, whatever the distance travelled across.
    const ConditionBlock b = block(5000, 5000);
    play(directed(EffectType::spring, {Axis::x, Axis::y}, b, DirectionKind::cartesian, {3, 4}));
    for (int k = 0; k < 500; ++k) {
        const double t = -6000 + 24.0 * k;  // along the perpendicular (-0.8, 0.6)
        expect_along_only(tick_at(0.6 * 2000 - 0.8 * t, 0.8 * 2000 + 0.6 * t), {0.6, 0.8, 0}, -1000, 1e-2, k);
    }
}

TEST_F(DirectedCondition, ASphericalSpringOnThreeAxes) {
    // Azimuth 30° from +x toward +y, 60° away from +z (§6.5.c):
    // u = (sin 60° cos 30°, sin 60° sin 30°, cos 60°).
    const double th = kPi / 6, ph = kPi / 3;
    const Vec3 u{std::sin(ph) * std::cos(th), std::sin(ph) * std::sin(th), std::cos(ph)};
    const ConditionBlock b = block(7000, 4000, 500, 10000, 3000, 200);
    reset(sim::engine_config_for(*sim::find_device_profile("3axis")));  // x, y, z
    play(directed(EffectType::spring, {Axis::x, Axis::y, Axis::z}, b, DirectionKind::spherical, {3000, 6000}));
    for (int k = 0; k < 2000; ++k) {
        const Vec3 x{8000 * std::sin(2 * kPi * k / 700.0), 6000 * std::cos(2 * kPi * k / 1100.0),
                     9000 * std::sin(2 * kPi * k / 1700.0)};
        expect_along_only(tick_at(x.x, x.y, x.z), u, law(dot(x, u), b), 1e-2, k);
    }
}

TEST_F(DirectedCondition, ARelativeSpringIsCenteredOnTheStartPositionAlongTheDirection) {
    const ConditionBlock b = block(4000, 6000, 500, 10000, 10000, 0, OffsetMode::relative);
    play(directed(EffectType::spring, {Axis::x, Axis::y}, b, DirectionKind::cartesian, {-3, 4}));
    const Vec3 u{-0.6, 0.8, 0};
    const double s0 = -0.6 * 3000 + 0.8 * 1000;
    ConditionBlock centered = b;
    centered.offset = 0;
    for (int k = 0; k < 1000; ++k) {
        const double x = 3000 - 4.0 * k, y = 1000 + 3.0 * k;
        expect_along_only(tick_at(x, y), u, law(-0.6 * x + 0.8 * y - (s0 + 500), centered), 1e-2, k);
    }
}

TEST_F(DirectedCondition, ADamperResistsOnlyTheVelocityAlongTheDirection) {
    // A straight motion at (vx, vy): along u = (0.6, 0.8) the velocity is 0.6 vx + 0.8 vy,
    // 10000 on the scale = velocity_ref (1e5 units/s on the joystick).
    const ConditionBlock b = block(8000, 5000, 300, 6000, 10000, 100);
    const double vx = 30000, vy = -45000;
    play(directed(EffectType::damper, {Axis::x, Axis::y}, b, DirectionKind::cartesian, {3000, 4000}));
    const double v_u = 0.6 * vx + 0.8 * vy;
    for (int k = 0; k < 150; ++k) {
        const TickOutput out = tick_at(-6000 + vx * k * 1e-3, 7000 + vy * k * 1e-3);
        if (k == 0) continue;  // one sample: no velocity yet
        expect_along_only(out, {0.6, 0.8, 0}, law(v_u * 10000 / 1e5, b), 1e-2, k);
    }
}

TEST_F(DirectedCondition, AnInertiaResistsOnlyTheAccelerationAlongTheDirection) {
    // Constant accelerations (ax, ay): along u the acceleration is 0.6 ax + 0.8 ay,
    // 10000 on the scale = acceleration_ref (2e6 units/s² on the joystick).
    const ConditionBlock b = block(6000, 3000, 0, 2500, 10000, 200);
    const double ax = 9e5, ay = -2e5;
    play(directed(EffectType::inertia, {Axis::x, Axis::y}, b, DirectionKind::cartesian, {3, 4}));
    const double a_u = 0.6 * ax + 0.8 * ay;
    for (int k = 0; k < 120; ++k) {
        const double t = k * 1e-3;
        const TickOutput out = tick_at(-5000 + 0.5 * ax * t * t, 4000 + 0.5 * ay * t * t);
        if (k < 10) continue;  // the parabola fit needs its window (inertia_test.cpp)
        expect_along_only(out, {0.6, 0.8, 0}, law(a_u * 10000 / 2e6, b), 0.5, k);
    }
}

TEST_F(DirectedCondition, FrictionRubsOnlyAlongTheDirection) {
    // §3.5: friction resists the motion with a constant magnitude. Sliding steadily along
    // u it is -f along u; sliding across u there is nothing to rub.
    const ConditionBlock b = block(6000, 6000);
    play(directed(EffectType::friction, {Axis::x, Axis::y}, b, DirectionKind::cartesian, {3, 4}));
    const Vec3 u{0.6, 0.8, 0};
    for (int k = 0; k < 300; ++k) {
        const double s = -6000 + 40.0 * k;  // 40000 units/s along u
        const TickOutput out = tick_at(0.6 * s, 0.8 * s);
        if (k < 100) continue;  // well past any presliding zone
        expect_along_only(out, u, -6000, 60, k);
    }
    reset(config_);
    play(directed(EffectType::friction, {Axis::x, Axis::y}, b, DirectionKind::cartesian, {3, 4}));
    for (int k = 0; k < 300; ++k) {
        const double t = -6000 + 40.0 * k;  // across u, along (-0.8, 0.6)
        const TickOutput out = tick_at(-0.8 * t, 0.6 * t);
        expect_along_only(out, u, 0, 60, k);
    }
}

TEST_F(DirectedCondition, TheSameInputsGiveBitIdenticalForces) {
    // The real-time rule: a directed friction and a directed inertia (the stateful and the
    // most derived input) replayed on a second engine give the very same bits.
    auto run = [&](Engine& e) {
        ConditionBlock b = block(7000, 5000);
        EffectParams friction = directed(EffectType::friction, {Axis::x, Axis::y}, b, DirectionKind::polar, {2100});
        EffectParams inertia = directed(EffectType::inertia, {Axis::y, Axis::x}, b, DirectionKind::cartesian, {-2, 5});
        for (const EffectParams& p : {friction, inertia}) {
            const CreateResult r = e.create(p);
            EXPECT_TRUE(r.error.ok()) << r.error.message();
            EXPECT_TRUE(e.start(r.id).ok());
        }
        std::vector<float> forces;
        for (int k = 0; k < 3000; ++k) {
            TickInput in;
            in.t_us = k * 1000;
            in.position[0] = static_cast<float>(quantize(7000 * std::sin(k / 230.0), kJoystickStep));
            in.position[1] = static_cast<float>(quantize(5000 * std::sin(k / 170.0 + 1), kJoystickStep));
            TickOutput out;
            e.tick(in, out);
            forces.push_back(out.force[0]);
            forces.push_back(out.force[1]);
        }
        return forces;
    };
    Engine a(config_), b(config_);
    const std::vector<float> first = run(a), second = run(b);
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(float)), 0);
}

TEST_F(DirectedCondition, ThePerAxisFormIsUnchanged) {
    // Without a direction each block acts on its own axis (§8.2 Spring(X..., Y...)).
    play(condition(EffectType::spring, {Axis::x, Axis::y}, {block(2000, 2000), block(6000, 6000)}));
    const TickOutput out = tick_at(1000, 1000);
    EXPECT_NEAR(out.force[0], -200, 1e-2);
    EXPECT_NEAR(out.force[1], -600, 1e-2);
}

}  // namespace
}  // namespace feel::test
