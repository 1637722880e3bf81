// Direction conventions (§6.5): every form names where the force comes FROM.
#include "engine_fixture.hpp"

namespace feel::test {
namespace {

using Direction2D = EngineFixture;

// A unit force from compass angle a (hundredths of a degree): it comes from
// (sin a, cos a) in (x, y) and pushes the other way.
void expect_from_compass(Direction2D& f, double degrees, double magnitude, const TickOutput& out) {
    const double a = degrees * kPi / 180.0;
    EXPECT_NEAR(out.force[0], -magnitude * std::sin(a), kForceTolerance) << degrees;
    EXPECT_NEAR(out.force[1], -magnitude * std::cos(a), kForceTolerance) << degrees;
    (void)f;
}

TEST_F(Direction2D, PolarCardinalPoints) {
    struct Case { int32_t angle; double fx, fy; };
    // From north pushes south (toward the user, -y); from east pushes west (-x).
    const Case cases[] = {{0, 0, -5000}, {9000, -5000, 0}, {18000, 0, 5000}, {27000, 5000, 0}};
    for (const Case& c : cases) {
        reset(2);
        play(on_xy_polar(constant_on_x(5000, kInfiniteUs), c.angle));
        const TickOutput out = tick();
        EXPECT_NEAR(out.force[0], c.fx, kForceTolerance) << c.angle;
        EXPECT_NEAR(out.force[1], c.fy, kForceTolerance) << c.angle;
    }
}

TEST_F(Direction2D, PrimerExampleFromBehindOnTheRightIs135Degrees) {
    // §6.5.b: a force coming from behind the stick on the right side has direction 135°.
    // It comes from +x and -y, so it pushes the stick left (-x) and forward (+y).
    play(on_xy_polar(constant_on_x(10000, kInfiniteUs), 13500));
    const TickOutput out = tick();
    EXPECT_LT(out.force[0], 0.0f);
    EXPECT_GT(out.force[1], 0.0f);
    expect_from_compass(*this, 135.0, 10000, out);
}

TEST_F(Direction2D, PolarEveryTenDegrees) {
    for (int deg = 0; deg < 360; deg += 10) {
        reset(2);
        play(on_xy_polar(constant_on_x(7000, kInfiniteUs), deg * 100));
        expect_from_compass(*this, deg, 7000, tick());
    }
}

TEST_F(Direction2D, CartesianVectorIsNormalizedAndNamesWhereTheForceComesFrom) {
    EffectParams p = on_xy_polar(constant_on_x(3000, kInfiniteUs), 0);
    p.direction.kind = DirectionKind::cartesian;
    p.direction.value[0] = 300;
    p.direction.value[1] = 400;  // from (0.6, 0.8)
    play(p);
    const TickOutput out = tick();
    EXPECT_NEAR(out.force[0], -3000 * 0.6, kForceTolerance);
    EXPECT_NEAR(out.force[1], -3000 * 0.8, kForceTolerance);
}

TEST_F(Direction2D, SingleAxisWithoutDirectionKeepsThePhysicalSign) {
    EffectParams p = constant_on_x(2000, kInfiniteUs);
    p.axes[0] = Axis::y;
    play(p);
    const TickOutput out = tick();
    EXPECT_EQ(out.force[0], 0.0f);
    EXPECT_EQ(out.force[1], 2000.0f);
}

class Direction3D : public EngineFixture {
protected:
    Direction3D() : EngineFixture(3) {}
};

TEST_F(Direction3D, SphericalAnglesFollowThePrimer) {
    // §6.5.c: the first angle turns in the XY plane from +x toward +y, the second leans
    // away from +z. The force comes from that direction.
    struct Case { int32_t azimuth, elevation; double fx, fy, fz; };
    const double h = std::sqrt(0.5) * 4000;
    const Case cases[] = {
        {0, 9000, -4000, 0, 0},    // from +x
        {9000, 9000, 0, -4000, 0}, // from +y
        {0, 0, 0, 0, -4000},       // from +z: pushes down
        {4500, 9000, -h, -h, 0},
        {18000, 4500, h, 0, -h},   // from -x and +z, 45° each
    };
    for (const Case& c : cases) {
        reset(3);
        EffectParams p = constant_on_x(4000, kInfiniteUs);
        p.axis_count = 3;
        p.axes[0] = Axis::x;
        p.axes[1] = Axis::y;
        p.axes[2] = Axis::z;
        p.direction.kind = DirectionKind::spherical;
        p.direction.value[0] = c.azimuth;
        p.direction.value[1] = c.elevation;
        play(p);
        const TickOutput out = tick();
        EXPECT_NEAR(out.force[0], c.fx, kForceTolerance) << c.azimuth << "," << c.elevation;
        EXPECT_NEAR(out.force[1], c.fy, kForceTolerance) << c.azimuth << "," << c.elevation;
        EXPECT_NEAR(out.force[2], c.fz, kForceTolerance) << c.azimuth << "," << c.elevation;
    }
}

TEST_F(Direction3D, CartesianOverThreeAxes) {
    EffectParams p = constant_on_x(9000, kInfiniteUs);
    p.axis_count = 3;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    p.axes[2] = Axis::z;
    p.direction.kind = DirectionKind::cartesian;
    p.direction.value[0] = 1;
    p.direction.value[1] = 2;
    p.direction.value[2] = 2;  // |v| = 3
    play(p);
    const TickOutput out = tick();
    EXPECT_NEAR(out.force[0], -3000, kForceTolerance);
    EXPECT_NEAR(out.force[1], -6000, kForceTolerance);
    EXPECT_NEAR(out.force[2], -6000, kForceTolerance);
}

}  // namespace
}  // namespace feel::test

namespace feel::test {
namespace {

TEST_F(Direction2D, CardinalDirectionsLeaveTheOtherAxisExactlyZero) {
    for (int32_t angle : {0, 9000, 18000, 27000}) {
        reset(2);
        play(on_xy_polar(constant_on_x(5000, kInfiniteUs), angle));
        const TickOutput out = tick();
        EXPECT_EQ(out.force[angle % 18000 == 0 ? 0 : 1], 0.0f) << angle;
    }
}

}  // namespace
}  // namespace feel::test
