// feel stream: the host closes the loop (§2.4) — a demonstration of force streaming.
//
// The host computes a force waveform itself (sine, square or step on the x axis) and
// sends one sample of it every 1/rate seconds with Device::stream_force, the way a game
// streams a force computed from the handle's position each frame. The device smooths the
// samples into its ~1 kHz loop (runtime/force_stream.hpp: a ramp from its present output
// to each new sample, one sample interval long) and reports the force its motors got in
// every state report, which arrive at up to 1 kHz. Ten times a second a line shows the
// last sample sent next to the force the device applied; the summary tells how faithful
// the reconstruction was (stream_wave.hpp): no overshoot beyond the samples, the delay
// that aligns the applied force with the ideal waveform, and the error left.
//
// Timing. Sample k is due at k/rate seconds after the start on the host's steady clock;
// between deadlines the command reads the device's reports. A host that falls behind
// (a busy machine) sends the latest due sample and counts the ones it skipped, like a
// game that drops a frame. After the last sample the device holds it (§2.4: the stream
// stopping is not a force the host commanded); the command shows the held force for
// kHoldCheck, then streams a final 0 so that the handle is left without force.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli.hpp"
#include "feel/host/device.hpp"
#include "flag_checks.hpp"
#include "host_device.hpp"
#include "interrupt.hpp"
#include "live_output.hpp"
#include "stream_wave.hpp"

namespace feel::cli {
namespace {

using Clock = std::chrono::steady_clock;

constexpr double kMaxSeconds = 600;
constexpr auto kProgressPeriod = std::chrono::milliseconds(100);
constexpr auto kHoldCheck = std::chrono::milliseconds(200);
constexpr auto kFadeInLimit = std::chrono::milliseconds(2000);

double seconds_since(Clock::time_point t0, Clock::time_point t) {
    return std::chrono::duration<double>(t - t0).count();
}

StreamWave checked_wave(const StreamArgs& args, int32_t rate) {
    StreamWave wave;
    const std::optional<StreamShape> shape = stream_shape_from_name(args.shape);
    if (!shape) throw UsageError("--shape \"" + args.shape + "\" is not a shape (allowed: sine, square, step)");
    wave.shape = *shape;
    wave.amplitude = checked_range("--amplitude", args.amplitude, 0, 10000, "");
    wave.frequency_hz = checked_range("--frequency", args.frequency_hz, 0, rate / 2.0, "Hz", false);
    wave.length_s = args.seconds;
    return wave;
}

std::string describe(const StreamWave& wave) {
    switch (wave.shape) {
        case StreamShape::sine: return "sine, amplitude " + number(wave.amplitude) + ", " + number(wave.frequency_hz) + " Hz";
        case StreamShape::square:
            return "square, amplitude " + number(wave.amplitude) + ", " + number(wave.frequency_hz) + " Hz";
        case StreamShape::step: return "step from 0 to " + number(wave.amplitude) + " at " + format_elapsed(wave.length_s / 2);
    }
    return "";
}

std::string progress_line(double t, int32_t sample, float applied) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "%s   sent x %+6d   applied x %+8.1f", format_elapsed(t).c_str(), sample,
                  static_cast<double>(applied));
    return buf;
}

}  // namespace

void run_stream(const StreamArgs& args, std::ostream& out, std::ostream& err) {
    const int32_t rate = checked_whole("--rate", args.rate_hz, 1, 1000, "Hz");
    const double seconds = checked_range("--seconds", args.seconds, 0, kMaxSeconds, "s", false);
    const StreamWave wave = checked_wave(args, rate);

    host::Device device = open_device(args.device);
    const host::DeviceCaps& caps = device.capabilities();
    const int32_t report_hz = use_fastest_reports(device);
    if (!wait_for_full_strength(device, kFadeInLimit)) {
        err << "feel stream: note: the device's forces are faded to " << number(device.input().fade_level)
            << " of full strength (is the handle held?)\n";
    }
    const int32_t axes = caps.axis_count;
    out << "streaming  " << describe(wave) << " on x, " << rate << " samples/s for " << number(seconds) << " s\n"
        << "to         " << device.address() << " (" << caps.device << ", " << caps.class_name
        << "), state reports at " << report_hz << " Hz\n"
        << std::flush;

    const double period_s = 1.0 / rate;
    StreamObserver observer(wave, period_s, device.input().force[0]);
    std::vector<int32_t> force(static_cast<std::size_t>(axes), 0);
    LiveLine live(out, args.terminal);
    uint64_t skipped = 0, refused = 0;
    std::string first_refusal;
    int64_t last_index = -1;
    int32_t last_sample = 0;
    float last_applied = device.input().force[0];
    const Clock::time_point t0 = Clock::now();
    Clock::time_point next_line = t0 + kProgressPeriod;
    bool interrupted = false;
    uint64_t reports_seen = device.input().reports_received;
    for (;;) {
        if (stop_requested().load()) {
            interrupted = true;
            break;
        }
        // The device's newest report, if one came since the last look.
        const host::InputState state = device.input();
        if (state.reports_received != reports_seen) {
            reports_seen = state.reports_received;
            const Clock::time_point arrived = Clock::now();
            last_applied = state.force[0];
            observer.applied(seconds_since(t0, arrived), last_applied);
            if (arrived >= next_line) {
                while (next_line <= arrived) next_line += kProgressPeriod;
                live.show(progress_line(seconds_since(t0, arrived), last_sample, last_applied));
            }
        }
        const Clock::time_point now = Clock::now();
        const double t = seconds_since(t0, now);
        if (t >= seconds) break;
        const auto due = static_cast<int64_t>(std::floor(t * rate));
        if (due > last_index) {
            skipped += static_cast<uint64_t>(due - last_index - 1);
            last_index = due;
            const double sample_t = static_cast<double>(due) * period_s;
            last_sample = static_cast<int32_t>(std::lround(wave.at(sample_t)));
            force[0] = last_sample;
            const host::Status sent = device.stream_force(force);
            if (!sent.ok()) {
                if (sent.kind == host::ErrorKind::disconnected) check(sent, "stream a force sample");
                if (refused++ == 0) first_refusal = sent.message;
            }
            observer.sent(seconds_since(t0, Clock::now()), last_sample);
            continue;
        }
        // Until the next sample is due, wait for the device's next report (wait_input
        // counts whole milliseconds; a shorter wait sleeps).
        const Clock::time_point next_due = t0 + std::chrono::duration_cast<Clock::duration>(
                                                    std::chrono::duration<double>(static_cast<double>(due + 1) * period_s));
        const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(next_due - now);
        if (wait.count() <= 0) {
            std::this_thread::sleep_until(next_due);
            continue;
        }
        const host::Result<host::InputState> report = device.wait_input(wait);
        if (!report && report.status().kind != host::ErrorKind::timeout) check(report.status(), "read the device's state");
    }
    const double streamed_s = seconds_since(t0, Clock::now());
    live.show(progress_line(streamed_s, last_sample, last_applied));
    live.finish();

    // The stream has stopped: the device holds the last sample.
    const Clock::time_point hold_end = Clock::now() + kHoldCheck;
    while (Clock::now() < hold_end && !interrupted) {
        const host::Result<host::InputState> report = device.wait_input(std::chrono::milliseconds(20));
        if (report) last_applied = report->force[0];
        else if (report.status().kind != host::ErrorKind::timeout) check(report.status(), "read the device's state");
    }
    std::fill(force.begin(), force.end(), 0);
    const host::Status released = device.stream_force(force);
    if (released.kind == host::ErrorKind::disconnected) check(released, "stream the final 0");

    const StreamObserver::DelayFit fit = observer.fit_delay();
    char line[160];
    out << "sent       " << observer.samples_sent() << " samples in " << format_elapsed(streamed_s);
    if (skipped > 0) out << " (" << skipped << " skipped: the host fell behind)";
    out << (interrupted ? " (interrupted)" : "") << '\n';
    out << "reports    " << observer.reports() << " device reports read\n";
    std::snprintf(line, sizeof line, "overshoot  %.1f beyond the samples (0 = the device stayed within them)\n",
                  observer.max_overshoot());
    out << line;
    std::snprintf(line, sizeof line, "delay      %.1f ms (best fit of the applied force to the ideal waveform)\n",
                  fit.delay_s * 1e3);
    out << line;
    std::snprintf(line, sizeof line, "error      max |applied - ideal| %.1f, after the delay %.1f (RMS %.1f)\n",
                  observer.max_error(), fit.max_error, fit.rms_error);
    out << line;
    std::snprintf(line, sizeof line, "held       x %+.1f for %d ms after the last sample (%+d)\n",
                  static_cast<double>(last_applied), static_cast<int>(kHoldCheck.count()), last_sample);
    out << line;
    out << "(force is normalized, ±10000 = the motor limit)\n";
    device.close();
    if (refused > 0) {
        throw std::runtime_error("the device refused " + std::to_string(refused) + " of " +
                                 std::to_string(observer.samples_sent()) + " samples: " + first_refusal);
    }
}

}  // namespace feel::cli
