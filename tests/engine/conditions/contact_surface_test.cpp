// The direction across an angle wall or barrier (contact_surface.cpp's element_direction),
// against double-precision sin and cos of the compass angle: every angle of the validator's
// range, rounded to float as an exact value would be (a clipped report 7000 units along an
// oblique wall must sit on the line to 1e-3 units, which needs u to float's last bit).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "conditions/contact_surface.hpp"
#include "slot_params.hpp"

namespace feel::test::contact_surface {
namespace {

// Half an ulp of the float nearest x: how far a correctly rounded float may be from x.
double half_ulp_of(double x) {
    const float f = std::fabs(static_cast<float>(x));
    return 0.5 * (static_cast<double>(std::nextafter(f, std::numeric_limits<float>::infinity())) - f);
}

void direction_of(EffectType type, int32_t angle, float u[kMaxAxes]) {
    detail::SlotParams p;
    p.type = type;
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    if (type == EffectType::angle_wall) {
        p.wall = WallBlock{};
        p.wall.angle = angle;
    } else {
        p.barrier = BarrierBlock{};
        p.barrier.angle = angle;
    }
    for (int a = 0; a < kMaxAxes; ++a) u[a] = 7.0f;
    detail::element_direction(p, u);
}

TEST(ElementDirection, AngleElementsTakeTheCompassDirectionToFloatsLastBit) {
    // The integer series is within 2e-9 of the truth before its one rounding (contact_surface.cpp).
    constexpr double kBeforeRounding = 4e-9;
    for (const EffectType type : {EffectType::angle_wall, EffectType::angle_barrier}) {
        for (int32_t angle = 0; angle < 36000; ++angle) {
            float u[kMaxAxes];
            direction_of(type, angle, u);
            const double radians = angle * std::numbers::pi / 18000;
            const double sine = std::sin(radians), cosine = std::cos(radians);
            ASSERT_LE(std::fabs(u[0] - sine), half_ulp_of(sine) + kBeforeRounding) << angle;
            ASSERT_LE(std::fabs(u[1] - cosine), half_ulp_of(cosine) + kBeforeRounding) << angle;
            for (int a = 2; a < kMaxAxes; ++a) ASSERT_EQ(u[a], 0.0f) << angle;
        }
    }
}

TEST(ElementDirection, TheFourAxisAnglesAreExactAxisVectors) {
    struct Case {
        int32_t angle;
        float x, y;
    };
    for (const Case c : {Case{0, 0, 1}, Case{9000, 1, 0}, Case{18000, 0, -1}, Case{27000, -1, 0}}) {
        float u[kMaxAxes];
        direction_of(EffectType::angle_wall, c.angle, u);
        EXPECT_EQ(u[0], c.x) << c.angle;
        EXPECT_EQ(u[1], c.y) << c.angle;
    }
}

TEST(ElementDirection, FortyFiveDegreesIsTheFloatNearestRootHalf) {
    // sin 45° = cos 45° = √½: the correctly rounded square root is float's nearest.
    float u[kMaxAxes];
    direction_of(EffectType::angle_wall, 4500, u);
    EXPECT_EQ(u[0], std::sqrt(0.5f));
    EXPECT_EQ(u[1], std::sqrt(0.5f));
}

}  // namespace
}  // namespace feel::test::contact_surface
