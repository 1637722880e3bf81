// feel::host::emulation — SenseClock: when a standard PID device sensed each Input report,
// reconstructed from the report sequence alone.
//
// Why. A standard Input report carries positions and no time. Host emulation renders each
// report with feel's engine, whose velocity estimate (a wall's passivity damper, a texture's
// bristle, a Dynamic's tether) divides position changes by time changes. Stamping a report
// with its arrival is right only on a link whose delay never changes: reports that queue
// behind a late reader (hidraw under load, qemu's TCG: gaps of 100 ms, then a burst read in
// one go) arrive together although they were sensed a report period apart, and the velocity
// of a burst reads as a jump then zero. So every report gets a sense time instead, that
// does not depend on when it arrived, for every PID device.
//
// How: a minimum-delay clock fit on the device's report grid. A PID device sends its Input
// report every period T (its report rate; a USB interrupt endpoint polls at a fixed
// interval). Report i was sensed at s_i; it arrives at a_i = s_i + d_i, with d_i ≥ d_min,
// the link's least delay. Reports are numbered by grid slots: a report read after the
// previous one is one slot later, unless the device dropped some in between (a USB gadget
// that keeps only its newest state when the host does not poll), which shows as every
// later report arriving at least a period later than the least-delayed ones did. So:
//
//  * learning: the reports of the first kLearnUs (at least kLearnReports) give T as their
//    mean spacing, counted from the newest of one drain to the newest of another (the
//    freshest of each; a drop there lengthens T slightly, the fit below corrects it);
//    meanwhile the reports are stamped with their arrival;
//  * each drain (the reports the host read back to back, oldest first) takes the next slots,
//    ŝ = ŝ_prev + T each: a burst is spread back over the periods it was sensed in;
//  * the least delay: the smallest apparent delay a − ŝ seen, the floor. A report that
//    would arrive before the floor lowers it (the slots run ahead of the device);
//  * drops: when every report of the last kWindowUs (two half windows) arrived at least a
//    period later than the floor, the grid is behind by that many whole periods, and the
//    slots skip them. A late report alone is never taken for a drop: a single late
//    arrival, or a burst behind a late reader, keeps its slots (the window holds on-time
//    reports too);
//  * the period: each half window's least-delayed report is a point (n, arrival), n its
//    number among the reports; over at least kFitBaselineUs of them (the newest
//    kFitPoints), the least-delayed point of the older half and of the newer half give the
//    slope of a = n·T + d_min: the device's own period on the host's clock, whatever the
//    delays in between. Counted in reports, not slots: a slot skipped for a drop is the
//    fit's consequence, so counting it would let a short T confirm itself. Drops lengthen T
//    by the drop rate (a few per thousand on a loaded VM: the velocity as much low).
//
//  * the lead bound: no report is placed more than kMaxLeadUs (100 ms) after its arrival,
//    ŝ_i − a_i ≤ kMaxLeadUs. Physically ŝ_i − a_i = d_anchor − d_i ≤ d_anchor, the delay of
//    the report the grid was anchored on: the newest of a drain, so at most about a period
//    plus the link's delay (a few ms; a starved device's gap between reports); the period's
//    learning error adds a few ms a second until the fit corrects it. Beyond that the slots
//    have run ahead of the device, which a drain holding more reports than periods have
//    passed does (stale or repeated reports in it, a period learned while the device skipped
//    ticks), and before this bound every such drain lowered the floor for good: the grid
//    never came back, and a starved host's clock ran seconds ahead of the arrivals. Now the
//    floor comes down no further than −kMaxLeadUs; a drain whose slots would pass the bound
//    has its skip cut to the whole periods that fit, or, if even its plain slots do not fit,
//    is spread evenly over the time there is (from the last sense time to the bound; a
//    microsecond apart at least, so a drain read within n µs of the last one at the bound
//    may pass it by its n µs). Drains compressed since the last fit are evidence that the
//    period is too long: a fit more than a fifth shorter, otherwise a miscount, then shortens
//    it by a fifth. A stall render (place_silence) keeps the bound too.
//
// The sense times are the host's clock shifted by the least delay (ŝ ≈ s + d_min), a
// constant offset the engine never sees: only differences matter to it. Their differences
// are whole periods: the velocity the host estimates is then the one the device would,
// from the same samples. A device that goes silent for longer than kWindowUs (or reports
// only on change) is re-anchored by its next report: it takes the slot nearest its arrival.
//
// Pure: no clock, no threads; the host's I/O thread feeds it the read times.
#pragma once

#include <cstdint>
#include <span>

namespace feel::host::emulation {

class SenseClock {
public:
    static constexpr int kLearnReports = 32;
    static constexpr int64_t kLearnUs = 500'000;
    static constexpr int64_t kWindowUs = 500'000;       // the drop evidence window (two halves)
    static constexpr int64_t kFitBaselineUs = 1'000'000;  // the period fit's shortest baseline
    static constexpr int64_t kMaxLeadUs = 100'000;        // the most a sense time is after its arrival

    // One drain: the read times (host µs, non-decreasing) of reports read back to back,
    // oldest first. Writes each one's sense time (host µs, increasing) to `sense`
    // (sense.size() == arrivals.size()).
    void place(std::span<const int64_t> arrivals, std::span<int64_t> sense) noexcept;
    // A render with no report (a silent device): the sense time of host time `now_us`, at
    // least a period after the last report's; it takes that slot.
    [[nodiscard]] int64_t place_silence(int64_t now_us) noexcept;

    [[nodiscard]] bool learned() const noexcept { return period_us_ > 0; }
    [[nodiscard]] double period_us() const noexcept { return period_us_; }  // 0 while learning
    [[nodiscard]] int64_t slots_skipped() const noexcept { return skipped_; }  // counted as dropped
    // Drains spread over less than their periods to keep the lead bound.
    [[nodiscard]] int64_t drains_compressed() const noexcept { return compressed_; }
    [[nodiscard]] double floor_us() const noexcept { return floor_; }        // the least delay seen
    [[nodiscard]] int64_t last_sense_us() const noexcept { return static_cast<int64_t>(last_); }

private:
    void learn(std::span<const int64_t> arrivals, std::span<int64_t> sense) noexcept;
    // The drop evidence of a report of apparent excess `excess` (a − ŝ − floor) read at `a`.
    void note_excess(int64_t a, double excess) noexcept;
    void note_fit_point(int64_t a, double excess) noexcept;

    double period_us_ = 0;
    double last_ = 0;  // the last report's sense time
    bool any_ = false;
    // Learning.
    int learn_count_ = 0;
    int64_t learn_first_ = 0;
    // Tracking.
    double floor_ = 0;
    int64_t slot_ = 0;     // the last report's slot (drops included)
    int64_t reports_ = 0;  // reports placed since learning (drops not included)
    int64_t last_arrival_ = 0;
    int64_t skipped_ = 0;
    int64_t compressed_ = 0;
    bool compressed_since_fit_ = false;
    // Drop evidence: the least excess of the current half window and of the one before it.
    int64_t half_ = -1;         // the current half window's index (a / (kWindowUs / 2))
    double half_min_ = 0;       // its least excess
    double prev_half_min_ = 0;  // the previous half window's (huge: none)
    // The period fit: the least-delayed report (reports placed, arrival) of each complete
    // half window, the newest kFitPoints of them.
    void refit() noexcept;
    struct FitPoint {
        int64_t slot = 0, arrival = 0;
    };
    static constexpr int kFitPoints = 64;
    FitPoint fit_points_[kFitPoints] = {};
    int fit_next_ = 0, fit_count_ = 0;
    double fit_best_ = 0;
    int64_t fit_slot_ = 0, fit_arrival_ = 0, fit_half_ = -1;
};

}  // namespace feel::host::emulation
