// Interim and final reporting of the sling and the paddle through the engine (§5.2,
// §6.6.f): interim reports at EngineConfig::interim_report_hz while the effect plays with
// interim_reporting set, one final report when a paddle ball leaves, none for a sling.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "ball_rig.hpp"
#include "engine_fixture.hpp"

namespace feel::test {
namespace {

std::vector<DynamicReport> drain(Engine& engine) {
    std::vector<DynamicReport> reports;
    DynamicReport r;
    while (engine.pop_report(r)) reports.push_back(r);
    return reports;
}

int count(const std::vector<DynamicReport>& reports, DynamicReport::Kind kind) {
    int n = 0;
    for (const DynamicReport& r : reports) n += r.kind == kind;
    return n;
}

class BallReports : public EngineFixture {
protected:
    BallReports() : EngineFixture(2) {}

    // Ticks at 1 kHz for duration_us (the handle at the origin) and collects the reports.
    std::vector<DynamicReport> run(int64_t duration_us) {
        std::vector<DynamicReport> all;
        for (int64_t t = 0; t < duration_us; t += 1000) {
            tick(1000);
            for (const DynamicReport& r : drain(*engine_)) all.push_back(r);
        }
        return all;
    }
};

TEST_F(BallReports, ASlingReportsItsBallAt60HzAndNeverEnds) {
    const EffectId id = play(sling_params(5000, 2000, 5000, 100, true));
    const auto reports = run(1'000'000);
    // Ticks at 0, 1, ..., 999 ms: reports at 0, 16.667, ..., 983.3 ms.
    EXPECT_NEAR(count(reports, DynamicReport::Kind::interim), 60, 1);
    EXPECT_EQ(count(reports, DynamicReport::Kind::final), 0);
    for (size_t i = 0; i < reports.size(); ++i) {
        EXPECT_EQ(reports[i].effect, id);
        EXPECT_EQ(reports[i].axis_count, 2);
        if (i > 0) {
            EXPECT_NEAR(static_cast<double>(reports[i].t_us - reports[i - 1].t_us), 1e6 / 60, 1000);
        }
    }
    EXPECT_EQ(engine_->state(id), EffectState::playing);
    ASSERT_TRUE(engine_->stop(id).ok());
    EXPECT_EQ(count(run(100'000), DynamicReport::Kind::final), 0) << "stopping is not an ending";
}

TEST_F(BallReports, TheRateIsConfigurable) {
    EngineConfig c;
    c.interim_report_hz = 25;
    engine_ = std::make_unique<Engine>(c);
    play(sling_params(5000, 2000, 5000, 100, true));
    EXPECT_NEAR(count(run(2'000'000), DynamicReport::Kind::interim), 50, 1);
}

TEST_F(BallReports, WithoutTheFlagThereAreNoInterimReports) {
    play(sling_params(5000, 2000, 5000, 100, false));
    EXPECT_TRUE(run(1'000'000).empty());
}

TEST_F(BallReports, APaddleReportsTheBounceAndEndsWithTheFinalVelocity) {
    // An elastic paddle at rest at the origin: the ball comes from compass 9000 (+x) at V,
    // presses the paddle in by at most V/ω, and leaves along +x at V.
    const EffectParams p = paddle_params(4000, 6000, 9000, 3000, 0, 0, true);
    const EngineConfig& c = engine_->config();
    const double m = scaled(p.dynamic.ball_mass, c.dynamic_mass_ref);
    const double k = scaled(p.dynamic.paddle_compliance, c.dynamic_stiffness_ref);
    const double V = scaled(p.dynamic.initial_velocity, c.velocity_ref);
    const double omega = std::sqrt(k / m);
    const EffectId id = play(p);
    const auto reports = run(2'000'000);
    EXPECT_EQ(engine_->state(id), EffectState::stopped);
    ASSERT_EQ(count(reports, DynamicReport::Kind::final), 1);
    const DynamicReport& last = reports.back();
    EXPECT_EQ(last.kind, DynamicReport::Kind::final);
    EXPECT_EQ(last.effect, id);
    EXPECT_NEAR(last.velocity[0], V, 1e-6 * V);
    EXPECT_NEAR(last.velocity[1], 0.0, 1e-6 * V);
    // The paddle (the handle) is at rest, so the fixed-frame velocity is the relative one.
    EXPECT_EQ(last.handle_velocity[0], 0.0f);
    EXPECT_EQ(last.handle_velocity[1], 0.0f);
    // The contact lasts π/ω: the final report comes on the first tick after it.
    EXPECT_EQ(last.t_us, static_cast<int64_t>(std::ceil(kBallPi / omega * 1e3)) * 1000);
    // Interim reports at 60 Hz during the bounce, the ball pressed into the paddle (x < 0)
    // by at most V/ω.
    const int interim = count(reports, DynamicReport::Kind::interim);
    EXPECT_NEAR(interim, std::ceil(kBallPi / omega * 60), 1);
    double deepest = 0;
    for (const DynamicReport& r : reports) {
        if (r.kind != DynamicReport::Kind::interim) continue;
        EXPECT_LE(r.position[0], 0.0f);
        deepest = std::min(deepest, static_cast<double>(r.position[0]));
    }
    EXPECT_GE(deepest, -V / omega * (1 + 1e-6));
    EXPECT_LE(deepest, -V / omega * std::cos(omega / 120));  // a report within 1/120 s of the deepest point
}

TEST_F(BallReports, APaddleWithoutTheFlagStillSendsItsFinalReport) {
    play(paddle_params(4000, 6000, 0, 3000, 2000, 0, false));
    const auto reports = run(2'000'000);
    ASSERT_EQ(reports.size(), 1u);
    EXPECT_EQ(reports[0].kind, DynamicReport::Kind::final);
    EXPECT_GT(reports[0].velocity[1], 0.0f);  // leaving along +y, where it came from
}

TEST_F(BallReports, ReportsFollowTheEffectsAxisOrder) {
    EffectParams p = paddle_params(4000, 6000, 0, 3000, 0, 0, false);
    p.axes[0] = Axis::y;
    p.axes[1] = Axis::x;
    play(p);
    const auto reports = run(2'000'000);
    ASSERT_EQ(reports.size(), 1u);
    const double V = scaled(6000, engine_->config().velocity_ref);
    EXPECT_NEAR(reports[0].velocity[0], V, 1e-6 * V);  // axis 0 of the effect is y
    EXPECT_NEAR(reports[0].velocity[1], 0.0, 1e-6 * V);
}

TEST_F(BallReports, TheTickOutputCarriesTheBallEveryTick) {
    play(paddle_params(4000, 6000, 0, 3000, 0, 0, false));
    const TickOutput first = tick();
    EXPECT_TRUE(first.has_mass);
    const TickOutput second = tick();
    EXPECT_TRUE(second.has_mass);
    EXPECT_LT(second.mass_position[1], 0.0f);  // pressing in
    EXPECT_LT(second.force[1], 0.0f);          // pushing the paddle the way the ball goes
}

// The engine around the models: any parameters, any hand. Forces stay within the motor's
// limit and finite, reports finite.
RC_GTEST_PROP(BallEngine, EngineOutputsStayFiniteAndLimited, ()) {
    EngineConfig c;
    Engine engine(c);
    const bool sling = *rc::gen::arbitrary<bool>();
    const EffectParams p =
        sling ? sling_params(*rc::gen::inRange(1, 10001), *rc::gen::inRange(0, 10001), *rc::gen::inRange(1, 10001),
                             *rc::gen::inRange(0, 10001), true)
              : paddle_params(*rc::gen::inRange(1, 10001), *rc::gen::inRange(-10000, 10001),
                              *rc::gen::inRange(0, 36000), *rc::gen::inRange(1, 10001), *rc::gen::inRange(0, 10001),
                              *rc::gen::inRange(-10000, 10001), true);
    const CreateResult created = engine.create(p);
    RC_ASSERT(created.error.ok());
    RC_ASSERT(engine.start(created.id).ok());
    int64_t t = 0;
    TickInput in;
    for (int i = 0; i < 300; ++i) {
        t += *rc::gen::inRange(100, 5000);
        in.t_us = t;
        if (*rc::gen::inRange(0, 4) == 0) {
            in.position[0] = static_cast<float>(*rc::gen::inRange(-10000, 10001));
            in.position[1] = static_cast<float>(*rc::gen::inRange(-10000, 10001));
        }
        TickOutput out;
        engine.tick(in, out);
        for (int a = 0; a < kMaxAxes; ++a) {
            RC_ASSERT(std::isfinite(out.force[a]));
            RC_ASSERT(std::fabs(out.force[a]) <= 10000.0f);
            RC_ASSERT(std::isfinite(out.mass_position[a]));
            RC_ASSERT(std::isfinite(out.mass_velocity[a]));
        }
        DynamicReport r;
        while (engine.pop_report(r)) {
            for (int a = 0; a < r.axis_count; ++a) {
                RC_ASSERT(std::isfinite(r.position[a]));
                RC_ASSERT(std::isfinite(r.velocity[a]));
            }
        }
    }
}

}  // namespace
}  // namespace feel::test
