// Stream waveforms and the measurements of their reconstruction (stream_wave.hpp).
#include "stream_wave.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace feel::cli {

std::optional<StreamShape> stream_shape_from_name(const std::string& name) {
    if (name == "sine") return StreamShape::sine;
    if (name == "square") return StreamShape::square;
    if (name == "step") return StreamShape::step;
    return std::nullopt;
}

double StreamWave::at(double t) const noexcept {
    if (t < 0) return 0;
    switch (shape) {
        case StreamShape::sine:
            return amplitude * std::sin(2 * std::numbers::pi * frequency_hz * t);
        case StreamShape::square: {
            const double cycles = t * frequency_hz;
            return cycles - std::floor(cycles) < 0.5 ? amplitude : -amplitude;
        }
        case StreamShape::step:
            return t < length_s / 2 ? 0 : amplitude;
    }
    return 0;
}

StreamObserver::StreamObserver(const StreamWave& wave, double sample_period_s, double force_before)
    : wave_(wave), window_s_(4 * sample_period_s + 0.05) {
    // The device ramps from the force it had to the first sample.
    recent_samples_.push_back({-std::numeric_limits<double>::infinity(), force_before});
}

void StreamObserver::sent(double t, double sample) {
    ++samples_;
    recent_samples_.push_back({t, sample});
    // Keep the window and the one sample before it: the device may still be ramping from it.
    while (recent_samples_.size() > 2 && recent_samples_[1].t < t - window_s_) recent_samples_.pop_front();
}

void StreamObserver::applied(double t, double force) {
    ++reports_;
    if (samples_ == 0) return;  // nothing streamed yet: the device's force is its own
    double low = recent_samples_.front().value, high = low;
    for (const Point& p : recent_samples_) {
        if (p.t > t) break;
        low = std::min(low, p.value);
        high = std::max(high, p.value);
    }
    max_overshoot_ = std::max({max_overshoot_, force - high, low - force});
    max_error_ = std::max(max_error_, std::fabs(force - wave_.at(t)));
    if (kept_reports_.size() < kMaxKeptReports) kept_reports_.push_back({t, force});
}

StreamObserver::DelayFit StreamObserver::fit_delay() const {
    DelayFit best;
    best.rms_error = std::numeric_limits<double>::infinity();
    const int steps = static_cast<int>(std::lround(kMaxDelayS / kDelayStepS));
    for (int i = 0; i <= steps; ++i) {
        const double delay = i * kDelayStepS;
        double sum = 0, worst = 0;
        std::size_t n = 0;
        for (const Point& p : kept_reports_) {
            if (p.t < delay) continue;  // before the stream reached the device
            const double e = p.value - wave_.at(p.t - delay);
            sum += e * e;
            worst = std::max(worst, std::fabs(e));
            ++n;
        }
        if (n == 0) continue;
        const double rms = std::sqrt(sum / static_cast<double>(n));
        if (rms < best.rms_error) best = {delay, rms, worst, n};
    }
    if (best.points == 0) best.rms_error = 0;
    return best;
}

}  // namespace feel::cli
