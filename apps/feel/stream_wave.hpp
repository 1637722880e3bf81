// The waveforms `feel stream` sends, and what it measures of the device's answer.
//
// StreamWave is the ideal force: the host samples it at the stream rate and sends each
// sample (rounded to a whole force unit). StreamObserver keeps what was sent and what the
// device reported applying, and tells afterwards how faithfully the device reconstructed
// the stream (§2.4):
//   * overshoot: how far an applied force went beyond the samples around it. The device's
//     reconstruction (runtime/force_stream.hpp) moves only between the output it had and
//     the newest sample, so this is 0 up to float rounding;
//   * the delay that best aligns the applied force with the ideal waveform (least RMS
//     error over 0..kMaxDelayS), and the largest error at that delay: one sample interval
//     of interpolation plus the trip to the device and back;
//   * the largest error without aligning (what a player would feel as lag).
// Times are host seconds since the stream started.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

namespace feel::cli {

enum class StreamShape : uint8_t { sine, square, step };

// "sine", "square", "step"; nullopt for another word.
[[nodiscard]] std::optional<StreamShape> stream_shape_from_name(const std::string& name);

struct StreamWave {
    StreamShape shape = StreamShape::sine;
    double amplitude = 5000;   // 0..10000
    double frequency_hz = 1;   // sine, square
    double length_s = 3;       // step: 0 for the first half of it, then the amplitude

    // The ideal force at t seconds (t < 0 is before the stream: 0).
    //   sine   A·sin(2π·F·t)
    //   square +A for the first half of each period (from t = 0), −A for the second
    //   step   0 before length/2, A from then on
    [[nodiscard]] double at(double t) const noexcept;
};

class StreamObserver {
public:
    static constexpr double kMaxDelayS = 0.25;       // the delay search's range
    static constexpr double kDelayStepS = 0.0005;    // and its resolution
    static constexpr std::size_t kMaxKeptReports = 20000;  // reports kept for the fit

    // sample_period_s: 1 / the stream rate; force_before: the device's force on the
    // streamed axis before the first sample (it ramps from there).
    StreamObserver(const StreamWave& wave, double sample_period_s, double force_before = 0);

    void sent(double t, double sample);     // a sample left the host at t
    void applied(double t, double force);   // a state report with this force arrived at t

    [[nodiscard]] uint64_t samples_sent() const noexcept { return samples_; }
    [[nodiscard]] uint64_t reports() const noexcept { return reports_; }
    // The furthest an applied force went beyond [min, max] of the samples sent in a window
    // before its report (4 sample periods + 50 ms, and the sample before it; before the
    // first samples, force_before), >= 0.
    [[nodiscard]] double max_overshoot() const noexcept { return max_overshoot_; }
    // max |applied(t) − ideal(t)| over the reports after the first sample.
    [[nodiscard]] double max_error() const noexcept { return max_error_; }

    struct DelayFit {
        double delay_s = 0;      // the delay with the least RMS error
        double rms_error = 0;    // at that delay
        double max_error = 0;    // max |applied(t) − ideal(t − delay)| at that delay
        std::size_t points = 0;  // reports used (those kept, at least delay after the start)
    };
    // Searches 0..kMaxDelayS in kDelayStepS steps over the kept reports.
    [[nodiscard]] DelayFit fit_delay() const;

private:
    struct Point {
        double t;
        double value;
    };
    StreamWave wave_;
    double window_s_;
    std::deque<Point> recent_samples_;  // the samples of the overshoot window
    std::vector<Point> kept_reports_;
    uint64_t samples_ = 0;
    uint64_t reports_ = 0;
    double max_overshoot_ = 0;
    double max_error_ = 0;
};

}  // namespace feel::cli
