// Velocity and acceleration by adaptive windowing (FOAW).
//
// The problem. The engine sees positions quantized to one sensor count q (4.88 units on
// the joystick) once per tick. At 2% of the joystick's reference speed the handle moves
// 0.4 count per tick: the backward difference (x[k] - x[k-1])/T reads 0 on three ticks of
// five and 4880 units/s (2.4 times the true speed) on the others. A fixed low-pass filter
// fixes the slow case only by lagging every fast motion; a fixed long window does the
// same. What is needed is a window that is long when the motion is slow and steady and
// short when it changes.
//
// The method (Janabi-Sharifi, Hayward & Chen, "Discrete-time adaptive windowing for
// velocity estimation", IEEE TCST 8(6), 2000). For a window of the n+1 most recent samples,
// fit a straight line x(t) = c0 + v·(t - t_k) by least squares. If every sample lies
// within the band d of that line, the samples are consistent with one velocity and v is a
// good estimate. The velocity is the slope over the longest window that passes. The
// paper's "best-fit FOAW" is exactly this; we take d = one sensor count, because rounding
// puts every sample within q/2 of the true path and the fitted line within another q/2 of
// it: a sample one count off the fit is quantization, two counts off is a change of speed.
//
// What it gives:
//   * at rest every window passes and the slope of a constant is exactly 0: no drift, no
//     noise, and a handle dithering between two counts reads a speed near 0;
//   * on a steady slow ramp the window grows to its longest (kHistory - 1 ticks or
//     kMaxWindowUs), and the error of a least-squares slope over a window W of quantized
//     samples is about q/W at worst (49 units/s for the joystick at 1 kHz, 2.5% of a
//     2000 units/s ramp) and much less on average;
//   * on a fast ramp the window is just as long (a line is a line), so the error is the
//     same q/W in absolute terms, a tiny fraction of the speed;
//   * when the motion bends, the samples leave the band once the bend exceeds a count,
//     and the window shrinks to what the curvature allows: for an acceleration a the
//     window is about sqrt(8q/a), and the lag is half of it: on sines of 0.5..5 Hz the
//     error stays within 5..6.5% of the peak speed on the joystick at 1 kHz.
//
// Why not take the lag back. The slope of a line fitted over a window is the speed at the
// window's middle; adding the acceleration times half the window moves it to now, and cuts
// the sine error to 1..3%. But at a sudden stop a parabola fits the "hockey stick" of the
// last samples within a count, and the corrected speed swings to 40..50% of the old speed
// with the wrong sign for several ticks: a damper would push the handle the wrong way, a
// friction's microdamping would kick. A speed that lags a little but never has the wrong
// sign is what dissipative conditions need, so the estimate is the plain fitted slope.
//
// Acceleration: the same idea one order up. Fit a parabola c0 + c1·τ + c2·τ² and keep the
// longest window whose samples all lie within d of it; the acceleration is 2·c2. A
// parabola needs the motion to bend by a count within the window before it sees any
// acceleration at all, so it is only as good as the motion is smooth: on smooth hand
// motion its window is long (tens of ms) and its noise small; on an impact it reads the
// impact. It is never fitted over fewer than kMinAccelerationWindow intervals: a parabola
// through three quantized samples reads their rounding as curvature.
//
// Cost. Trying every window length costs O(N²) per axis; trying a geometric ladder of
// lengths (1, 2, 3, 4, 6, 8, 12, ... and the whole history) costs O(N) and finds a window
// within a factor 1.5 of the longest, which changes the estimate by less than its own
// noise. Each fit is computed afresh over its window with times scaled to [-1, 0], so the
// normal equations stay well conditioned at every loop rate.
#include "motion_estimator.hpp"

#include <cmath>
#include <limits>

namespace feel::detail {
namespace {

// Window lengths tried, in sample intervals, after the whole history (adaptive_window
// walks them from the longest down).
constexpr int kLadder[] = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96};

// Samples of one axis, newest first: tau[i] (s, <= 0, tau[0] = 0) and y[i] = x[i] - x[0].
struct Window {
    const double* tau;
    const double* y;
};

// Least-squares line over samples 0..n; true and the slope (units/s) if every sample lies
// within band of the line.
bool fit_line(const Window& w, int n, double band, double& slope) noexcept {
    const double span = -w.tau[n];
    if (!(span > 0)) return false;
    double s0 = 0, su = 0, suu = 0, sy = 0, suy = 0;
    for (int i = 0; i <= n; ++i) {
        const double u = w.tau[i] / span;
        s0 += 1;
        su += u;
        suu += u * u;
        sy += w.y[i];
        suy += u * w.y[i];
    }
    const double det = s0 * suu - su * su;
    if (!(det > 0)) return false;
    const double c1 = (s0 * suy - su * sy) / det;
    const double c0 = (sy - c1 * su) / s0;
    for (int i = 0; i <= n; ++i) {
        if (std::fabs(w.y[i] - (c0 + c1 * w.tau[i] / span)) > band) return false;
    }
    slope = c1 / span;
    return true;
}

// Least-squares parabola over samples 0..n (n >= 2); true and the second derivative
// (units/s²) if every sample lies within band of it.
bool fit_parabola(const Window& w, int n, double band, double& curvature) noexcept {
    const double span = -w.tau[n];
    if (!(span > 0)) return false;
    double s[5] = {};  // s[p] = Σ u^p
    double r[3] = {};  // r[p] = Σ u^p·y
    for (int i = 0; i <= n; ++i) {
        const double u = w.tau[i] / span;
        const double u2 = u * u;
        s[0] += 1;
        s[1] += u;
        s[2] += u2;
        s[3] += u2 * u;
        s[4] += u2 * u2;
        r[0] += w.y[i];
        r[1] += u * w.y[i];
        r[2] += u2 * w.y[i];
    }
    // Normal equations M·c = r with M[i][j] = s[i+j], solved by Cramer's rule.
    auto det3 = [](double a, double b, double c, double d, double e, double f, double g, double h,
                   double k) { return a * (e * k - f * h) - b * (d * k - f * g) + c * (d * h - e * g); };
    const double det = det3(s[0], s[1], s[2], s[1], s[2], s[3], s[2], s[3], s[4]);
    if (!(det > 0)) return false;
    const double c0 = det3(r[0], s[1], s[2], r[1], s[2], s[3], r[2], s[3], s[4]) / det;
    const double c1 = det3(s[0], r[0], s[2], s[1], r[1], s[3], s[2], r[2], s[4]) / det;
    const double c2 = det3(s[0], s[1], r[0], s[1], s[2], r[1], s[2], s[3], r[2]) / det;
    for (int i = 0; i <= n; ++i) {
        const double u = w.tau[i] / span;
        if (std::fabs(w.y[i] - (c0 + c1 * u + c2 * u * u)) > band) return false;
    }
    curvature = 2.0 * c2 / (span * span);
    return true;
}

// The longest window from min_n up to max_n that fit() accepts, trying the whole history
// first and then the ladder downwards; 0 if none does. `value` receives the accepted
// fit's estimate. Longest first rather than growing until the first failure: on a ramp
// whose speed is close to a whole number of counts per tick the rounding error is a slow
// sawtooth, which a middle-sized window can fail while both a short and a long one pass;
// the long one is the better estimate, and for steady motion this order needs one fit.
template <typename Fit>
int adaptive_window(const Window& w, int min_n, int max_n, double band, Fit fit, double& value) noexcept {
    constexpr int kRungs = static_cast<int>(sizeof kLadder / sizeof kLadder[0]);
    int previous = max_n + 1;
    for (int rung = kRungs; rung >= 0; --rung) {
        int n = rung == kRungs ? max_n : kLadder[rung];
        if (n > max_n) n = max_n;
        if (n >= previous) continue;
        if (n < min_n) break;
        previous = n;
        double estimate = 0;
        if (fit(w, n, band, estimate)) {
            value = estimate;
            return n;
        }
    }
    return 0;
}

}  // namespace

void MotionEstimator::configure(float sensor_step) noexcept {
    band_ = std::isfinite(sensor_step) && sensor_step > 0 ? sensor_step : 1.0f;
    reset();
}

void MotionEstimator::reset() noexcept {
    count_ = 0;
    head_ = 0;
    for (int a = 0; a < kMaxAxes; ++a) {
        velocity_[a] = acceleration_[a] = 0.0f;
        velocity_window_[a] = acceleration_window_[a] = 0;
    }
}

void MotionEstimator::update(int64_t t_us, const float position[kMaxAxes], int axis_count) noexcept {
    if (count_ > 0 && t_us < t_us_[head_]) reset();  // time went backwards: start over
    // A new slot for this sample, unless it is the same instant as the newest one or would
    // crowd it: samples before the newest stay kMinSpacingUs apart, so that the history
    // spans kMaxWindowUs at any loop rate (at 10 kHz it keeps every 8th tick, plus the
    // newest). Otherwise the newest sample is replaced by this fresher reading.
    const int previous = (head_ - 1 + kHistory) % kHistory;
    const bool crowded = count_ >= 2 && t_us - t_us_[previous] < kMinSpacingUs;
    if (count_ == 0 || (t_us > t_us_[head_] && !crowded)) {
        head_ = (head_ + 1) % kHistory;
        if (count_ < kHistory) ++count_;
    }
    t_us_[head_] = t_us;
    for (int a = 0; a < kMaxAxes; ++a) x_[a][head_] = a < axis_count ? position[a] : 0.0f;

    // The sample times relative to the newest, shared by every axis.
    double tau[kHistory];
    int max_n = 0;
    for (int i = 0; i < count_; ++i) {
        const int k = (head_ - i + kHistory) % kHistory;
        const int64_t age_us = t_us_[head_] - t_us_[k];
        if (i > 1 && age_us > kMaxWindowUs) break;  // the newest two samples are always usable
        tau[i] = -static_cast<double>(age_us) * 1e-6;
        max_n = i;
    }
    for (int a = 0; a < axis_count && a < kMaxAxes; ++a) estimate_axis(a, tau, max_n);
}

void MotionEstimator::estimate_axis(int axis, const double* tau, int max_n) noexcept {
    double y[kHistory];
    for (int i = 0; i <= max_n; ++i) {
        const int k = (head_ - i + kHistory) % kHistory;
        y[i] = static_cast<double>(x_[axis][k]) - static_cast<double>(x_[axis][head_]);
    }
    // At rest (every sample the same reading) both fits are exactly 0 over the whole
    // history: skip them, it is the commonest case.
    bool still = true;
    for (int i = 1; i <= max_n && still; ++i) still = y[i] == 0.0;
    if (still) {
        velocity_window_[axis] = max_n;
        acceleration_window_[axis] = max_n >= kMinAccelerationWindow ? max_n : 0;
        velocity_[axis] = 0.0f;
        acceleration_[axis] = 0.0f;
        return;
    }
    const Window w{tau, y};
    const double band = band_;

    double v = 0;
    const int nv = adaptive_window(w, 1, max_n, band, fit_line, v);
    // The acceleration needs a window of kMinAccelerationWindow at least: a parabola
    // through a few quantized samples reads the rounding as curvature (3 samples 1 ms
    // apart: ±q/T² = 2.4 times the joystick's acceleration_ref). Where no longer window
    // fits, the shortest one is used anyway: its estimate is the motion's mean curvature
    // over those few ms. Until the history holds that many samples, it reads 0.
    double a = 0;
    int na = 0;
    if (max_n >= kMinAccelerationWindow) {
        na = adaptive_window(w, kMinAccelerationWindow, max_n, band, fit_parabola, a);
        if (na == 0 && fit_parabola(w, kMinAccelerationWindow, std::numeric_limits<double>::infinity(), a)) {
            na = kMinAccelerationWindow;
        }
    }
    velocity_window_[axis] = nv;
    acceleration_window_[axis] = na;
    velocity_[axis] = nv > 0 && std::isfinite(v) ? static_cast<float>(v) : 0.0f;
    acceleration_[axis] = na > 0 && std::isfinite(a) ? static_cast<float>(a) : 0.0f;
}

}  // namespace feel::detail
