// The same inputs give bit-identical outputs, and no input the validator accepts can make
// the engine emit NaN, inf or a force beyond the device maximum.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include "engine_fixture.hpp"
#include "feel/effect_validation.hpp"

namespace feel::test {
namespace {

// A busy mix of every wave type on two axes.
std::vector<EffectParams> wave_mix() {
    std::vector<EffectParams> mix;
    const EffectType periodic[] = {EffectType::sine, EffectType::square, EffectType::triangle,
                                   EffectType::saw_up, EffectType::saw_down};
    int i = 0;
    for (EffectType t : periodic) {
        EffectParams p = on_xy_polar(periodic_on_x(t, 1000 + 500 * i, 100 * i, 7'000 + 3'000 * i, 1234 * i, 800'000), 4500 * i);
        p.has_envelope = true;
        p.envelope = {8000, 30'000, 0, 100'000};
        mix.push_back(p);
        EffectParams s = periodic_on_x(static_cast<EffectType>(static_cast<int>(EffectType::sweep_sine) + i),
                                       2000, 0, 11'000, 0, 600'000);
        s.axis_count = 2;
        s.axes[1] = Axis::y;
        s.periodic.sweep_start_angle = 1000 * i;
        s.periodic.sweep_end_angle = 30000 - 1000 * i;
        s.periodic.sweep_sense = i % 2 ? SweepSense::clockwise : SweepSense::counterclockwise;
        mix.push_back(s);
        ++i;
    }
    EffectParams ramp = constant_on_x(0, 400'000);
    ramp.type = EffectType::ramp;
    ramp.ramp = {-5000, 5000};
    ramp.iterations = 2;
    mix.push_back(ramp);
    mix.push_back(on_xy_polar(constant_on_x(3000, 300'000), 27000));
    return mix;
}

std::vector<TickOutput> run(const std::vector<EffectParams>& mix) {
    EngineConfig c;
    Engine e(c);
    for (const EffectParams& p : mix) {
        const CreateResult r = e.create(p);
        EXPECT_TRUE(r.error.ok()) << r.error.message();
        EXPECT_TRUE(e.start(r.id).ok());
    }
    std::vector<TickOutput> out(1000);
    for (int n = 0; n < 1000; ++n) {
        TickInput in;
        in.t_us = n * 1000;
        in.position[0] = static_cast<float>(n % 37);
        e.tick(in, out[static_cast<size_t>(n)]);
    }
    return out;
}

TEST(Determinism, SameInputsGiveBitIdenticalOutputs) {
    const auto mix = wave_mix();
    const auto a = run(mix);
    const auto b = run(mix);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(std::memcmp(a[i].force, b[i].force, sizeof a[i].force), 0) << "tick " << i;
    }
}

// Random valid wave effects: whatever the parameters, every force is finite and within
// ±10000 on every axis.
RC_GTEST_PROP(EngineSafety, AnyValidWaveStaysFiniteAndWithinTheMaximum, ()) {
    const auto type = *rc::gen::element(EffectType::constant, EffectType::vector_force, EffectType::smart_pop,
                                        EffectType::sine, EffectType::square, EffectType::triangle,
                                        EffectType::saw_up, EffectType::saw_down, EffectType::ramp,
                                        EffectType::sweep_sine, EffectType::sweep_saw_down);
    EffectParams p;
    p.type = type;
    p.duration_us = *rc::gen::inRange<int64_t>(1, kMaxTimeUs + 1);
    p.start_delay_us = *rc::gen::inRange<int64_t>(0, 100'000);
    p.gain = *rc::gen::inRange(0, kFullScale + 1);
    p.iterations = *rc::gen::inRange(1, 256);
    p.axis_count = 2;
    p.axes[0] = Axis::x;
    p.axes[1] = Axis::y;
    if (!is_sweep(type)) {
        p.direction.kind = DirectionKind::polar;
        p.direction.value[0] = *rc::gen::inRange(0, 36000);
    }
    const bool envelope = supports_envelope(type) && *rc::gen::arbitrary<bool>();
    if (envelope) {
        p.has_envelope = true;
        p.envelope = {*rc::gen::inRange(0, kFullScale + 1), *rc::gen::inRange<int64_t>(0, kMaxTimeUs + 1),
                      *rc::gen::inRange(0, kFullScale + 1), *rc::gen::inRange<int64_t>(0, kMaxTimeUs + 1)};
    }
    p.constant.magnitude = *rc::gen::inRange(-kFullScale, kFullScale + 1);
    p.ramp = {*rc::gen::inRange(-kFullScale, kFullScale + 1), *rc::gen::inRange(-kFullScale, kFullScale + 1)};
    p.periodic.magnitude = *rc::gen::inRange(is_sweep(type) ? -kFullScale : 0, kFullScale + 1);
    p.periodic.offset = *rc::gen::inRange(-kFullScale, kFullScale + 1);
    p.periodic.period_us = *rc::gen::inRange<int64_t>(1, kMaxTimeUs + 1);
    p.periodic.phase = *rc::gen::inRange(0, 36000);
    p.periodic.sweep_start_angle = *rc::gen::inRange(0, 36000);
    p.periodic.sweep_end_angle = *rc::gen::inRange(0, 36000);
    RC_PRE(validate_effect(p).ok());

    EngineConfig c;
    Engine e(c);
    for (int copies = 0; copies < 3; ++copies) {
        const CreateResult r = e.create(p);
        RC_ASSERT(r.error.ok());
        RC_ASSERT(e.start(r.id).ok());
    }
    const int64_t step = *rc::gen::inRange<int64_t>(1, 50'000);
    for (int n = 0; n < 200; ++n) {
        TickInput in;
        in.t_us = n * step;
        TickOutput out;
        e.tick(in, out);
        for (int a = 0; a < kMaxAxes; ++a) {
            RC_ASSERT(std::isfinite(out.force[a]));
            RC_ASSERT(std::fabs(out.force[a]) <= 10000.0f);
        }
    }
}

}  // namespace
}  // namespace feel::test
