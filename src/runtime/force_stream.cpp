// The force stream's reconstruction filter: linear ramps one estimated interval long,
// starting from where the output is (force_stream.hpp explains the choice).
#include "feel/runtime/force_stream.hpp"

#include <algorithm>
#include <cmath>

#include "feel/units.hpp"

namespace feel::runtime {
namespace {

int32_t ticks_for(int64_t us, int32_t loop_rate_hz) noexcept {
    const int64_t ticks = (us * loop_rate_hz + 500'000) / 1'000'000;
    return static_cast<int32_t>(std::max<int64_t>(1, ticks));
}

}  // namespace

ForceStream::ForceStream(int32_t axis_count, int32_t loop_rate_hz) noexcept
    : axis_count_(std::clamp<int32_t>(axis_count, 1, kMaxAxes)) {
    const int32_t rate = std::max<int32_t>(1, loop_rate_hz);
    max_interval_ticks_ = ticks_for(kMaxIntervalUs, rate);
    initial_interval_ticks_ = std::min(ticks_for(kInitialIntervalUs, rate), max_interval_ticks_);
}

int32_t ForceStream::interval_ticks() const noexcept {
    if (interval_count_ == 0) return initial_interval_ticks_;
    // The median of the remembered intervals; a copy, so the ring keeps its order.
    int32_t sorted[kIntervalHistory];
    std::copy(intervals_, intervals_ + interval_count_, sorted);
    const int32_t middle = interval_count_ / 2;
    std::nth_element(sorted, sorted + middle, sorted + interval_count_);
    return std::clamp(sorted[middle], 1, max_interval_ticks_);
}

double ForceStream::value_at(int axis, int64_t tick) const noexcept {
    const double start = start_[axis];
    const double target = target_[axis];
    const int64_t done = tick - ramp_tick_ + 1;  // ticks of the ramp played by the end of `tick`
    if (done >= ramp_ticks_) return target;
    if (done <= 0) return start;
    const double value = start + (target - start) * (static_cast<double>(done) / ramp_ticks_);
    // Rounding must not carry the ramp past either end.
    return std::clamp(value, std::min(start, target), std::max(start, target));
}

void ForceStream::push(int64_t tick, const int16_t* force) noexcept {
    if (active_ && tick != ramp_tick_) {
        const int64_t gap = tick - ramp_tick_;
        if (gap > 0 && gap <= max_interval_ticks_) {
            intervals_[interval_next_] = static_cast<int32_t>(gap);
            interval_next_ = (interval_next_ + 1) % kIntervalHistory;
            interval_count_ = std::min(interval_count_ + 1, kIntervalHistory);
        }
    }
    // The new ramp starts from what the output was in the tick before this one; a second
    // sample in the same tick keeps that start and only replaces the target.
    for (int a = 0; a < axis_count_; ++a) {
        const double previous = active_ ? value_at(a, tick - 1) : 0.0;
        start_[a] = previous;
        target_[a] = std::clamp<double>(force[a], -kFullScale, kFullScale);
    }
    ramp_tick_ = tick;
    ramp_ticks_ = interval_ticks();
    active_ = true;
    ++samples_;
}

void ForceStream::output(int64_t tick, float out[kMaxAxes]) const noexcept {
    for (int a = 0; a < kMaxAxes; ++a) {
        out[a] = active_ && a < axis_count_ ? static_cast<float>(value_at(a, tick)) : 0.0f;
    }
}

void ForceStream::clear() noexcept {
    active_ = false;
    std::fill(std::begin(start_), std::end(start_), 0.0);
    std::fill(std::begin(target_), std::end(target_), 0.0);
    interval_count_ = 0;
    interval_next_ = 0;
    ramp_ticks_ = 1;
}

void add_streamed_force(const float streamed[kMaxAxes], int32_t axis_count, int32_t gain, bool output_on,
                        float force[kMaxAxes]) noexcept {
    const double scale = output_on ? std::clamp(gain, 0, kFullScale) / static_cast<double>(kFullScale) : 0.0;
    for (int a = 0; a < kMaxAxes; ++a) {
        if (a >= axis_count) {
            force[a] = 0.0f;
            continue;
        }
        double f = static_cast<double>(force[a]) + static_cast<double>(streamed[a]) * scale;
        if (!std::isfinite(f)) f = 0.0;
        force[a] = static_cast<float>(std::clamp<double>(f, -kFullScale, kFullScale));
    }
}

}  // namespace feel::runtime
