// The force stream's reconstruction filter on its own (force_stream.hpp), against truths
// from outside the code: the samples the host sent (the output must stay inside their
// range: no overshoot), the size of a zero-order hold's step (the filter's steps must be
// that step spread over one sample interval), the sine the host sampled (the output is that
// sine, one interval late, within the error of linear interpolation), and a 1 kHz stream
// (which must come out unchanged).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "feel/runtime/force_stream.hpp"

namespace feel::runtime {
namespace {

constexpr int32_t kLoopHz = 1000;

// One sample, as the host sent it.
struct Sample {
    int64_t tick = 0;
    int16_t value = 0;
};

// The tick in which a host streaming at `rate_hz` delivers sample k: the first loop tick at
// or after k/rate (a 60 Hz game frame on a 1 kHz loop: 16 or 17 ticks apart).
int64_t arrival_tick(int64_t k, double rate_hz) {
    return static_cast<int64_t>(std::ceil(static_cast<double>(k) * kLoopHz / rate_hz - 1e-9));
}

// Runs a 1-axis stream over ticks [0, end) and returns the output of every tick.
std::vector<float> reconstruct(const std::vector<Sample>& samples, int64_t end, ForceStream& stream) {
    std::vector<float> out(static_cast<size_t>(end));
    size_t next = 0;
    for (int64_t t = 0; t < end; ++t) {
        while (next < samples.size() && samples[next].tick == t) stream.push(t, &samples[next++].value);
        float force[kMaxAxes];
        stream.output(t, force);
        out[static_cast<size_t>(t)] = force[0];
        for (int a = 1; a < kMaxAxes; ++a) EXPECT_EQ(force[a], 0.0f);
    }
    return out;
}

std::vector<float> reconstruct(const std::vector<Sample>& samples, int64_t end) {
    ForceStream stream(1, kLoopHz);
    return reconstruct(samples, end, stream);
}

float largest_step(const std::vector<float>& out, size_t from) {
    float step = 0;
    for (size_t t = std::max<size_t>(from, 1); t < out.size(); ++t) step = std::max(step, std::abs(out[t] - out[t - 1]));
    return step;
}

TEST(ForceStream, NothingStreamedIsNoForce) {
    ForceStream stream(3, kLoopHz);
    float force[kMaxAxes];
    stream.output(123, force);
    for (float f : force) EXPECT_EQ(f, 0.0f);
    EXPECT_FALSE(stream.active());
}

TEST(ForceStream, AOneKilohertzStreamPassesThroughUnchanged) {
    // One sample per tick on a 1 kHz loop: after the first sample (whose rate is not known
    // yet) every tick's output is that tick's sample, exactly: no delay at all.
    std::vector<Sample> samples;
    uint32_t noise = 12345;
    for (int64_t t = 0; t < 2000; ++t) {
        noise = noise * 1103515245u + 12345u;
        samples.push_back({t, static_cast<int16_t>(static_cast<int32_t>((noise >> 8) % 20001) - 10000)});
    }
    const std::vector<float> out = reconstruct(samples, 2000);
    for (size_t t = 1; t < out.size(); ++t) ASSERT_EQ(out[t], samples[t].value) << "tick " << t;
}

TEST(ForceStream, ASixtyHertzSineIsReconstructedWithoutOvershootOrSteps) {
    // A game at 60 Hz streams a 2 Hz sine of amplitude 8000 for 3 s.
    constexpr double kRate = 60, kFrequency = 2, kAmplitude = 8000;
    std::vector<Sample> samples;
    for (int64_t k = 0; arrival_tick(k, kRate) < 3000; ++k) {
        const double t_s = static_cast<double>(k) / kRate;
        samples.push_back({arrival_tick(k, kRate),
                           static_cast<int16_t>(std::lround(kAmplitude * std::sin(2 * std::numbers::pi * kFrequency * t_s)))});
    }
    const std::vector<float> out = reconstruct(samples, 3000);

    // No overshoot: from the second sample on, every tick's output lies within the range of
    // the samples around it (the newest and the two before it), and never beyond the sine.
    size_t k = 1;
    for (int64_t t = samples[2].tick; t < 3000; ++t) {
        while (k + 1 < samples.size() && samples[k + 1].tick <= t) ++k;
        const int16_t lo = std::min({samples[k - 1].value, samples[k].value, k >= 2 ? samples[k - 2].value : samples[k - 1].value});
        const int16_t hi = std::max({samples[k - 1].value, samples[k].value, k >= 2 ? samples[k - 2].value : samples[k - 1].value});
        const float y = out[static_cast<size_t>(t)];
        ASSERT_GE(y, lo) << "tick " << t;
        ASSERT_LE(y, hi) << "tick " << t;
        ASSERT_LE(std::abs(y), kAmplitude);
    }

    // No steps: the largest change between samples, spread over one sample interval
    // (1 kHz / 60 Hz = 16.7 ticks), within a small factor for the 16-or-17-tick frames.
    int32_t largest_delta = 0;
    for (size_t i = 1; i < samples.size(); ++i)
        largest_delta = std::max(largest_delta, std::abs(samples[i].value - samples[i - 1].value));
    const double spread = largest_delta / (kLoopHz / kRate);
    const float step = largest_step(out, static_cast<size_t>(samples[2].tick));
    EXPECT_LE(step, 1.15 * spread) << "largest sample change " << largest_delta;
    EXPECT_LT(step, largest_delta / 10.0);  // a zero-order hold would step by largest_delta

    // It is the sine, one sample interval late: within the error of linear interpolation
    // of a sine (A·ω²·h²/8 = 44) plus the sine's slope (A·ω = 100 per ms) times the most
    // the filter's delay can differ from 16.7 ms (a sample lands up to 1 tick after its
    // frame began and ramps over T = 16 or 17 ticks: a delay of 15..17 ms, 1.7 ms off).
    double worst = 0;
    for (int64_t t = 100; t < 3000; ++t) {
        const double late_s = (static_cast<double>(t) - kLoopHz / kRate) / kLoopHz;
        const double truth = kAmplitude * std::sin(2 * std::numbers::pi * kFrequency * late_s);
        worst = std::max(worst, std::abs(out[static_cast<size_t>(t)] - truth));
    }
    EXPECT_LE(worst, 44 + 1.7 * kAmplitude * 2 * std::numbers::pi * kFrequency / 1000);
}

TEST(ForceStream, AStepRisesMonotonicallyWithoutOvershoot) {
    // 0 for half a second, then 5000, at 60 Hz.
    std::vector<Sample> samples;
    int64_t step_tick = 0;
    for (int64_t k = 0; arrival_tick(k, 60) < 2000; ++k) {
        const int64_t tick = arrival_tick(k, 60);
        const bool high = tick >= 500;
        if (high && step_tick == 0) step_tick = tick;
        samples.push_back({tick, static_cast<int16_t>(high ? 5000 : 0)});
    }
    const std::vector<float> out = reconstruct(samples, 2000);
    for (int64_t t = 0; t < step_tick; ++t) ASSERT_EQ(out[static_cast<size_t>(t)], 0.0f);
    for (int64_t t = step_tick; t < 2000; ++t) {
        const auto i = static_cast<size_t>(t);
        ASSERT_GE(out[i], out[i - 1]) << "tick " << t << ": not monotonic";
        ASSERT_LE(out[i], 5000.0f) << "tick " << t << ": overshoot";
    }
    // It is there one sample interval (17 ticks at most) after the step arrived, and stays.
    EXPECT_EQ(out[static_cast<size_t>(step_tick + 16)], 5000.0f);
    // Its steps are the step spread over ~16.7 ticks, not 5000 at once.
    EXPECT_LE(largest_step(out, 0), 5000.0f / 16.0f + 0.01f);
    EXPECT_GT(out[static_cast<size_t>(step_tick)], 0.0f);  // and it starts at once: no dead time
}

TEST(ForceStream, HoldsTheLastSampleWhenTheStreamStops) {
    std::vector<Sample> samples;
    for (int64_t k = 0; k < 30; ++k) samples.push_back({arrival_tick(k, 60), static_cast<int16_t>(-100 * k)});
    const std::vector<float> out = reconstruct(samples, 10'000);  // 10 s
    for (int64_t t = samples.back().tick + 17; t < 10'000; ++t) ASSERT_EQ(out[static_cast<size_t>(t)], -2900.0f);
}

TEST(ForceStream, AJitteredStreamStillNeverStepsOrOvershoots) {
    // 60 Hz with a late frame followed by an early one (two samples in consecutive ticks),
    // then a frame dropped: the median interval keeps the ramps ~17 ticks long.
    const int64_t ticks[] = {0, 17, 33, 50, 67, 83, 100, 117, 150, 151, 167, 183, 217, 233, 250, 267, 283};
    std::vector<Sample> samples;
    for (size_t i = 0; i < std::size(ticks); ++i) samples.push_back({ticks[i], static_cast<int16_t>(i % 2 ? 3000 : -3000)});
    const std::vector<float> out = reconstruct(samples, 400);
    for (float y : out) {
        ASSERT_LE(y, 3000.0f);
        ASSERT_GE(y, -3000.0f);
    }
    // A change of 6000 over a ~16-tick ramp; the burst's early sample starts its ramp where
    // the output is, so it cannot step either.
    EXPECT_LE(largest_step(out, 20), 6000.0f / 15.0f);
}

TEST(ForceStream, FollowsAHostThatSpeedsUp) {
    std::vector<Sample> samples;
    for (int64_t k = 0; k < 20; ++k) samples.push_back({arrival_tick(k, 60), static_cast<int16_t>(50 * k)});
    const int64_t fast_from = samples.back().tick + 17;
    for (int64_t t = fast_from; t < fast_from + 100; ++t) samples.push_back({t, static_cast<int16_t>(t - 3000)});
    const std::vector<float> out = reconstruct(samples, fast_from + 100);
    // Once most of the remembered intervals are one tick, each sample plays in its tick.
    for (int64_t t = fast_from + ForceStream::kIntervalHistory; t < fast_from + 100; ++t)
        ASSERT_EQ(out[static_cast<size_t>(t)], static_cast<float>(t - 3000)) << "tick " << t;
}

TEST(ForceStream, TwoSamplesInOneTickCountAsOneArrivalTheNewestWins) {
    ForceStream stream(1, kLoopHz);
    for (int64_t t = 0; t < 10; ++t) {
        const int16_t v = 100;
        stream.push(t, &v);
    }
    const int16_t first = 2000, second = 4000;
    stream.push(10, &first);
    stream.push(10, &second);
    EXPECT_EQ(stream.interval_ticks(), 1);
    float force[kMaxAxes];
    stream.output(10, force);
    EXPECT_EQ(force[0], 4000.0f);
    EXPECT_EQ(stream.samples(), 12);
}

TEST(ForceStream, ClearEndsTheStreamAndForgetsItsRate) {
    ForceStream stream(2, kLoopHz);
    const int16_t v[2] = {7000, -7000};
    for (int64_t t = 0; t < 10; ++t) stream.push(t, v);
    EXPECT_TRUE(stream.active());
    EXPECT_EQ(stream.interval_ticks(), 1);
    stream.clear();
    EXPECT_FALSE(stream.active());
    float force[kMaxAxes];
    stream.output(11, force);
    EXPECT_EQ(force[0], 0.0f);
    EXPECT_EQ(force[1], 0.0f);
    // A 60 Hz frame again until a new interval is measured (round(16.667 ms · 1 kHz)).
    EXPECT_EQ(stream.interval_ticks(), 17);
    // A new stream starts from 0, not from the old value: its first ramp begins at 0.
    stream.push(20, v);
    stream.output(20, force);
    EXPECT_NEAR(force[0], 7000.0f / 17, 1e-3);
}

TEST(ForceStream, IntervalsScaleWithTheLoopRate) {
    ForceStream slow(1, 500);
    EXPECT_EQ(slow.interval_ticks(), 8);            // 16.667 ms at 2 ms per tick
    EXPECT_EQ(slow.max_interval_ticks(), 50);       // 100 ms
    ForceStream fast(1, 20'000);
    EXPECT_EQ(fast.interval_ticks(), 333);
    EXPECT_EQ(fast.max_interval_ticks(), 2000);
    // A pause in the stream longer than 100 ms is not an interval.
    ForceStream stream(1, kLoopHz);
    const int16_t v = 1;
    stream.push(0, &v);
    stream.push(5000, &v);
    EXPECT_EQ(stream.interval_ticks(), 17);
}

TEST(AddStreamedForce, ScalesByGainCutsWhenOffAndClampsTheSum) {
    const float streamed[kMaxAxes] = {6000, -6000, 4000, 0, 0, 0};
    float force[kMaxAxes] = {1000, -1000, 8000, 0, 0, 0};
    add_streamed_force(streamed, 3, 5000, true, force);  // half gain
    EXPECT_EQ(force[0], 4000.0f);
    EXPECT_EQ(force[1], -4000.0f);
    EXPECT_EQ(force[2], 10000.0f);  // 8000 + 2000
    float sum[kMaxAxes] = {8000, -8000, 0, 0, 0, 0};
    add_streamed_force(streamed, 2, 10000, true, sum);
    EXPECT_EQ(sum[0], 10000.0f);   // 14000, clamped
    EXPECT_EQ(sum[1], -10000.0f);  // -14000, clamped
    EXPECT_EQ(sum[2], 0.0f);       // beyond the axes
    float off[kMaxAxes] = {300, 0, 0, 0, 0, 0};
    add_streamed_force(streamed, 2, 10000, false, off);
    EXPECT_EQ(off[0], 300.0f);
    float bad[kMaxAxes] = {std::nanf(""), INFINITY, 0, 0, 0, 0};
    add_streamed_force(streamed, 2, 10000, true, bad);
    EXPECT_EQ(bad[0], 0.0f);
    EXPECT_EQ(bad[1], 0.0f);
}

}  // namespace
}  // namespace feel::runtime
