// The waveforms `feel stream` sends and its measurements of the device's reconstruction,
// against the waveforms' definitions and signals built with a known delay and overshoot.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "stream_wave.hpp"

namespace feel::cli {
namespace {

TEST(StreamWave, NamesParseAndOthersDoNot) {
    EXPECT_EQ(stream_shape_from_name("sine"), StreamShape::sine);
    EXPECT_EQ(stream_shape_from_name("square"), StreamShape::square);
    EXPECT_EQ(stream_shape_from_name("step"), StreamShape::step);
    EXPECT_FALSE(stream_shape_from_name("Sine"));
    EXPECT_FALSE(stream_shape_from_name("triangle"));
}

TEST(StreamWave, SineHasItsAmplitudeAndPeriod) {
    const StreamWave w{StreamShape::sine, 4000, 2, 3};
    EXPECT_NEAR(w.at(0), 0, 1e-9);
    EXPECT_NEAR(w.at(0.125), 4000, 1e-9);   // a quarter period of 0.5 s
    EXPECT_NEAR(w.at(0.375), -4000, 1e-9);
    EXPECT_NEAR(w.at(0.3), w.at(0.8), 1e-9);  // periodic
    EXPECT_EQ(w.at(-0.1), 0);                 // nothing before the stream
}

TEST(StreamWave, SquareIsHighForTheFirstHalfOfEachPeriod) {
    const StreamWave w{StreamShape::square, 3000, 4, 3};  // period 0.25 s
    EXPECT_EQ(w.at(0), 3000);
    EXPECT_EQ(w.at(0.1), 3000);
    EXPECT_EQ(w.at(0.13), -3000);
    EXPECT_EQ(w.at(0.26), 3000);
}

TEST(StreamWave, StepRisesHalfWay) {
    const StreamWave w{StreamShape::step, 7000, 1, 2};
    EXPECT_EQ(w.at(0.99), 0);
    EXPECT_EQ(w.at(1.0), 7000);
    EXPECT_EQ(w.at(1.9), 7000);
}

// A device that plays each sample exactly, `delay` after it was sent, sampled by 1 kHz
// reports: the fit finds the delay, and nothing overshoots.
TEST(StreamObserver, FindsTheDelayOfAFaithfulReconstruction) {
    const StreamWave w{StreamShape::sine, 5000, 2, 2};
    const double rate = 100, delay = 0.020;
    // Reports: the ideal waveform delayed (a perfectly smooth reconstruction).
    StreamObserver smooth(w, 1 / rate);
    for (int k = 0; k < 200; ++k) smooth.sent(k / rate, w.at(k / rate));
    for (int i = 0; i < 2000; ++i) {
        const double t = i / 1000.0;
        smooth.applied(t, w.at(t - delay));
    }
    const StreamObserver::DelayFit fit = smooth.fit_delay();
    EXPECT_NEAR(fit.delay_s, delay, StreamObserver::kDelayStepS);
    EXPECT_LT(fit.max_error, 1e-6);
    // Without aligning, the error is the slope times the delay: 2π·F·A·delay at the zero
    // crossings.
    EXPECT_NEAR(smooth.max_error(), 2 * std::numbers::pi * 2 * 5000 * delay, 30);
    EXPECT_EQ(smooth.samples_sent(), 200u);
    EXPECT_EQ(smooth.reports(), 2000u);
}

TEST(StreamObserver, LinearInterpolationBetweenSamplesDoesNotOvershoot) {
    const StreamWave w{StreamShape::square, 6000, 5, 1};
    const double rate = 60;
    StreamObserver o(w, 1 / rate);
    // Send on a 60 Hz grid; the device ramps from the previous sample to the newest over
    // one interval, the design of runtime/force_stream.hpp.
    double previous = 0;
    int k = 0;
    for (int i = 0; i < 1000; ++i) {
        const double t = i / 1000.0;
        while (k / rate <= t) {
            previous = k == 0 ? 0 : std::round(w.at((k - 1) / rate));
            o.sent(k / rate, std::round(w.at(k / rate)));
            ++k;
        }
        const double since = t - (k - 1) / rate;
        const double target = std::round(w.at((k - 1) / rate));
        const double x = std::min(1.0, since * rate);
        o.applied(t, previous + (target - previous) * x);
    }
    EXPECT_LT(o.max_overshoot(), 1e-9);
}

TEST(StreamObserver, ReportsAnOvershoot) {
    const StreamWave w{StreamShape::step, 5000, 1, 0.2};
    StreamObserver o(w, 0.01);
    for (int k = 0; k < 20; ++k) o.sent(k * 0.01, w.at(k * 0.01));
    // A ringing reconstruction: 5% above the step's top, and a dip below 0 before it.
    o.applied(0.05, -120);
    o.applied(0.15, 5250);
    EXPECT_NEAR(o.max_overshoot(), 250, 1e-9);
    StreamObserver dip(w, 0.01);
    for (int k = 0; k < 5; ++k) dip.sent(k * 0.01, 0);
    dip.applied(0.045, -120);
    EXPECT_NEAR(dip.max_overshoot(), 120, 1e-9);
}

}  // namespace
}  // namespace feel::cli
