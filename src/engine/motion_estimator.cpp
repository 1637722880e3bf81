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
// lengths (1, 2, 3, 4, 6, 8, 12, ... and the whole history) finds a window within a factor
// 1.5 of the longest, which changes the estimate by less than its own noise. The ladder's
// fits are cheap because of how they are computed:
//   * every window ends at the newest sample, so the least-squares sums of all of them
//     come from one pass over the history: the sums of each segment between two rungs
//     (y, u·y, u²·y; four independent partial sums, which the compiler turns into vector
//     code), added up rung by rung. A fit is then a handful of operations (Cramer's rule).
//   * the time sums (Σu^p) and the times themselves are shared by all axes and change only
//     when the loop's rhythm does: at a steady rate every sample's age is i·T, so they are
//     computed once and kept (refresh_time_pattern).
//   * the band check (every sample within a count of the fit) is the one O(n) part; it
//     first tries the newest samples and the window's eighths, where a window too long
//     for a bending motion leaves the band, so a failed rung costs a few samples.
// That is the general path. On the common one (every older interval the same, positions
// within range) the sums come without a pass at all (issue 14):
//   * the sums over the frozen samples (all but the newest, which a fresher reading of the
//     same instant may replace) are kept in 64-bit integers, the positions as integers of
//     a power-of-two unit far below a sensor count. Where the build optimises for speed
//     (x86) they are prefix sums through every frozen sample, one addition of three terms
//     a tick, and a window's sums are the difference of two (issue 14, twelfth pass: the
//     slides below were a fifth of the moving tick's estimator); on the board (RAM) each
//     ladder window's sums, slid by O(1) updates when a sample arrives (slide_sums), not
//     at all at rest (window_sums). Integers are exact, so the sums never drift and both
//     are the same numbers;
//   * the band is checked on a fixed set of samples: the newest kDenseSamples, where a
//     stop or a reversal shows first, and the window's eighths, where a bend shows, looked
//     at in the order windows fail (within_band);
//   * the downward search starts kRungsUp above the window accepted last tick.
// Where the build optimises for speed (x86) the tick's common cases have their own code: a
// line's window sums without the parabola's share, each rung's determinants kept with the
// time pattern, the newest samples gathered once a tick and checked as vectors; the board
// (-Os) keeps one path for each (flash, RAM). Both give the same bits.
// On bench/motion_estimator_accuracy.cpp's motions it gives the general path's figures
// (docs/tick-cost.md has both side by side).
// Times are fitted as u = -age / kMaxWindowUs, in [-1, 0]. Each term of Cramer's rule for a
// window of span σ scales as the same power of σ, so fitting in these fixed units has the
// rounding of fitting in [-1, 0] per window: single precision is enough (the normal
// equations of a parabola on [-1, 0] lose about 2 of float's 7 digits).
//
// Memory and code (issue 14's RAM and flash). The ring keeps one copy of each position, the
// float it was given: the running sums' fixed-point value of a sample is worked out when
// they read it (fixed_at: a multiplication and a rounding, 9 samples an axis a tick), not
// kept beside it (512 bytes an axis). Both paths share one fit loop (fit: the line and the
// parabola by Cramer's rule, the band check, the search down the rungs); only the sums
// (running or gathered) and the set of samples checked differ, so the Cortex-M4 carries
// one copy of each.
//
// Everything is float and every sum is taken in a fixed order, without fused multiply-adds
// (the firmware build turns contraction off), so x86 and the Cortex-M4 agree bit for bit.
#include "motion_estimator.hpp"

#include <cmath>

#include "int64_to_float.hpp"

namespace feel::detail {
namespace {

static_assert((MotionEstimator::kHistory & (MotionEstimator::kHistory - 1)) == 0, "the ring is indexed by a mask");
constexpr int kMask = MotionEstimator::kHistory - 1;
constexpr float kUnitsPerUs = 1.0f / static_cast<float>(MotionEstimator::kMaxWindowUs);

// The ring keeps the low 32 bits of each sample's time (issue 14: 512 bytes less). The time
// between two of them is exact while it is under 2^32 µs: update() restarts the history
// after a gap of kMaxGapUs or more between ticks, so every interval in the ring is shorter,
// and the ages the fits read (at most the window plus one interval) are too.
constexpr uint32_t low_bits(int64_t t_us) noexcept { return static_cast<uint32_t>(static_cast<uint64_t>(t_us)); }
constexpr int64_t elapsed_us(uint32_t later, uint32_t earlier) noexcept {
    return static_cast<int64_t>(static_cast<uint32_t>(later - earlier));
}
// u is time in units of kMaxWindowUs: d/dt = d/du / kWindowS.
constexpr float kWindowS = static_cast<float>(MotionEstimator::kMaxWindowUs) * 1e-6f;


// A 3x3 determinant expanded along its first row (a, b, c) with the minors of each
// (minor_a = e·k - f·h, minor_b = d·k - f·g, minor_c = d·h - e·g for rows (d, e, f) and
// (g, h, k)): apart so that a minor of the normal matrix alone can be the time pattern's.
float expand_row(float a, float b, float c, float minor_a, float minor_b, float minor_c) noexcept {
    return a * minor_a - b * minor_b + c * minor_c;
}
float det3(float a, float b, float c, float d, float e, float f, float g, float h, float k) noexcept {
    return expand_row(a, b, c, e * k - f * h, d * k - f * g, d * h - e * g);
}
// A line's normal matrix's determinant: m0 = Σ u⁰ (the sample count), m1 = Σ u, m2 = Σ u².
float line_det(float m0, float m1, float m2) noexcept { return m0 * m2 - m1 * m1; }

// Σ m^p·X over m = 0..n-1 for a constant X (p = 0, 1, 2): a window at rest, or the newest
// sample's share of a window's sums. Exact in 64-bit integers.
// n is a window's length in samples, at most kHistory: Σ m and Σ m² are int32 (the division
// by 2 and 6 stays 32-bit: a Cortex-M4 has no 64-bit division in hardware) and exact.
static_assert((MotionEstimator::kHistory - 1) * MotionEstimator::kHistory * (2 * MotionEstimator::kHistory - 1) <=
              INT32_MAX);
// Σ m and Σ m² over m = 0..n-1, 0 <= n <= kHistory (unsigned: the divisions by a constant
// are a multiplication and a shift).
constexpr int32_t sum_of_m(int n) noexcept { return static_cast<int32_t>(static_cast<uint32_t>(n * (n - 1)) / 2u); }
constexpr int32_t sum_of_m_squared(int n) noexcept {
    return static_cast<int32_t>(static_cast<uint32_t>((n - 1) * n * (2 * n - 1)) / 6u);
}
// Out of line on the board: three callers share one copy (flash). The ladder's sums only
// (FEEL_ESTIMATOR_SPEED_TABLES 0: the prefix sums read the time pattern's Σ m^p).
#if defined(__OPTIMIZE_SIZE__)
[[gnu::noinline]]
#endif
[[maybe_unused]] void constant_sums(int n, int64_t value, int64_t out[3]) noexcept {
    out[0] = n * value;
    out[1] = int64_t{sum_of_m(n)} * value;
    out[2] = int64_t{sum_of_m_squared(n)} * value;
}

// The prefix sums through a frozen sample from those through the one before it: its value
// X with weights 1, j, j² (FEEL_ESTIMATOR_SPEED_TABLES), modulo 2^64.
[[maybe_unused]] inline void add_prefix(const uint64_t before[3], uint64_t j, uint64_t value, uint64_t out[3]) noexcept {
    out[0] = before[0] + value;
    out[1] = before[1] + j * value;
    out[2] = before[2] + j * j * value;
}

// Whether a fit solves for every coefficient, read or not: on the board, in one straight
// path (the branch would cost its flash); elsewhere it solves only for those it reads.
#if defined(__OPTIMIZE_SIZE__)
constexpr bool kSolveUnread = true;
#else
constexpr bool kSolveUnread = false;
#endif

// Where the running-sum fits start their downward search: kRungsUp above the rung accepted
// last time, the whole history (top) at most. The full search (longest window first) is
// what the general path does every tick; a window that passed last tick grows by a rung or
// two a tick at most, so starting a little above it finds the same window except when the
// motion has just turned steady after a bend: then the window grows back to its longest
// over a few ticks instead of at once.
int start_rung(int previous, int top) noexcept {
    return previous + MotionEstimator::kRungsUp < top ? previous + MotionEstimator::kRungsUp : top;
}

// The band check on the running-sum path looks at a fixed set of samples within 0..n: the
// newest kDenseSamples one by one (where a stop or a reversal first shows), then the
// window's eighths (where a bend shows: a line fitted to a curve departs from it most at
// the ends and the middle, a parabola fitted to a cubic at the ends and at about a sixth in
// from them). The general path checks the same set first, then every other sample.
constexpr int kDenseSamples = MotionEstimator::kDenseSamples;
// The newest samples relative to the newest one, dense[i] = x_i - x_0 (i = 0..kDenseSamples),
// gathered once an axis and tick on x86 for every band check of both fits (dense_samples).
constexpr int kDenseSlots = MotionEstimator::kDenseSlots;

// True if every sample of a window of n intervals lies within band of c0 + c1·u (+ c2·u²
// for a parabola): on the running-sum path (y null) the fixed set of samples kDenseSamples
// describes, read from the ring (x, head, x0: one axis's ring and its newest sample), the
// dense ones on x86 from `dense` (dense_samples); on the general path (y: the gathered
// samples, the same values) that set first, then every other sample in one pass without
// branches (vector code). Every sample is judged alone, so the order they are looked at in
// changes the cost only (issue 14, measured on the slow circle: a window that fails leaves
// the band at its oldest sample two times in three, at a dense one otherwise): on x86 the
// oldest first, then the dense ones as whole vectors, then the other eighths. A template on
// the order: the line's check is the tick's commonest loop, and a parabola's terms would
// cost it a third more.
template <bool kParabola>
bool within_band(const float* dense, const float* x, int head, float x0, const float* u, const float* y, int n,
                 float c0, float c1, float c2, float band) noexcept {
    auto outside = [=](float yi, int i) {
        const float fit = kParabola ? c0 + c1 * u[i] + c2 * (u[i] * u[i]) : c0 + c1 * u[i];
        return std::fabs(yi - fit) > band;
    };
    const auto step = static_cast<unsigned>(n);
    const int last_dense = n < kDenseSamples ? n : kDenseSamples;
#if defined(__OPTIMIZE_SIZE__)
    // The board (flash): the dense samples read from the ring (dense is null), each with an
    // early exit, then the eighths from the oldest.
    static_cast<void>(dense);
    for (int i = 0; i <= last_dense; ++i) {
        if (outside(x[(head + i) & kMask] - x0, i)) return false;
    }
    const unsigned first_eighth = 8;
#else
    // The oldest sample, where a window too long for the motion leaves the band first; then
    // the dense samples, where it fails next most often, as two vectors without a branch.
    if (n > kDenseSamples && outside(x[(head + n) & kMask] - x0, n)) return false;
    int dense_outside = static_cast<int>(outside(dense[0], 0));
    if (last_dense == kDenseSamples) {
        for (int i = 1; i <= kDenseSamples; ++i) dense_outside |= static_cast<int>(outside(dense[i], i));
    } else {
        for (int i = 1; i <= last_dense; ++i) dense_outside |= static_cast<int>(outside(dense[i], i));
    }
    if (dense_outside != 0) return false;
    const unsigned first_eighth = 7;
#endif
    // The other eighths, i = n·j/8 for j = first_eighth down while it is past the dense samples.
    for (unsigned nj = step * first_eighth; nj / 8 > kDenseSamples; nj -= step) {
        const int i = static_cast<int>(nj / 8);
        if (outside(x[(head + i) & kMask] - x0, i)) return false;
    }
    if (y == nullptr) return true;
    int any = 0;
    for (int i = kDenseSamples + 1; i < n; ++i) any |= static_cast<int>(outside(y[i], i));
    return !any;
}


}  // namespace

// The fixed-point value is exact for every float position within ±max_fixed_position_
// whose finest bit is not below 1/fixed_scale_; elsewhere in range a deterministic rounding
// of it, half away from zero (the same on every platform), at most half a unit off (1/8192
// of a count on the joystick). Out of range (or not finite) it is 0, and the sums that
// read it are not used (fixed_run_). The conversion stays within int32 whatever x is.
inline bool MotionEstimator::representable(float x) const noexcept { return std::fabs(x) < max_fixed_position_; }

inline int32_t MotionEstimator::fixed_value(float x) const noexcept {
    const float scaled = representable(x) ? x * fixed_scale_ : 0.0f;
    return static_cast<int32_t>(scaled + std::copysign(0.5f, scaled));  // ±0 gives 0 either way
}

inline int64_t MotionEstimator::fixed_at(int axis, int i) const noexcept {
    return fixed_value(x_[axis][(head_ + i) & kMask]);
}

// fixed_at for a sample known to be representable (within fixed_run_): the same value
// without the range check, on the sums' every-tick reads.
inline int64_t MotionEstimator::held_fixed_at(int axis, int i) const noexcept {
    const float scaled = x_[axis][(head_ + i) & kMask] * fixed_scale_;
    return static_cast<int32_t>(scaled + std::copysign(0.5f, scaled));
}

void MotionEstimator::configure(float sensor_step) noexcept {
    band_ = std::isfinite(sensor_step) && sensor_step > 0 ? sensor_step : 1.0f;
    // The fixed-point unit: the largest power of two at most band_/kFixedPerCount (2^-10 on
    // the joystick, whose positions are multiples of 2^-7), at least 1/kMaxFixedScale.
    fixed_scale_ = 1.0f;
    while (fixed_scale_ < kMaxFixedScale && 1.0f / fixed_scale_ > band_ / kFixedPerCount) fixed_scale_ *= 2.0f;
    max_fixed_position_ = 1073741824.0f / fixed_scale_;
    fixed_unit_ = 1.0f / fixed_scale_;
    reset();
}

void MotionEstimator::reset() noexcept {
    count_ = 0;
    head_ = 0;
    for (int& run : still_run_) run = 0;
    steady_interval_us_ = 0;
    steady_run_ = 0;
    pattern_.steady_interval_us = 0;
    pattern_.max_n = 0;
    frozen_interval_us_ = 0;
    frozen_run_ = 0;
    sums_axes_ = 0;
    acceleration_ready_ = kEveryAxis;
    for (int a = 0; a < kMaxAxes; ++a) {
        fixed_run_[a] = 0;
        newest_fixed_[a] = frozen_fixed_[a] = false;
#if !FEEL_ESTIMATOR_SPEED_TABLES
        sums_[a] = RungSums{};  // the prefix sums are written afresh by rebuild_sums (sums_axes_ 0)
        sums_still_[a] = false;
#endif
        velocity_[a] = acceleration_[a] = 0.0f;
        velocity_window_[a] = acceleration_window_[a] = 0;
        velocity_rung_[a] = acceleration_rung_[a] = kRungs;
    }
}

// Keeps count of how many of the newest intervals are equal: while they all are, the
// time pattern is i·T and need not be recomputed.
void MotionEstimator::push_interval(int64_t interval_us) noexcept {
    if (interval_us == steady_interval_us_) {
        if (steady_run_ < kHistory) ++steady_run_;
    } else {
        steady_interval_us_ = interval_us;
        steady_run_ = 1;
    }
}

void MotionEstimator::update(int64_t t_us, const float position[kMaxAxes], int axis_count,
                             bool with_acceleration) noexcept {
    // Time went backwards, or stood still for over half an hour (the ring's 32-bit times,
    // above; a sample that old says nothing of the motion now): start over.
    if (count_ > 0 && (t_us < newest_t_us_ ||
                       static_cast<uint64_t>(t_us) - static_cast<uint64_t>(newest_t_us_) >= kMaxGapUs)) {
        reset();
    }
    // A new slot for this sample, unless it is the same instant as the newest one or would
    // crowd it: samples before the newest stay kMinSpacingUs apart, so that the history
    // spans kMaxWindowUs at any loop rate (at 10 kHz it keeps every 8th tick, plus the
    // newest). Otherwise the newest sample is replaced by this fresher reading.
    const int previous = (head_ + 1) & kMask;
    const bool crowded = count_ >= 2 && elapsed_us(low_bits(t_us), t_low_[previous]) < kMinSpacingUs;
    const bool pushed = count_ == 0 || (t_us > newest_t_us_ && !crowded);
    if (pushed) {
        if (count_ > 0) push_interval(t_us - newest_t_us_);
        // The newest sample becomes frozen: the interval between it and the one before
        // joins the frozen ones.
        if (count_ >= 2) {
            const int64_t frozen = elapsed_us(t_low_[head_], t_low_[previous]);
            if (frozen == frozen_interval_us_) {
                if (frozen_run_ < kHistory) ++frozen_run_;
            } else {
                frozen_interval_us_ = frozen;
                frozen_run_ = 1;
            }
        }
        head_ = (head_ - 1) & kMask;
        if (count_ < kHistory) ++count_;
    } else if (count_ >= 2) {
        // The newest interval changes: if it no longer matches, only it is known steady.
        const int64_t interval = elapsed_us(low_bits(t_us), t_low_[previous]);
        if (interval != steady_interval_us_) {
            steady_interval_us_ = interval;
            steady_run_ = 1;
        }
    }
    t_low_[head_] = low_bits(t_us);
    newest_t_us_ = t_us;
    const int axes = axis_count < kMaxAxes ? (axis_count > 0 ? axis_count : 0) : kMaxAxes;
    // Axes never written hold 0 throughout the ring, which is what they would read: they are
    // skipped (kMaxAxes is 6; a device has 2 or 3) until an update names them.
    const int written = axes > written_axes_ ? axes : written_axes_;
    written_axes_ = written;
    for (int a = 0; a < written; ++a) {
        const float x = a < axis_count ? position[a] : 0.0f;
        // A new sample extends the run if it repeats the newest; a replacing one keeps it
        // only if it repeats the value it replaces.
        const float compared = pushed ? x_[a][(head_ + 1) & kMask] : x_[a][head_];
        if (count_ >= 2 && x == compared) {
            if (pushed && still_run_[a] < kHistory) ++still_run_[a];
        } else {
            still_run_[a] = 1;
        }
        x_[a][head_] = x;
        if (pushed) {
            frozen_fixed_[a] = newest_fixed_[a];
            frozen_fixed_value_[a] = newest_fixed_value_[a];
        }
        newest_fixed_[a] = representable(x);
        newest_fixed_value_[a] = fixed_value(x);
    }

#if FEEL_ESTIMATOR_SPEED_TABLES
    if (pushed && count_ >= 2) ++frozen_count_;
#endif
    for (int a = 0; a < axes; ++a) {
        if (a >= sums_axes_) {
            rebuild_sums(a);
        } else if (pushed && count_ >= 2) {
            slide_sums(a);
        }
    }
    sums_axes_ = axes;

    refresh_time_pattern();
    newest_interval_u_ = count_ >= 2 ? float_of_int64(elapsed_us(t_low_[head_], t_low_[(head_ + 1) & kMask])) * kUnitsPerUs : 0.0f;
    frozen_interval_u_ = float_of_int64(frozen_interval_us_) * kUnitsPerUs;
    // The axes not updated, and all of them without the acceleration: fitted when asked for.
    acceleration_ready_ = with_acceleration ? static_cast<uint8_t>((1u << axes) - 1) : uint8_t{0};
    for (int a = 0; a < axes; ++a) estimate(a, true, with_acceleration);
}

// After a push: the newest frozen sample joins the prefix sums (x86); on the board it
// enters every ladder window at m = 0,
// the others move one m older, and the one that reaches m = n (index n + 1) leaves:
//   Σ X   += X_in - X_out
//   Σ m·X += Σ X - n·X_out           (each staying sample's m grows by one)
//   Σ m²X += 2·Σ m·X + Σ X - n²·X_out
// with the sums on the right taken before the update. Exact in 64-bit integers: a sum is
// at most 96³·2^30 in magnitude.
void MotionEstimator::slide_sums(int axis) noexcept {
    const bool representable = frozen_fixed_[axis];
    fixed_run_[axis] = representable ? (fixed_run_[axis] < kHistory ? fixed_run_[axis] + 1 : kHistory) : 0;
#if FEEL_ESTIMATOR_SPEED_TABLES
    // The prefix sums: the newest frozen sample (index 1, j = frozen_count_) adds its terms to
    // the sums up to the one before it (index 2, or the zeros past the oldest). Nothing
    // leaves, and at rest there is nothing to skip: three additions whatever the motion.
    const uint64_t value = static_cast<uint64_t>(int64_t{frozen_fixed_value_[axis]});
    add_prefix(prefix_[axis][(head_ + 2) & kMask], frozen_count_, value, prefix_[axis][(head_ + 1) & kMask]);
#else
    // At rest (the newest frozen sample and the longest ladder window all one value) the
    // sums are implied; leaving rest, they are first written out for the state before
    // this push (every window full of the value now at index 2).
    if (still_run_[axis] > kLadder[kLadderSize - 1] + 1) {
        sums_still_[axis] = true;
        return;
    }
    if (sums_still_[axis]) {
        sums_still_[axis] = false;
        const int64_t still = fixed_at(axis, 2);
        for (int k = kFirstSummed; k < kLadderSize; ++k) constant_sums(kLadder[k], still, sums_[axis].at(k));
    }
    const int64_t in = frozen_fixed_value_[axis];
    auto slide = [&](int k, int64_t out) {
        const int64_t n = kLadder[k];
        int64_t* s = sums_[axis].at(k);
        const int64_t s0 = s[0], s1 = s[1];
        s[0] = s0 + in - out;
        s[1] = s1 + s0 - n * out;
        s[2] = s[2] + 2 * s1 + s0 - n * n * out;
    };
    // Where every leaving sample is known to have a value (the common case), it is read
    // without the range check.
    const bool held = fixed_run_[axis] > kLadder[kLadderSize - 1];
    for (int k = kFirstSummed; k < kLadderSize; ++k) {
        // Before the ring holds n + 1 frozen samples nothing leaves.
        const int leaving = kLadder[k] + 1;
        slide(k, leaving > count_ - 1 ? 0 : held ? held_fixed_at(axis, leaving) : fixed_at(axis, leaving));
    }
#endif
}

// The running sums of an axis from the ring, for an axis that was not kept up to date.
void MotionEstimator::rebuild_sums(int axis) noexcept {
    const float* x = x_[axis];
    fixed_run_[axis] = 0;
    while (fixed_run_[axis] + 1 < count_ && representable(x[(head_ + fixed_run_[axis] + 1) & kMask])) {
        ++fixed_run_[axis];
    }
#if FEEL_ESTIMATOR_SPEED_TABLES
    // From the zeros past the oldest frozen sample to the newest (index 1, j = frozen_count_).
    uint64_t* past_oldest = prefix_[axis][(head_ + count_) & kMask];
    past_oldest[0] = past_oldest[1] = past_oldest[2] = 0;
    for (int i = count_ - 1; i >= 1; --i) {
        add_prefix(prefix_[axis][(head_ + i + 1) & kMask], frozen_count_ - static_cast<uint64_t>(i - 1),
                   static_cast<uint64_t>(fixed_at(axis, i)), prefix_[axis][(head_ + i) & kMask]);
    }
#else
    sums_still_[axis] = false;
    for (int k = kFirstSummed; k < kLadderSize; ++k) {
        int64_t* s = sums_[axis].at(k);
        s[0] = s[1] = s[2] = 0;
        for (int i = 1; i <= kLadder[k] && i < count_; ++i) {
            const int64_t value = fixed_at(axis, i);
            const int64_t m = i - 1;
            s[0] += value;
            s[1] += m * value;
            s[2] += m * m * value;
        }
    }
#endif
}

bool MotionEstimator::fast_fit_possible(int axis) const noexcept {
    const int max_n = pattern_.max_n;
    return max_n >= 1 && axis < sums_axes_ && fixed_run_[axis] >= max_n && newest_fixed_[axis] &&
           (max_n <= 1 || (frozen_run_ >= max_n - 1 && frozen_interval_us_ > 0));
}

// Σ y, Σ u·y (and, for a parabola, Σ u²·y) over samples 0..n, y relative to the newest
// sample. The frozen samples 1..n are at ages a1 + m·T (m = i - 1, a1 the newest interval,
// T the frozen one), so with α = a1/W, β = T/W (W = kMaxWindowUs) u = -(α + m·β) and
//   Σ u·y  = -(α·Σy + β·Σm·y),   Σ u²·y = α²·Σy + 2αβ·Σm·y + β²·Σm²·y,
// where Σ m^p·y = Σ m^p·X - X_0·Σ m^p (the newest sample's y is 0). The sums of a rung
// between two ladder lengths (the whole history) add the few samples past the longest
// ladder window below it. A line reads no Σ u²·y: its fits skip that sum's share (issue 14).
// Inlined into each order's fit where the build optimises for speed (fit_order).
#if defined(__OPTIMIZE_SIZE__)
void MotionEstimator::window_sums(int axis, int r, bool parabola, float out[3]) const noexcept {
    parabola = true;  // the board: one path for both orders (flash); a line ignores out[2]
#else
[[gnu::always_inline]] inline void MotionEstimator::window_sums(int axis, int r, bool parabola,
                                                               float out[3]) const noexcept {
#endif
    const int n = pattern_.rung_n[r];
    int64_t s[3] = {0, 0, 0};
#if FEEL_ESTIMATOR_SPEED_TABLES
    // Frozen samples 1..n: the prefix sums at index 1 less those at n + 1, their j (m = c - j
    // for the newest frozen sample's c) turned into m: Σ m·X = c·Σ X - Σ j·X,
    // Σ m²·X = c²·Σ X - 2c·Σ j·X + Σ j²·X, modulo 2^64 and so exact.
    const uint64_t* through_newest = prefix_[axis][(head_ + 1) & kMask];
    const uint64_t* before_window = prefix_[axis][(head_ + n + 1) & kMask];
    const uint64_t c = frozen_count_;
    const uint64_t sx = through_newest[0] - before_window[0];
    const uint64_t sjx = through_newest[1] - before_window[1];
    s[0] = static_cast<int64_t>(sx);
    s[1] = static_cast<int64_t>(c * sx - sjx);
    if (parabola) s[2] = static_cast<int64_t>(c * (c * sx - 2 * sjx) + (through_newest[2] - before_window[2]));
#else
    const int k = pattern_.rung_ladder[r];
    int from = 1;
    if (k >= 0) {
        // At rest every ladder window holds the newest frozen sample's value (sums_still_).
        if (sums_still_[axis]) {
            constant_sums(kLadder[k], frozen_fixed_value_[axis], s);
        } else {
            const int64_t* kept = sums_[axis].at(k);
            s[0] = kept[0];
            s[1] = kept[1];
            s[2] = kept[2];
        }
        from = kLadder[k] + 1;
    }
    for (int i = from; i <= n; ++i) {  // the running-sum path: every sample within fixed_run_
        const int64_t value = held_fixed_at(axis, i);
        const int64_t m = i - 1;
        s[0] += value;
        s[1] += m * value;
        if (parabola) s[2] += m * m * value;
    }
#endif
    // The newest sample's share, X_0·Σ m^p over m = 0..n-1 (Σ m^p the time pattern's on x86).
    int64_t newest[3];
#if FEEL_ESTIMATOR_SPEED_TABLES
    const int64_t x0 = newest_fixed_value_[axis];
    newest[0] = n * x0;
    newest[1] = int64_t{pattern_.m_sums[0][r]} * x0;
    newest[2] = int64_t{pattern_.m_sums[1][r]} * x0;
#else
    constant_sums(n, newest_fixed_value_[axis], newest);
#endif
    const float unit = fixed_unit_;
    const float sy = float_of_int64(s[0] - newest[0]) * unit;
    const float smy = float_of_int64(s[1] - newest[1]) * unit;
    const float alpha = newest_interval_u_;
    const float beta = frozen_interval_u_;
    out[0] = sy;
    out[1] = -(alpha * sy + beta * smy);
    if (parabola) {
        const float smmy = float_of_int64(s[2] - newest[2]) * unit;
        out[2] = alpha * alpha * sy + 2.0f * alpha * beta * smy + beta * beta * smmy;
    }
}

void MotionEstimator::refresh_time_pattern() noexcept {
    TimePattern& p = pattern_;
    // Steady: every interval in the window is T, so max_n follows from T alone, and the
    // pattern is the one already computed if it was computed for the same T and max_n.
    if (count_ >= 2 && steady_interval_us_ > 0) {
        // The quotient in 32 bits (a Cortex-M4 has no 64-bit division): an interval longer
        // than the window fits no whole interval in it.
        static_assert(kMaxWindowUs <= INT32_MAX);
        const int32_t fit = steady_interval_us_ > kMaxWindowUs
                                ? 0
                                : static_cast<int32_t>(kMaxWindowUs) / static_cast<int32_t>(steady_interval_us_);
        int max_n = count_ - 1;
        if (fit < max_n) max_n = fit < 1 ? 1 : static_cast<int>(fit);
        if (steady_run_ >= max_n && p.steady_interval_us == steady_interval_us_ && p.max_n == max_n) return;
    }
    int max_n = 0;
    for (int i = 0; i < count_; ++i) {
        const int64_t age_us = elapsed_us(t_low_[head_], t_low_[(head_ + i) & kMask]);
        if (i > 1 && age_us > kMaxWindowUs) break;  // the newest two samples are always usable
        p.u[i] = -float_of_int64(age_us) * kUnitsPerUs;
        max_n = i;
    }
    p.max_n = max_n;
    p.steady_interval_us = max_n >= 1 && steady_run_ >= max_n ? steady_interval_us_ : 0;
    p.rung_count = 0;
    for (int n : kLadder) {
        if (n < max_n) p.rung_n[p.rung_count++] = static_cast<uint8_t>(n);
    }
    p.rung_n[p.rung_count++] = static_cast<uint8_t>(max_n);
    for (int r = 0, k = -1; r < p.rung_count; ++r) {
        while (k + 1 < kLadderSize && kLadder[k + 1] <= p.rung_n[r]) ++k;
        p.rung_ladder[r] = static_cast<int8_t>(k >= kFirstSummed ? k : -1);
    }
    float sum[4] = {};  // Σ u, Σ u², Σ u³, Σ u⁴
    int i = 0;
    for (int r = 0; r < p.rung_count; ++r) {
        for (; i <= p.rung_n[r]; ++i) {
            const float u = p.u[i], u2 = u * u;
            sum[0] += u;
            sum[1] += u2;
            sum[2] += u2 * u;
            sum[3] += u2 * u2;
        }
        for (int k = 0; k < 4; ++k) p.moment[k][r] = sum[k];
#if FEEL_ESTIMATOR_SPEED_TABLES
        const float m0 = static_cast<float>(p.rung_n[r] + 1), m1 = sum[0], m2 = sum[1], m3 = sum[2], m4 = sum[3];
        p.line_det[r] = line_det(m0, m1, m2);
        p.parabola_det[r] = det3(m0, m1, m2, m1, m2, m3, m2, m3, m4);
        p.normal_minor[0][r] = m1 * m3 - m2 * m2;
        p.normal_minor[1][r] = m2 * m4 - m3 * m3;
        p.normal_minor[2][r] = m1 * m4 - m3 * m2;
        p.m_sums[0][r] = sum_of_m(p.rung_n[r]);
        p.m_sums[1][r] = sum_of_m_squared(p.rung_n[r]);
#endif
    }
}

// The newest kDenseSlots samples of an axis relative to the newest (within_band), in buffer:
// without the ring's wrap when it is not in the way (vector code). Null on the board, whose
// band check reads them from the ring (flash).
const float* MotionEstimator::dense_samples(int axis, float* buffer) const noexcept {
#if defined(__OPTIMIZE_SIZE__)
    static_cast<void>(axis);
    static_cast<void>(buffer);
    return nullptr;
#else
    const float* x = x_[axis];
    const float x0 = x[head_];
    if (head_ <= kHistory - kDenseSlots) {
        for (int i = 0; i < kDenseSlots; ++i) buffer[i] = x[head_ + i] - x0;
    } else {
        for (int i = 0; i < kDenseSlots; ++i) buffer[i] = x[(head_ + i) & kMask] - x0;
    }
    return buffer;
#endif
}

// The fits of both paths: for each rung from `top` down (longest first) the least-squares
// line or parabola by Cramer's rule on the normal equations M·c = s, M[i][j] = Σ u^(i+j),
// then its band check; the first that passes is the estimate. Longest first rather than
// growing until the first failure: on a ramp whose speed is close to a whole number of
// counts per tick the rounding error is a slow sawtooth, which a middle-sized window can
// fail while both a short and a long one pass; the long one is the better estimate, and
// for steady motion this order needs one fit. The parabola is never fitted over fewer
// than kMinAccelerationWindow intervals, and over that many it is taken without the band
// check: where no longer window fits, its estimate is the motion's mean curvature over
// those few ms (kMinAccelerationWindow is a rung: kLadder holds it, or it is max_n).
// The running sums (gathered null) search down from kRungsUp above the rung accepted last
// time; the general path from the whole history. The estimate, its window and the rung go
// to the axis's velocity (order 1) or acceleration (order 2).
// On the board (-Os) one copy serves both orders. Elsewhere each order gets its own copy,
// the order a constant in it: the tick's x86 estimator takes about 120 instructions fewer.
#if defined(__OPTIMIZE_SIZE__)
inline void MotionEstimator::fit_order(int axis, int order, const float* dense, const float* y,
                                        const float (*gathered)[kRungs]) noexcept {
#else
[[gnu::always_inline]] inline void MotionEstimator::fit_order(int axis, int order, const float* dense, const float* y,
                                                             const float (*gathered)[kRungs]) noexcept {
#endif
    const TimePattern& p = pattern_;
    const bool line = order == 1;
    const int min_n = line ? 1 : kMinAccelerationWindow;
    const bool fast = gathered == nullptr;
    int& rung = line ? velocity_rung_[axis] : acceleration_rung_[axis];
    int& window = line ? velocity_window_[axis] : acceleration_window_[axis];
    float& result = line ? velocity_[axis] : acceleration_[axis];
    const int top = p.rung_count - 1;
    for (int r = fast ? start_rung(rung, top) : top; r >= 0; --r) {
        const int n = p.rung_n[r];
        if (n < min_n) break;
        float s[3];
        if (gathered != nullptr) {
            for (int q = 0; q < 3; ++q) s[q] = gathered[q][r];
        } else {
            window_sums(axis, r, !line, s);
        }
        const float m0 = static_cast<float>(n + 1), m1 = p.moment[0][r], m2 = p.moment[1][r];
        float c0 = 0, c1 = 0, c2 = 0, estimate = 0;
        if (line) {
#if FEEL_ESTIMATOR_SPEED_TABLES
            const float det = p.line_det[r];
#else
            const float det = line_det(m0, m1, m2);
#endif
            if (!(det > 0)) continue;
            c1 = (m0 * s[1] - m1 * s[0]) / det;
            c0 = (s[0] - c1 * m1) / m0;
            estimate = c1 / kWindowS;
        } else {
            // Cramer's rule, each determinant expanded along the sums' column; the
            // determinant and the minors of the normal matrix alone (normal_minor) are the
            // time pattern's where it keeps them.
            const float m3 = p.moment[2][r], m4 = p.moment[3][r];
#if FEEL_ESTIMATOR_SPEED_TABLES
            const float det = p.parabola_det[r];
            const float minor_01_12 = p.normal_minor[0][r], minor_11_22 = p.normal_minor[1][r],
                        minor_01_22 = p.normal_minor[2][r];
#else
            const float det = det3(m0, m1, m2, m1, m2, m3, m2, m3, m4);
            const float minor_01_12 = m1 * m3 - m2 * m2, minor_11_22 = m2 * m4 - m3 * m3,
                        minor_01_22 = m1 * m4 - m3 * m2;
#endif
            if (!(det > 0)) continue;
            // det3(m0, m1, s0, m1, m2, s1, m2, m3, s2), det3(s0, m1, m2, s1, m2, m3, s2, m3, m4)
            // and det3(m0, s0, m2, m1, s1, m3, m2, s2, m4), the same operations.
            const float s2_m3 = m1 * s[2] - s[1] * m2, s1_m4 = s[1] * m4 - m3 * s[2];
            c2 = expand_row(m0, m1, s[0], m2 * s[2] - s[1] * m3, s2_m3, minor_01_12) / det;
            estimate = 2.0f * c2 / (kWindowS * kWindowS);
            // Over kMinAccelerationWindow the parabola is taken without the band check, which
            // alone reads c0 and c1 (x86: the board solves for them anyway, for its flash).
            if (kSolveUnread || n > kMinAccelerationWindow) {
                c0 = expand_row(s[0], m1, m2, minor_11_22, s1_m4, s[1] * m3 - m2 * s[2]) / det;
                c1 = expand_row(m0, s[0], m2, s1_m4, minor_01_22, s2_m3) / det;
            }
        }
        const float* x = x_[axis];
        const bool passes =
            line ? within_band<false>(dense, x, head_, x[head_], p.u, y, n, c0, c1, c2, band_)
                 : n == kMinAccelerationWindow || within_band<true>(dense, x, head_, x[head_], p.u, y, n, c0, c1, c2, band_);
        if (!passes) continue;
        if (fast) rung = r;
        window = n;
        result = std::isfinite(estimate) ? estimate : 0.0f;
        return;
    }
    // None passes: a degenerate window, or a position that is not finite (a line through
    // two samples passes otherwise).
    if (fast && line) rung = 0;
    window = 0;
    result = 0.0f;
}

void MotionEstimator::fit(int axis, int order, const float* dense, const float* y,
                          const float (*gathered)[kRungs]) noexcept {
#if defined(__OPTIMIZE_SIZE__)
    fit_order(axis, order, dense, y, gathered);
#else
    if (order == 1) {
        fit_order(axis, 1, dense, y, gathered);
    } else {
        fit_order(axis, 2, dense, y, gathered);
    }
#endif
}

void MotionEstimator::estimate(int axis, bool velocity, bool acceleration) noexcept {
    const TimePattern& p = pattern_;
    const int max_n = p.max_n;
    acceleration_[axis] = 0.0f;
    acceleration_window_[axis] = 0;
    // The acceleration needs a window of kMinAccelerationWindow at least: a parabola
    // through a few quantized samples reads the rounding as curvature (3 samples 1 ms
    // apart: ±q/T² = 2.4 times the joystick's acceleration_ref). Until the history holds
    // that many samples, it reads 0.
    const bool fits_acceleration = acceleration && max_n >= kMinAccelerationWindow;
    if (max_n < 1 || (!velocity && !fits_acceleration)) {
        if (velocity) {
            velocity_[axis] = 0.0f;
            velocity_window_[axis] = 0;
        }
        return;
    }
    // At rest (every sample the same reading) both fits are exactly 0 over the whole
    // history: skip them, it is the commonest case. (Where still_run_ reads short after a
    // replaced sample, the fits reach the same answer.)
    if (still_run_[axis] > max_n) {
        if (velocity) {
            velocity_rung_[axis] = acceleration_rung_[axis] = kRungs;
            velocity_window_[axis] = max_n;
            velocity_[axis] = 0.0f;
        }
        if (max_n >= kMinAccelerationWindow) acceleration_window_[axis] = max_n;
        return;
    }
    if (fast_fit_possible(axis)) {
        estimate_fast(axis, velocity, fits_acceleration);
    } else {
        estimate_general(axis, velocity, fits_acceleration);
    }
}

void MotionEstimator::fit_acceleration_now(int axis) noexcept {
    estimate(axis, false, true);
    acceleration_ready_ = static_cast<uint8_t>(acceleration_ready_ | 1u << axis);
}

void MotionEstimator::estimate_fast(int axis, bool velocity, bool acceleration) noexcept {
    float buffer[kDenseSlots];
    const float* dense = dense_samples(axis, buffer);
    if (velocity) fit(axis, 1, dense, nullptr, nullptr);
    if (acceleration) fit(axis, 2, dense, nullptr, nullptr);
}

}  // namespace feel::detail
