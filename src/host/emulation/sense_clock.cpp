// SenseClock: the sense time of each Input report from the report sequence (sense_clock.hpp).
#include "emulation/sense_clock.hpp"

#include <algorithm>
#include <cmath>

namespace feel::host::emulation {

namespace {
constexpr int64_t kHalfUs = SenseClock::kWindowUs / 2;
constexpr double kNone = 1e18;  // an empty window's least excess
}  // namespace

void SenseClock::learn(std::span<const int64_t> arrivals, std::span<int64_t> sense) noexcept {
    // Stamped with the arrival until the period is known (never backwards, never equal).
    for (std::size_t j = 0; j < arrivals.size(); ++j) {
        const double s = any_ ? std::max(last_ + 1.0, static_cast<double>(arrivals[j])) : static_cast<double>(arrivals[j]);
        sense[j] = static_cast<int64_t>(s);
        last_ = static_cast<double>(sense[j]);
        any_ = true;
    }
    // From the newest report of the first drain to the newest of a later one: each is the
    // freshest of its drain, so a burst at either end does not bend the count.
    if (learn_count_ == 0) {
        learn_first_ = arrivals.back();
        learn_count_ = 1;
        return;
    }
    learn_count_ += static_cast<int>(arrivals.size());
    const int64_t span = arrivals.back() - learn_first_;
    if (learn_count_ >= kLearnReports && span >= kLearnUs) {
        period_us_ = static_cast<double>(span) / (learn_count_ - 1);
        last_ = static_cast<double>(arrivals.back());  // the newest anchors the grid: its delay is the floor
        floor_ = 0;
        slot_ = 0;
        half_ = arrivals.back() / kHalfUs;
        half_min_ = 0;
        prev_half_min_ = kNone;
        fit_half_ = half_;
        fit_best_ = 0;
        fit_slot_ = 0;
        fit_arrival_ = arrivals.back();
    }
    last_arrival_ = arrivals.back();
}

void SenseClock::note_fit_point(int64_t a, double excess) noexcept {
    const int64_t h = a / kHalfUs;
    if (h != fit_half_) {
        // The half window [fit_half_] is complete: its least-delayed report is a fit point.
        if (fit_best_ < kNone) {
            fit_points_[fit_next_] = {fit_slot_, fit_arrival_};
            fit_next_ = (fit_next_ + 1) % kFitPoints;
            fit_count_ = std::min(fit_count_ + 1, kFitPoints);
            refit();
        }
        fit_half_ = h;
        fit_best_ = kNone;
    }
    if (excess < fit_best_) {
        fit_best_ = excess;
        fit_slot_ = reports_;
        fit_arrival_ = a;
    }
}

void SenseClock::refit() noexcept {
    if (fit_count_ < 4) return;
    // Oldest first: the ring's points from fit_next_ on.
    const auto point = [&](int i) -> const FitPoint& { return fit_points_[(fit_next_ - fit_count_ + i + kFitPoints) % kFitPoints]; };
    if (point(fit_count_ - 1).arrival - point(0).arrival < kFitBaselineUs) return;
    // The least-delayed point of the older half and of the newer half: the residual
    // a − slot·T of each is the link's least delay plus the line's error there, so the
    // slope between them corrects T by what the line misses, delays aside.
    const int half = fit_count_ / 2;
    double best[2] = {kNone, kNone};
    int64_t best_slot[2] = {0, 0};
    for (int i = 0; i < fit_count_; ++i) {
        const FitPoint& p = point(i);
        const double r = static_cast<double>(p.arrival) - static_cast<double>(p.slot) * period_us_;
        const int g = i < half ? 0 : 1;
        if (r < best[g]) {
            best[g] = r;
            best_slot[g] = p.slot;
        }
    }
    if (best_slot[1] <= best_slot[0]) return;
    const double fitted = period_us_ + (best[1] - best[0]) / static_cast<double>(best_slot[1] - best_slot[0]);
    // A fit far off the period in use is a miscount, not a clock rate: kept out. Unless the
    // lead bound has had to compress drains since the last fit: the slots ran ahead of the
    // arrivals, so the period in use is too long, and a shorter fit is the evidence of it
    // (a period learned while the device skipped ticks): the period shortens by a fifth, and
    // the fit starts afresh, since its older points are from the device's other rate.
    if (std::abs(fitted - period_us_) < 0.2 * period_us_) {
        period_us_ = fitted;
    } else if (compressed_since_fit_ && fitted < period_us_) {
        period_us_ *= 0.8;
        fit_count_ = 0;
    }
    compressed_since_fit_ = false;
}

void SenseClock::note_excess(int64_t a, double excess) noexcept {
    const int64_t h = a / kHalfUs;
    if (h != half_) {
        // A new half window: the one before it is the current one if adjacent, else empty.
        prev_half_min_ = h == half_ + 1 ? half_min_ : kNone;
        half_ = h;
        half_min_ = kNone;
    }
    half_min_ = std::min(half_min_, excess);
}

void SenseClock::place(std::span<const int64_t> arrivals, std::span<int64_t> sense) noexcept {
    if (arrivals.empty() || sense.size() != arrivals.size()) return;
    if (!learned()) {
        learn(arrivals, sense);
        return;
    }
    const auto n = static_cast<int64_t>(arrivals.size());
    const int64_t a = arrivals.back();
    constexpr auto kLead = static_cast<double>(kMaxLeadUs);
    // The next n slots; the newest's excess over the least delay.
    const double on_grid = last_ + static_cast<double>(n) * period_us_;
    double excess = static_cast<double>(a) - on_grid - floor_;
    if (excess < 0) {
        // Sooner than the least delay: the slots ran ahead; the floor comes down, no lower
        // than the lead bound (below), and the excesses kept (relative to it) go up by as
        // much. What the bound keeps the floor from taking, the drain's compression takes.
        const double lowered = std::max(floor_ + excess, -kLead);
        const double by = floor_ - lowered;
        floor_ = lowered;
        if (half_min_ < kNone) half_min_ += by;
        if (prev_half_min_ < kNone) prev_half_min_ += by;
        excess = 0;
    }
    note_excess(a, excess);
    // Drops: every report of the last window (both halves) came at least a period late.
    // After a silence of a whole window this report alone anchors the grid.
    const bool silent_before = a - last_arrival_ >= kWindowUs;
    const bool covered = prev_half_min_ < kNone;
    const double late = silent_before ? excess : std::min(half_min_, prev_half_min_);
    int64_t skip = 0;
    // (A quarter period of slack: a drop shows as a whole period, delay jitter does not.)
    if ((covered || silent_before) && late >= 0.75 * period_us_)
        skip = static_cast<int64_t>(std::floor(late / period_us_ + 0.25));
    // The lead bound: no report is placed more than kMaxLeadUs after its arrival. The latest
    // the newest slot may be with the drain a period apart: a skip that would pass it is cut
    // to the whole periods that fit; a drain whose slots do not fit even unskipped holds
    // more reports than periods have passed (stale or repeated reports, a period too long):
    // it is spread evenly over the time there is, from the last sense time to the bound.
    double latest = kNone;
    for (int64_t j = 0; j < n; ++j)
        latest = std::min(latest, static_cast<double>(arrivals[static_cast<std::size_t>(j)]) + kLead +
                                      static_cast<double>(n - 1 - j) * period_us_);
    if (on_grid + static_cast<double>(skip) * period_us_ > latest)
        skip = on_grid > latest ? 0 : static_cast<int64_t>(std::floor((latest - on_grid) / period_us_));
    double newest = on_grid + static_cast<double>(skip) * period_us_;
    double spacing = period_us_;
    if (newest > latest) {
        spacing = kNone;
        for (int64_t j = 0; j < n; ++j)
            spacing = std::min(spacing, (static_cast<double>(arrivals[static_cast<std::size_t>(j)]) + kLead - last_) /
                                            static_cast<double>(j + 1));
        spacing = std::max(spacing, 1.0);  // sense times still increase (by 1 µs at least)
        newest = last_ + static_cast<double>(n) * spacing;
        ++compressed_;
        compressed_since_fit_ = true;
    }
    if (skip > 0) {
        const double shift = static_cast<double>(skip) * period_us_;
        half_min_ -= shift;
        if (covered) prev_half_min_ -= shift;
        skipped_ += skip;
    }
    for (int64_t j = 0; j < n; ++j) {
        sense[static_cast<std::size_t>(j)] =
            static_cast<int64_t>(std::llround(newest - static_cast<double>(n - 1 - j) * spacing));
    }
    last_ = newest;
    last_arrival_ = a;
    slot_ += n + skip;
    reports_ += n;
    note_fit_point(a, static_cast<double>(a) - newest - floor_);
}

int64_t SenseClock::place_silence(int64_t now_us) noexcept {
    if (!learned()) {
        last_ = any_ ? std::max(last_ + 1.0, static_cast<double>(now_us)) : static_cast<double>(now_us);
        any_ = true;
        return static_cast<int64_t>(last_);
    }
    const double wanted = static_cast<double>(now_us) - floor_;
    const auto k = std::max<int64_t>(1, std::llround((wanted - last_) / period_us_));
    // The lead bound holds here too (the next reports arrive after now_us, and start from
    // this time): no later than now_us + kMaxLeadUs, still after the last sense time.
    const double bound = static_cast<double>(now_us) + static_cast<double>(kMaxLeadUs);
    last_ = std::max(last_ + 1.0, std::min(last_ + static_cast<double>(k) * period_us_, bound));
    slot_ += k;
    return std::llround(last_);
}

}  // namespace feel::host::emulation
