// The lockstep rig of the PidDevice tests: feel's simulated device (its DeviceSession on a
// RuntimePipeline, as the peripheral tests build it) ticked by the test in lockstep with the
// host. A tick, then the host is handed the frames the tick produced and the test waits
// until it has answered and sits in receive() again. So everything runs on device time (the
// host's clock reads it) and a run repeats exactly: a host report sent in answer to tick n's
// frames reaches the session before tick n + 1 (one tick of link latency, L = 1 ms).
//
// No wall time. However long the machine's load keeps the test's thread from its next step,
// the host lives none of it: its receive() waits for the next tick's frames (until the rig
// closes) instead of timing out, or PidDevice would take the wall-clock silence for a
// device gone quiet and render a stall between two ticks (PidEmulation.RecoilMatches...
// failed so under load). And while the test waits on a host call, the rig steps only when
// the host sent something or the device has commands in flight (else one tick per
// kIdleStep of wall time), so a test thread kept waiting does not burn the ticks the
// test's timeline allows for its set-up.
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "feel/peripheral/device_session.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/transport/transport.hpp"

namespace feel::host {

using transport::Frame;
using transport::FrameKind;
using namespace std::chrono_literals;

inline constexpr int64_t kTickUs = 1000;  // the profile's 1 kHz loop
inline constexpr auto kIdleStep = 5ms;    // background(): a tick this often when nothing waits

inline runtime::RuntimeConfig quiet_config(const sim::DeviceProfile& p, int32_t report_rate_hz) {
    runtime::RuntimeConfig c = runtime::runtime_config_for(p);
    c.safety.fade_in_us = 0;                 // forces at once
    c.safety.host_timeout_us = kInfiniteUs;  // a PID host sends no keep-alives
    c.report_rate_hz = report_rate_hz;
    return c;
}

// The device's pipeline with a kinematic hand following `motion`.
inline std::unique_ptr<runtime::RuntimePipeline> make_pipeline(const sim::DeviceProfile& p, const std::string& motion,
                                                        int32_t report_rate_hz) {
    auto backend = std::make_unique<runtime::SimBackend>(p, sim::Grip::kinematic,
                                                         sim::TargetMotion::parse(motion, 4.0, p.axis_count));
    return std::make_unique<runtime::RuntimePipeline>(quiet_config(p, report_rate_hz), std::move(backend));
}

// The lockstep device: its DeviceSession, and the host's end of the "cable".
class Lockstep {
public:
    Lockstep(const char* profile, const std::string& motion, int32_t report_rate_hz)
        : profile_(sim::find_device_profile(profile)),
          caps_(runtime::capabilities_for(*profile_)),
          pipeline_(make_pipeline(*profile_, motion, report_rate_hz)),
          link_(pipeline_->commands(), pipeline_->reports()),
          session_(caps_, pipeline_->config(), link_) {}
    ~Lockstep() { background(false); }

    class End : public transport::Connection {
    public:
        explicit End(Lockstep& rig) : rig_(rig) {}
        void send(const Frame& f) override {
            std::lock_guard lock(rig_.mu_);
            if (rig_.closed_) throw transport::TransportError(transport::TransportError::Kind::disconnected, "closed");
            rig_.inbox_.push_back(f);
            rig_.cv_.notify_all();  // a background() driver steps for it
        }
        std::optional<Frame> receive(std::chrono::milliseconds timeout) override {
            std::unique_lock lock(rig_.mu_);
            if (rig_.outbox_.empty() && timeout.count() > 0) {
                // Idle: everything handed over is handled and answered. Then the next tick's
                // frames, however long the test takes to step (no wall time; see above).
                rig_.host_idle_ = true;
                rig_.cv_.notify_all();
                rig_.cv_.wait(lock, [&] { return !rig_.outbox_.empty() || rig_.closed_; });
                rig_.host_idle_ = false;
            }
            if (rig_.closed_) throw transport::TransportError(transport::TransportError::Kind::disconnected, "closed");
            if (rig_.outbox_.empty()) return std::nullopt;
            Frame f = std::move(rig_.outbox_.front());
            rig_.outbox_.pop_front();
            return f;
        }
        void close() noexcept override {
            std::lock_guard lock(rig_.mu_);
            rig_.closed_ = true;
            rig_.cv_.notify_all();
        }
        [[nodiscard]] std::string peer() const override { return "lockstep"; }

    private:
        Lockstep& rig_;
    };

    std::unique_ptr<transport::Connection> host_end() { return std::make_unique<End>(*this); }
    int64_t now_us() const { return now_us_.load(); }

    // One tick: the host's frames to the session, the tick, the device's frames to the host,
    // then wait until the host has handled them (at most 2 s: a host that answers nothing
    // is not waited for longer).
    void step() {
        std::vector<Frame> in;
        {
            std::lock_guard lock(mu_);
            in.assign(inbox_.begin(), inbox_.end());
            inbox_.clear();
        }
        for (Frame& f : in) {
            if (!session_.offer(std::move(f))) ADD_FAILURE() << "the session's inbox is full";
        }
        std::vector<Frame> out;
        session_.pump(out);
        pipeline_->tick(tick_);
        now_us_ = tick_ * kTickUs;
        ++tick_;
        session_.pump(out);
        std::unique_lock lock(mu_);
        for (Frame& f : out) outbox_.push_back(std::move(f));
        if (!out.empty()) host_idle_ = false;  // idle again once back in receive(), all handled
        cv_.notify_all();
        cv_.wait_for(lock, 2s, [&] { return (outbox_.empty() && host_idle_) || closed_; });
    }

    // Steps on a thread of its own, while the test waits on a host call that needs answers:
    // at once for what the host sent and while the device has commands in flight, else once
    // per kIdleStep.
    void background(bool on) {
        if (on && !driver_.joinable()) {
            driving_ = true;
            driver_ = std::thread([this] {
                auto last = std::chrono::steady_clock::now();
                while (driving_) {
                    bool due = session_.in_flight() > 0 || std::chrono::steady_clock::now() - last >= kIdleStep;
                    if (!due) {
                        std::unique_lock lock(mu_);
                        due = cv_.wait_for(lock, 1ms, [&] { return !inbox_.empty() || !driving_; }) && driving_;
                    }
                    if (!due) continue;
                    step();
                    last = std::chrono::steady_clock::now();
                }
            });
        } else if (!on && driver_.joinable()) {
            driving_ = false;
            driver_.join();
        }
    }

    runtime::RuntimePipeline& pipeline() { return *pipeline_; }
    int64_t tick() const { return tick_; }

private:
    const sim::DeviceProfile* profile_;
    runtime::Capabilities caps_;
    std::unique_ptr<runtime::RuntimePipeline> pipeline_;
    runtime::HostLink link_;
    peripheral::DeviceSession session_;
    int64_t tick_ = 0;
    std::atomic<int64_t> now_us_{0};
    std::mutex mu_;
    std::condition_variable cv_;
    std::deque<Frame> inbox_, outbox_;
    bool host_idle_ = false;
    bool closed_ = false;
    std::atomic<bool> driving_{false};
    std::thread driver_;
};

}  // namespace feel::host
