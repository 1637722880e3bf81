// Velocity and acceleration from a quantized position sensor.
//
// Real devices see only encoder counts. A raw difference of two quantized positions is
// either zero or a whole count per tick: at slow speeds it reads zero most ticks and then
// a spike, which makes a damper buzz and collapse. The estimator exists so that Spatial
// Conditions get a velocity and an acceleration they can use.
//
// Method: first-order adaptive windowing (FOAW, Janabi-Sharifi, Hayward & Chen 2000), in
// its best-fit form, and the same idea one order up for the acceleration. Each tick, for
// growing windows of recent samples, fit a line (a parabola for the acceleration) by least
// squares and keep the longest window whose samples all lie within one sensor count of the
// fit. Slow motion gets a long window (a count every few ticks averages out), fast or
// changing motion a short one (little lag). motion_estimator.cpp has the details and
// docs/conditions.md the reasoning and the measured accuracy.
//
// Cost (issue 14): the window sums come from running sums, exact in integers (prefix sums
// on x86, each ladder rung's on the board: FEEL_ESTIMATOR_SPEED_TABLES), so a fit is O(1);
// the band check looks at a fixed set of samples (the newest few, then the window's
// eighths) instead of all of them. motion_estimator.cpp explains.
//
// Real-time safe: fixed-size history, no allocation, no clock; the output is a pure
// function of the samples fed in. Single precision throughout (a Cortex-M4F has no double
// FPU), time in integer microseconds. History for kMaxAxes axes: 2 in the firmware build
// (feel/axis.hpp, FEEL_MAX_AXES).
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "feel/axis.hpp"

// Where the build optimises for speed the estimator keeps larger tables: the running sums
// are prefix sums over every frozen sample (O(1) a tick, 3 KB an axis) and the time
// pattern keeps each rung's determinants; a build for size (the Cortex-M4F image, whose RAM
// has no 3 KB to spare) keeps the sums of each ladder window and slides them, and works the
// determinants out in each fit. The sums are exact integers and the determinants the same
// operations, so both give the same bits. It sets the class's layout: every translation
// unit of a program must agree (the board's image is -Os throughout).
#if !defined(FEEL_ESTIMATOR_SPEED_TABLES)
#if defined(__OPTIMIZE_SIZE__)
#define FEEL_ESTIMATOR_SPEED_TABLES 0
#else
#define FEEL_ESTIMATOR_SPEED_TABLES 1
#endif
#endif

namespace feel::detail {

class MotionEstimator {
public:
    // Samples kept per axis; the longest window is kHistory - 1 intervals.
    static constexpr int kHistory = 128;
    // No window spans more than this, µs, whatever the loop rate: bounds the lag at low
    // rates (100 Hz would otherwise average over 1.27 s).
    static constexpr int64_t kMaxWindowUs = 100'000;
    // Samples older than the newest are kept at least this far apart, µs, so that the
    // history spans kMaxWindowUs whatever the loop rate (faster loops keep every few ticks;
    // the newest sample is always the latest tick).
    static constexpr int64_t kMinSpacingUs = kMaxWindowUs / (kHistory - 1);
    // A tick this long after the previous one restarts the history (as time going backwards
    // does): 2^31 µs, 36 minutes. It keeps every interval the ring's 32-bit times hold exact.
    static constexpr uint64_t kMaxGapUs = uint64_t{1} << 31;
    // The acceleration is fitted over at least this many sample intervals (8 ms at 1 kHz).
    static constexpr int kMinAccelerationWindow = 8;
    // Window lengths tried (in sample intervals) below the whole history, shortest first;
    // kRungs counts them and the whole history.
    static constexpr int kLadder[] = {1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96};
    static constexpr int kLadderSize = static_cast<int>(sizeof kLadder / sizeof kLadder[0]);
    static constexpr int kRungs = kLadderSize + 1;
    static_assert(kHistory - 1 <= UINT8_MAX && kLadderSize <= INT8_MAX, "TimePattern keeps rungs in bytes");
    // Positions enter the running sums as integers of 1/fixed_scale_ position unit: the
    // power of two that makes a unit at most 1/kFixedPerCount of a sensor count (exact for
    // the device profiles' quantized positions; far inside the fit's band in any case),
    // but no finer than 1/kMaxFixedScale so that ±16384 units fit in 31 bits. A position
    // beyond 2^30 units of it (or not finite) is fitted the slow way.
    static constexpr float kFixedPerCount = 4096.0f;
    static constexpr float kMaxFixedScale = 65536.0f;
    // A window grows by at most this many rungs a tick (the fits search downwards from
    // there): one tick's new sample rarely lets a window grow more.
    static constexpr int kRungsUp = 1;
    // The board's running sums are kept for the ladder's windows of this many intervals or
    // more; shorter ones are summed from the ring when a fit needs them (x86's prefix sums
    // serve every window).
    static constexpr int kMinSummedWindow = 8;
    // The band check's newest samples, looked at one by one, and the slots that hold them
    // with the newest (motion_estimator.cpp, within_band and dense_samples).
    static constexpr int kDenseSamples = 8;
    static constexpr int kDenseSlots = kDenseSamples + 1;
    // The first kLadder index whose window's sums are kept.
    static constexpr int kFirstSummed = [] {
        int k = 0;
        while (kLadder[k] < kMinSummedWindow) ++k;
        return k;
    }();

    // Every member 0 but the tolerance and fixed-point scale (a sensor count of 1 until
    // configure) and the ready flags. One zero fill: default member initialisers had the
    // constructor write each array and scalar out by itself, 200 bytes of the board's
    // Engine::Engine (issue 14's flash). The members are numbers only: zero bytes are 0.
    MotionEstimator() noexcept {
        std::memset(static_cast<void*>(this), 0, sizeof *this);
        band_ = 1.0f;
        fixed_scale_ = 64.0f;
        fixed_unit_ = 1.0f / 64.0f;
        max_fixed_position_ = 16777216.0f;
        acceleration_ready_ = kEveryAxis;
    }

    // sensor_step: the position change of one sensor count, normalized units (> 0). The
    // fit tolerance is one count: a sample one count off a line is quantization, two
    // counts off is motion.
    void configure(float sensor_step) noexcept;
    // Forgets the history; velocity and acceleration read 0 until new samples arrive.
    void reset() noexcept;

    // Feeds the sensed positions of one tick at t_us. Times must not decrease; a sample at
    // the same time as the newest one, or closer than kMinSpacingUs to the one before it,
    // replaces the newest; an earlier time, or one kMaxGapUs or more later, restarts the
    // history.
    // with_acceleration false leaves the acceleration to be fitted if acceleration() is
    // called (it then gathers the history again); the tick passes false when no inertia
    // plays.
    void update(int64_t t_us, const float position[kMaxAxes], int axis_count, bool with_acceleration = true) noexcept;

    [[nodiscard]] float velocity(int axis) const noexcept { return velocity_[axis]; }  // units/s
    // units/s². Fitted by update() or, if it was told not to, on the first call after it.
    [[nodiscard]] float acceleration(int axis) noexcept {
        if ((acceleration_ready_ >> axis & 1u) == 0) fit_acceleration_now(axis);
        return acceleration_[axis];
    }
    // The windows used at the last update, in sample intervals (0: no estimate yet).
    [[nodiscard]] int velocity_window(int axis) const noexcept { return velocity_window_[axis]; }
    [[nodiscard]] int acceleration_window(int axis) noexcept {
        if ((acceleration_ready_ >> axis & 1u) == 0) fit_acceleration_now(axis);
        return acceleration_window_[axis];
    }

private:
    // The sample times as the fits see them, shared by every axis: recomputed only when
    // they change, which at a steady loop rate is never (every sample's age is then i·T).
    struct TimePattern {
        int max_n;       // samples 0..max_n are within kMaxWindowUs of the newest
        int rung_count;  // windows tried: rung_n[0..rung_count-1], the last max_n
        // Bytes (issue 14's RAM): a length is at most kHistory - 1 = 127, an index at most 12.
        uint8_t rung_n[kRungs];      // their lengths, ascending
        int8_t rung_ladder[kRungs];  // the longest kLadder index not longer (-1: none)
        // moment[p - 1][r] = Σ u_i^p over samples 0..rung_n[r], p = 1..4 (Σ u^0 is the
        // sample count, rung_n[r] + 1: not kept).
        float moment[4][kRungs];
        // u_i = -age_i / kMaxWindowUs, in [-1, 0]. The fits square it where they need u_i²
        // (one multiplication, the same rounding as a stored copy, half a KB less: issue 14).
        float u[kHistory];
        int64_t steady_interval_us;  // every interval was this (0: not a steady pattern)
#if FEEL_ESTIMATOR_SPEED_TABLES
        // Per rung, what the fits' Cramer's rule reads of the normal matrix alone (M, with
        // M[i][j] = moment of order i + j): a line's det, a parabola's det and the three
        // 2x2 minors without the sums (normal_minor: M01·M12 - M11·M11, M11·M22 - M12·M12,
        // M01·M22 - M12·M11), computed as the fit would (fit_order).
        float line_det[kRungs];
        float parabola_det[kRungs];
        float normal_minor[3][kRungs];
        // Σ m and Σ m² over m = 0..rung_n[r] - 1: the weights of the newest sample's share of
        // a window's sums (window_sums).
        int32_t m_sums[2][kRungs];
#endif
    };

    // Running sums of the frozen samples (all but the newest, which a later sample of the
    // same instant may replace) over the ladder's window lengths, in 1/fixed_scale_ units:
    // for the n frozen samples 1..n (m = i - 1 = 0..n-1), Σ X, Σ m·X, Σ m²·X.
    // Only the windows of kFirstSummed up are kept (issue 14's RAM: 120 bytes an axis).
    // The board's (FEEL_ESTIMATOR_SPEED_TABLES 0).
    struct RungSums {
        int64_t s[kLadderSize - kFirstSummed][3];
        int64_t* at(int k) noexcept { return s[k - kFirstSummed]; }
        const int64_t* at(int k) const noexcept { return s[k - kFirstSummed]; }
    };

    void push_interval(int64_t interval_us) noexcept;
    void slide_sums(int axis) noexcept;
    void rebuild_sums(int axis) noexcept;
    // Σ y, Σ u·y (and Σ u²·y if parabola) over rung r's samples 0..n of an axis from the
    // running sums, y relative to the newest sample.
    void window_sums(int axis, int r, bool parabola, float out[3]) const noexcept;
    bool fast_fit_possible(int axis) const noexcept;
    void refresh_time_pattern() noexcept;
    // One axis's samples newest first relative to the newest (y[0..max_n]) and the window
    // sums at every rung (sums[p][r] = Σ u^p·y, p = 0, 1, 2). Not at rest: estimate() has
    // answered that without the history.
    void gather_axis(int axis, float* y, float (*sums)[kRungs]) const noexcept;
    // The velocity (and the acceleration) of an axis at this tick; velocity false fits only
    // the acceleration (acceleration() after an update told not to).
    void estimate(int axis, bool velocity, bool acceleration) noexcept;
    // The general path: the history gathered (uneven older intervals, a position the
    // running sums cannot hold). Not inlined: its buffers stay off the common path's stack.
    [[gnu::noinline]] void estimate_general(int axis, bool velocity, bool acceleration) noexcept;
    // The acceleration of an axis update() was told not to fit, or did not name.
    void fit_acceleration_now(int axis) noexcept;
    // The common path: the running sums. Apart from estimate(), so that a handle at rest
    // (answered there) does not pay for its frame.
    void estimate_fast(int axis, bool velocity, bool acceleration) noexcept;
    // The longest rung whose line (order 1) or parabola (order 2) passes the band check:
    // its slope or second derivative, window and rung are the axis's velocity or
    // acceleration. gathered: the sums at every rung and the samples (gather_axis), the band
    // checked on every sample; nullptr: the running sums, the band checked on a fixed set of
    // samples.
    // dense: the newest samples relative to the newest (dense_samples), for the band check.
    void fit(int axis, int order, const float* dense, const float* y, const float (*gathered)[kRungs]) noexcept;
    void fit_order(int axis, int order, const float* dense, const float* y,
                   const float (*gathered)[kRungs]) noexcept;  // fit's body
    // The newest few samples of an axis relative to the newest one, in buffer (null on the
    // board: motion_estimator.cpp, kDenseSlots).
    const float* dense_samples(int axis, float* buffer) const noexcept;

    // Whether x has a fixed-point value (see kFixedPerCount), and the value: x as an
    // integer of 1/fixed_scale_ units, rounded half away from zero; 0 where x has none.
    bool representable(float x) const noexcept;
    int32_t fixed_value(float x) const noexcept;
    // Sample i's position of an axis as the running sums hold it. Worked out when read
    // (issue 14's RAM: the ring keeps one copy of a position, the float it was given).
    int64_t fixed_at(int axis, int i) const noexcept;
    int64_t held_fixed_at(int axis, int i) const noexcept;  // i within fixed_run_

    // Every member starts at 0 but the five the constructor sets.
    float band_;                // fit tolerance, normalized position units: one sensor count (1)
    float fixed_scale_;         // fixed-point units per position unit, a power of two (64)
    float fixed_unit_;          // 1 / fixed_scale_, exact
    float max_fixed_position_;  // position units: 2^30 fixed-point units
    int count_;  // valid samples in the ring, 0..kHistory
    int head_;   // index of the newest sample; older ones follow it (mod kHistory)
    // The newest steady_run_ intervals all equal steady_interval_us_ (µs).
    int64_t steady_interval_us_;
    int steady_run_;
    int64_t newest_t_us_;  // the newest sample's time
    // Every sample's time, its low 32 bits: the times between them follow exactly
    // (kMaxGapUs; motion_estimator.cpp, elapsed_us).
    uint32_t t_low_[kHistory];
    // Axes update() has written samples of (the ring of the others holds only 0); never
    // lowered, not even by reset(), which leaves the ring's contents.
    int written_axes_;
    // The positions as given. Their fixed-point values (fixed_at) are not kept: a copy would
    // cost 512 bytes an axis, and working one out is a multiplication and a rounding.
    float x_[kMaxAxes][kHistory];
    // How many of the newest samples of each axis read the newest value (never more than
    // they do; it may read fewer after a replaced sample): at rest it reaches max_n and
    // the fits are skipped without looking at the history.
    int still_run_[kMaxAxes];
    TimePattern pattern_;
    // Intervals between frozen samples: the newest frozen_run_ of them are all
    // frozen_interval_us_ (µs).
    int64_t frozen_interval_us_;
    int frozen_run_;
    // How many of the newest frozen samples of each axis have a fixed-point value.
    int fixed_run_[kMaxAxes];
    // Whether the newest sample (index 0) and the newest frozen one (index 1) have one: the
    // verdicts kept, not recomputed.
    bool newest_fixed_[kMaxAxes];
    bool frozen_fixed_[kMaxAxes];
    // Their fixed-point values (fixed_at(axis, 0) and (axis, 1)), the ones the sums read
    // every tick, kept rather than worked out again.
    int32_t newest_fixed_value_[kMaxAxes];
    int32_t frozen_fixed_value_[kMaxAxes];
    // What window_sums needs that is the same for every axis and rung of a tick, set by update:
    // the newest interval and the frozen one in units of kMaxWindowUs.
    float newest_interval_u_;
    float frozen_interval_u_;
    // Axes whose running sums are kept up to date (the first sums_axes_).
    int sums_axes_;
#if FEEL_ESTIMATOR_SPEED_TABLES
    // prefix_[axis][slot] = Σ X_j, Σ j·X_j, Σ j²·X_j over the axis's frozen samples up to and
    // including the one in that slot, j counting frozen samples (frozen_count_: the newest's),
    // modulo 2^64: a window's sums are the difference of two (window_sums), exact wherever
    // the true sum fits an int64. The slot past the oldest frozen sample holds the sums
    // before it (the newest sample's slot, once the ring is full: its own are written when
    // it is frozen).
    uint64_t prefix_[kMaxAxes][kHistory][3];
    uint64_t frozen_count_;
#else
    RungSums sums_[kMaxAxes];
    // At rest the sums are not slid: every ladder window then holds one value, the newest
    // frozen sample's, and its sums follow from it (window_sums). True while that holds.
    bool sums_still_[kMaxAxes];
#endif
    float velocity_[kMaxAxes];
    float acceleration_[kMaxAxes];
    int velocity_window_[kMaxAxes];
    // The rungs (indices into the pattern's rung_n) the fast fits accepted last time: the
    // next search starts at most kRungsUp above them.
    int velocity_rung_[kMaxAxes];
    int acceleration_rung_[kMaxAxes];
    int acceleration_window_[kMaxAxes];
    // Bit a: axis a's acceleration is fitted for the last update (one byte: update sets them
    // all in one store, fit_acceleration_now its axis's).
    static constexpr uint8_t kEveryAxis = static_cast<uint8_t>((1u << kMaxAxes) - 1);
    uint8_t acceleration_ready_;  // kEveryAxis
};

static_assert(std::is_trivially_copyable_v<MotionEstimator>, "its constructor fills it with zero bytes");

}  // namespace feel::detail
