// Force streaming round trip at 1 kHz (issue 6, §8 "Streaming"; primer §2.4).
//
// The host closes the loop: it sends one force sample every millisecond with
// Device::stream_force, and the device adds it to its effects' force. This program
// measures, for each sample, the time from just before the host sent it to the arrival on
// the host of the first state report whose motor force shows it: the round trip a
// host-side control loop lives with.
//
// Telling samples apart. The stream is a rising ramp (1000, 1008, 1016, ... one step per
// millisecond for one second), so the first report with force >= a sample's value is the
// first that shows that sample: the device's reconstruction never overshoots
// (runtime/force_stream.hpp), so the force cannot reach a value before the sample that
// carries it arrived, and at 1 kHz it passes each sample through in the tick it arrives.
// Between ramps the stream sends 0 for 100 ms (still one sample per millisecond, so the
// device's estimate of the stream rate stays at 1 kHz); zeros are not timed. The first
// ramp warms up that estimate (a device assumes a 60 Hz stream until it has measured one)
// and is not timed either. A sample that no report shows within 100 ms counts as lost:
// none is when the host keeps its 1 ms grid; when the host's sends jitter (a loaded
// machine: see "late"), two samples can land in one device tick, the device's estimate of
// the stream interval grows past one tick (runtime/force_stream.hpp), its ramp trails by a
// tick or two, and the last sample of a ramp can be overtaken by the zeros that follow
// before the output reaches it.
//
// Timing. The host thread sends on a 1 ms grid of the steady clock and, between sends,
// looks at the newest input state every ~50 µs (Device::input(), no round trip), so the
// arrival time is exact to about that. State reports are set to 1000 Hz. Host and device
// are in one process (in-process, a Peripheral serving a Unix socket and TCP on
// loopback), so one clock times both ends. The first row is the runtime alone (commands
// and reports through its queues, no protocol): every report is read, and the device
// part — the stream_force ack's tick to the tick of the report showing the sample — is
// exact in device time.
//
// Run: build/bench/bench_streaming [RAMPS]     (default 5 one-second ramps, the first untimed)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

#include "feel/host/device.hpp"
#include "host_bench_support.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/runtime/device_runtime.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/transport/transport.hpp"

namespace {

using namespace feel;
using bench::Clock;
using bench::ms_since;
using bench::percentile;
using bench::require;

constexpr const char* kProfile = "iforce2";
constexpr int32_t kReportRateHz = 1000;
constexpr int kRampSamples = 1000;   // one second at 1 kHz
constexpr int kGapSamples = 100;     // 100 ms of zeros between ramps
constexpr int32_t kRampStart = 1000;
constexpr int32_t kRampStep = 8;     // 1000 .. 8992
constexpr double kLostAfterMs = 100;
constexpr auto kWaitLimit = std::chrono::milliseconds(2000);



// Sample n of the stream and whether it is timed.
struct StreamSample {
    int32_t value = 0;
    bool timed = false;
};
StreamSample sample_at(int64_t n) {
    const int64_t cycle = kRampSamples + kGapSamples;
    const int64_t ramp = n / cycle;
    const int64_t i = n % cycle;
    if (i >= kRampSamples) return {0, false};
    return {kRampStart + kRampStep * static_cast<int32_t>(i), ramp > 0};
}

// The samples sent and not yet seen, and the round trips of those seen.
class RoundTrips {
public:
    void sent(int32_t value, bool timed, Clock::time_point at) {
        if (timed) pending_.push_back({value, at});
    }
    // A state report showing `force` arrived at `at`.
    void seen(float force, Clock::time_point at) {
        // Lost first: a sample of an earlier ramp must not match this report.
        while (!pending_.empty() && ms_since(pending_.front().at, at) > kLostAfterMs) {
            ++lost_;
            pending_.pop_front();
        }
        while (!pending_.empty() && static_cast<float>(pending_.front().value) <= force + 0.5f) {
            ms_.push_back(ms_since(pending_.front().at, at));
            pending_.pop_front();
        }
    }
    [[nodiscard]] const std::vector<double>& ms() const { return ms_; }
    [[nodiscard]] std::size_t lost() const { return lost_ + pending_.size(); }

private:
    struct Pending {
        int32_t value;
        Clock::time_point at;
    };
    std::deque<Pending> pending_;
    std::vector<double> ms_;
    std::size_t lost_ = 0;
};


struct Figures {
    std::vector<double> ms;
    std::size_t lost = 0;
    std::size_t sent = 0;
    std::size_t late_sends = 0;  // sends more than 0.5 ms after their slot
    std::vector<double> device_us;  // runtime only
};

// ---------------------------------------------------------------------------------------

Figures measure_host(host::Device& device, int ramps) {
    require(device.set_report_rate(kReportRateHz), "set_report_rate");
    const Clock::time_point ready_limit = Clock::now() + kWaitLimit;
    while (device.input().fade_level < 1.0f || device.input().reports_received == 0) {
        if (Clock::now() > ready_limit) throw std::runtime_error("the device did not reach full strength");
        (void)device.wait_input(std::chrono::milliseconds(50));
    }
    const int32_t axes = device.capabilities().axis_count;
    std::vector<int32_t> force(static_cast<std::size_t>(axes), 0);
    RoundTrips trips;
    Figures f;
    const int64_t total = static_cast<int64_t>(ramps) * (kRampSamples + kGapSamples);
    uint64_t reports_seen = device.input().reports_received;
    const Clock::time_point t0 = Clock::now();
    for (int64_t n = 0; n < total; ++n) {
        const Clock::time_point slot = t0 + std::chrono::microseconds(1000 * n);
        for (;;) {  // until the slot: watch the reports
            const host::InputState s = device.input();
            if (s.reports_received != reports_seen) {
                reports_seen = s.reports_received;
                trips.seen(s.force[0], Clock::now());
            }
            if (Clock::now() >= slot) break;
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
        const StreamSample sample = sample_at(n);
        force[0] = sample.value;
        const Clock::time_point at = Clock::now();
        if (ms_since(slot, at) > 0.5) ++f.late_sends;
        require(device.stream_force(force), "stream_force");
        trips.sent(sample.value, sample.timed, at);
        ++f.sent;
    }
    std::fill(force.begin(), force.end(), 0);
    require(device.stream_force(force), "stream_force");
    f.ms = trips.ms();
    f.lost = trips.lost();
    return f;
}

Figures measure_runtime(int ramps) {
    using namespace feel::runtime;
    const sim::DeviceProfile& profile = *sim::find_device_profile(kProfile);
    RuntimeConfig config = runtime_config_for(profile);
    config.report_rate_hz = kReportRateHz;
    DeviceRuntime rt(config, std::make_unique<SimBackend>(profile, sim::Grip::firm,
                                                          sim::TargetMotion::parse("hold:0", 1e9, profile.axis_count)));
    rt.start();
    Report r;
    const Clock::time_point ready_limit = Clock::now() + kWaitLimit;
    for (bool ready = false; !ready;) {
        while (rt.poll(r)) ready = ready || (r.kind == ReportKind::state && r.state.safety.fade_level >= 1.0f);
        if (Clock::now() > ready_limit) throw std::runtime_error("the runtime did not reach full strength");
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    std::vector<int16_t> force(static_cast<std::size_t>(profile.axis_count), 0);
    RoundTrips trips;
    Figures f;
    // The device part: the tick that applied each timed sample (its ack) and the tick of
    // the first report showing it.
    struct Applied {
        uint32_t sequence;
        int32_t value;
        int64_t ack_t_us;
    };
    std::deque<Applied> awaiting;
    auto drain = [&] {
        while (rt.poll(r)) {
            const Clock::time_point now = Clock::now();
            if (r.kind == ReportKind::ack && r.ack.command == CommandKind::stream_force) {
                if (!r.ack.error.ok()) throw std::runtime_error("stream_force refused: " + r.ack.error.message());
                for (Applied& a : awaiting) {
                    if (a.sequence == r.ack.sequence) a.ack_t_us = r.ack.t_us;
                }
            } else if (r.kind == ReportKind::state) {
                trips.seen(r.state.force[0], now);
                // A sample no report showed within the lost limit (device time) never will.
                while (!awaiting.empty() && awaiting.front().ack_t_us >= 0 &&
                       static_cast<double>(r.state.t_us - awaiting.front().ack_t_us) > kLostAfterMs * 1e3) {
                    awaiting.pop_front();
                }
                while (!awaiting.empty() && awaiting.front().ack_t_us >= 0 &&
                       static_cast<float>(awaiting.front().value) <= r.state.force[0] + 0.5f) {
                    f.device_us.push_back(static_cast<double>(r.state.t_us - awaiting.front().ack_t_us));
                    awaiting.pop_front();
                }
                while (awaiting.size() > 200) awaiting.pop_front();  // acks that never came
            }
        }
    };
    const int64_t total = static_cast<int64_t>(ramps) * (kRampSamples + kGapSamples);
    const Clock::time_point t0 = Clock::now();
    for (int64_t n = 0; n < total; ++n) {
        const Clock::time_point slot = t0 + std::chrono::microseconds(1000 * n);
        for (;;) {
            drain();
            if (Clock::now() >= slot) break;
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
        const StreamSample sample = sample_at(n);
        force[0] = static_cast<int16_t>(sample.value);
        const Clock::time_point at = Clock::now();
        if (ms_since(slot, at) > 0.5) ++f.late_sends;
        const std::optional<uint32_t> seq = rt.stream_force(force);
        if (!seq) throw std::runtime_error("the command queue is full");
        trips.sent(sample.value, sample.timed, at);
        if (sample.timed) awaiting.push_back({*seq, sample.value, -1});
        ++f.sent;
    }
    drain();
    rt.stop();
    f.ms = trips.ms();
    f.lost = trips.lost();
    return f;
}

void row(const char* transport, const Figures& f) {
    std::printf("%-14s %8.3f %8.3f %8.3f %8zu %6zu %6zu\n", transport, percentile(f.ms, 50), percentile(f.ms, 99),
                percentile(f.ms, 100), f.ms.size(), f.lost, f.late_sends);
}

}  // namespace

int main(int argc, char** argv) {
    int ramps = 5;
    if (argc > 1) {
        ramps = std::atoi(argv[1]);
        if (ramps < 2 || ramps > 600) {
            std::fprintf(stderr, "bench_streaming: RAMPS = %s is out of range (allowed 2..600)\n", argv[1]);
            return 2;
        }
    }
    try {
        std::printf("feel force streaming round trip at 1 kHz: stream_force -> first state report showing the sample\n"
                    "device %s (1000 Hz loop), state reports at %d Hz, %d ramps of %d samples (the first untimed),\n"
                    "host std::chrono::steady_clock; times in ms\n\n",
                    kProfile, kReportRateHz, ramps, kRampSamples);
        std::printf("%-14s %8s %8s %8s %8s %6s %6s\n", "transport", "p50", "p99", "max", "timed", "lost", "late");
        const Figures runtime = measure_runtime(ramps);
        row("runtime only", runtime);
        bench::for_each_transport(kProfile, "feel-bench-stream", [&](const char* name, host::Device& device) {
            row(name, measure_host(device, ramps));
        });
        std::printf("\ndevice side (runtime, stream_force ack t_us -> first report t_us showing the sample): "
                    "p50 %.0f us, p99 %.0f us, max %.0f us\n",
                    percentile(runtime.device_us, 50), percentile(runtime.device_us, 99),
                    percentile(runtime.device_us, 100));
        std::printf("timed = samples whose round trip was measured; lost = not seen within %.0f ms; late = sends "
                    "more than 0.5 ms after their 1 ms slot\n",
                    kLostAfterMs);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_streaming: %s\n", e.what());
        return 1;
    }
    return 0;
}
