// The velocity estimator's accuracy figures (docs/tick-cost.md, "The velocity estimator"):
// the quantities the accuracy tests bound, measured on quantized motions whose true speed
// is known in closed form, printed as markdown rows. Run it before and after a change to
// the estimator to compare them side by side.
//
//   ramps     worst |v_est - v| / v after the first 110 ms, joystick sensor (4.88 units a
//             count), ten sub-count start phases, both directions
//   reversal  a triangle motion turning from +v to -v: ms until the estimate changes sign
//             and until it is within 5% of -v
//   stop      a ramp stopped dead: ms until the estimate reads 0, and the largest
//             wrong-sign reading (units/s)
//   rest      a handle dithering at random between two counts: RMS and worst |v| (units/s)
//   sine      worst velocity error on a 5000-unit sine, % of the peak speed
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <array>
#include <random>

#include "motion_estimator.hpp"

namespace {

using feel::kMaxAxes;
using feel::detail::MotionEstimator;

constexpr double kStep = 20000.0 / 4096.0;
constexpr double kVelocityRef = 1e5;
constexpr double kPi = 3.141592653589793;

double quantize(double x) { return kStep * std::round(x / kStep); }

MotionEstimator make() {
    MotionEstimator m;
    m.configure(static_cast<float>(kStep));
    return m;
}

double feed(MotionEstimator& m, int64_t t_us, double x) {
    float p[kMaxAxes] = {static_cast<float>(x)};
    m.update(t_us, p, 1);
    return m.velocity(0);
}

double ramp_worst(double fraction, int64_t dt_us) {
    const double v0 = fraction * kVelocityRef;
    const int64_t duration = std::min<int64_t>(static_cast<int64_t>(18000 / v0 * 1e6), 2'000'000);
    double worst = 0;
    for (double sign : {1.0, -1.0}) {
        for (int phase = 0; phase < 10; ++phase) {
            const double v = sign * v0, x0 = -sign * 9500 + phase * kStep / 10;
            MotionEstimator m = make();
            for (int64_t t = 0; t <= duration; t += dt_us) {
                const double est = feed(m, t, quantize(x0 + v * static_cast<double>(t) * 1e-6));
                if (t >= 110'000) worst = std::max(worst, std::fabs(est - v) / v0);
            }
        }
    }
    return worst;
}

void reversal(double fraction, double& to_sign_ms, double& to_5pct_ms) {
    const double v = fraction * kVelocityRef;
    MotionEstimator m = make();
    to_sign_ms = to_5pct_ms = -1;
    const int64_t turn = 300'000;
    for (int64_t t = 0; t < 600'000; t += 1000) {
        const double s = static_cast<double>(std::min(t, turn) - std::max<int64_t>(0, t - turn)) * 1e-6;
        const double est = feed(m, t, quantize(-8000 + v * s));
        if (t <= turn) continue;
        const double ms = static_cast<double>(t - turn) * 1e-3;
        if (to_sign_ms < 0 && est < 0) to_sign_ms = ms;
        if (to_5pct_ms < 0 && std::fabs(est + v) < 0.05 * v) to_5pct_ms = ms;
    }
}

void stop(double fraction, double& to_zero_ms, double& wrong_sign) {
    const double v = fraction * kVelocityRef;
    MotionEstimator m = make();
    to_zero_ms = -1;
    wrong_sign = 0;
    const int64_t at = 200'000;
    for (int64_t t = 0; t < 500'000; t += 1000) {
        const double est = feed(m, t, quantize(-9000 + v * static_cast<double>(std::min(t, at)) * 1e-6));
        if (t <= at) continue;
        wrong_sign = std::max(wrong_sign, -est);
        if (to_zero_ms < 0 && est == 0) to_zero_ms = static_cast<double>(t - at) * 1e-3;
        if (est != 0) to_zero_ms = -1;
    }
}

void rest(double& rms, double& worst) {
    MotionEstimator m = make();
    std::mt19937 random(7);
    double sum = 0;
    int n = 0;
    worst = 0;
    for (int k = 0; k < 5000; ++k) {
        const double est = feed(m, k * 1000, kStep * (300 + static_cast<int>(random() & 1)));
        if (k <= 110) continue;
        sum += est * est;
        ++n;
        worst = std::max(worst, std::fabs(est));
    }
    rms = std::sqrt(sum / n);
}

double sine_worst(double hz) {
    MotionEstimator m = make();
    const double amplitude = 5000, w = 2 * kPi * hz;
    double worst = 0;
    for (int k = 0; k < 3000; ++k) {
        const double t = k * 1e-3;
        const double est = feed(m, k * 1000, quantize(amplitude * std::sin(w * t)));
        if (k >= 150) worst = std::max(worst, std::fabs(est - amplitude * w * std::cos(w * t)));
    }
    return worst / (amplitude * w);
}

}  // namespace

int main() {
    std::printf("| quantized ramp, %% of velocity_ref | 0.25%% | 0.5%% | 1%% | 2%% | 5%% | 20%% | 100%% |\n|---|---|---|---|---|---|---|---|\n");
    for (int64_t dt : {1000, 100, 5000}) {
        std::printf("| worst error at %g Hz |", 1e6 / static_cast<double>(dt));
        for (double f : {0.0025, 0.005, 0.01, 0.02, 0.05, 0.2, 1.0}) std::printf(" %.3g%% |", 100 * ramp_worst(f, dt));
        std::printf("\n");
    }
    std::printf("\n| motion | 2%% | 20%% | 100%% |\n|---|---|---|---|\n");
    double a[3], b[3];
    for (int i = 0; i < 3; ++i) reversal(std::array{0.02, 0.2, 1.0}[i], a[i], b[i]);
    std::printf("| reversal: ms to the new sign | %g | %g | %g |\n", a[0], a[1], a[2]);
    std::printf("| reversal: ms to within 5%% of the new speed | %g | %g | %g |\n", b[0], b[1], b[2]);
    for (int i = 0; i < 3; ++i) stop(std::array{0.02, 0.2, 1.0}[i], a[i], b[i]);
    std::printf("| stop: ms to exactly 0 | %g | %g | %g |\n", a[0], a[1], a[2]);
    std::printf("| stop: largest wrong-sign reading, units/s | %g | %g | %g |\n", b[0], b[1], b[2]);
    double rms = 0, worst = 0;
    rest(rms, worst);
    std::printf("\n| at rest, dithering between two counts | RMS %.3g units/s | worst %.3g units/s |\n", rms, worst);
    std::printf("| sine 5000 units, worst error, %% of peak speed | 0.5 Hz: %.2f%% | 2 Hz: %.2f%% | 5 Hz: %.2f%% |\n",
                100 * sine_worst(0.5), 100 * sine_worst(2), 100 * sine_worst(5));
    return 0;
}
