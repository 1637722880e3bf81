// The simulated device as a peripheral: runtime, session and the service threads
// (peripheral.hpp).
//
// Threads. The runtime's loop thread ticks the pipeline. One service thread at a time
// serves the attached host: it is the session's only user and so the single producer and
// consumer of the runtime's queues. It reads the host's frames with a short timeout (1 ms,
// or none while commands are in flight, so that acks go back within a tick), pumps the
// session and sends what it produced. On a connection that rings a doorbell when a frame
// arrives (the in-process one: doorbell.hpp) it sleeps on that doorbell instead, which the
// loop rings too after a tick that left reports: a report then leaves as soon as it is
// posted, not when the 1 ms read times out (docs/studio.md, "Latency"). When the host leaves it resets the device through
// the session and waits (at most kResetWaitS) for the runtime to confirm, then ends; the
// next host gets a new service thread. An accept thread, when serving a listener, hands
// each connection to attach(), which answers `busy` while a host is attached.
//
// No host holds the device (docs/peripheral.md, "Guarantees to hosts"):
//   * a host that sends no frame for the runtime's watchdog time is detached (the runtime's
//     watchdog has faded its forces out by then; the reset frees its effects);
//   * the transport closes a connection whose partial frame stays partial, or whose host
//     does not read (transport.hpp); the service thread never blocks on a send;
//   * state reports (JoystickInput, DeviceStatus), which the next round supersedes, are
//     sent with send_or_drop and counted when dropped; answers are never dropped;
//   * a connection arriving while the last host's teardown runs waits for it instead of
//     being told `busy`, so hosts back to back are all served: kAdmitWait for the service
//     thread to see its host gone, then as long as the reset takes (at most kResetWait,
//     longer than kAdmitWait only on a machine too loaded to run the loop's ticks).
#include "feel/peripheral/peripheral.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/standard_pid.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/transport/doorbell.hpp"
#include "feel/transport/thread_priority.hpp"
#include "feel/sim/device_profile.hpp"
#include "standard_pid_connection.hpp"

namespace feel::peripheral {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

// How far a ramp target motion runs, s (TargetMotion::parse needs a span; a device runs
// without end, so the ramp reaches its end after this and holds it).
constexpr double kMotionSpanS = 60;
// How long a service thread waits for the runtime to confirm the reset after its host left.
constexpr auto kResetWait = 2s;
// The accept loop's poll period (stop() also closes the listener, which wakes it at once).
constexpr auto kAcceptPoll = 100ms;
// How long a new connection waits for the attached host's teardown before it gets `busy`:
// a host leaves, the service thread sees it within its 1 ms read, and the reset takes a few
// ticks; the next host should not be refused for arriving a few ms after the last left.
constexpr auto kAdmitWait = 250ms;

// Frames a host can do without: a state report is superseded by the next round's.
bool droppable(const transport::Frame& frame) {
    if (frame.kind != transport::FrameKind::input_report || frame.payload.empty()) return false;
    const auto id = static_cast<protocol::ReportId>(frame.payload[0]);
    return id == protocol::ReportId::joystick_input || id == protocol::ReportId::device_status ||
           id == protocol::ReportId::effect_states;
}

const sim::DeviceProfile& profile_named(const std::string& name) {
    if (const sim::DeviceProfile* p = sim::find_device_profile(name)) return *p;
    std::string names;
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        names += names.empty() ? "" : ", ";
        names += p.name;
    }
    throw std::invalid_argument("profile \"" + name + "\" is not a known device (available: " + names + ")");
}

sim::Grip grip_named(const std::string& name) {
    if (const auto g = sim::grip_from_name(name)) return *g;
    std::string names;
    for (sim::Grip g : {sim::Grip::none, sim::Grip::loose, sim::Grip::firm, sim::Grip::stiff, sim::Grip::kinematic}) {
        names += names.empty() ? "" : ", ";
        names += sim::grip_name(g);
    }
    throw std::invalid_argument("hand \"" + name + "\" is not a hand (allowed: " + names + ")");
}

runtime::RuntimeConfig config_for(const sim::DeviceProfile& profile, int32_t loop_rate_hz, bool host_watchdog) {
    runtime::RuntimeConfig config = runtime::runtime_config_for(profile);
    if (!host_watchdog) config.safety.host_timeout_us = kInfiniteUs;
    if (loop_rate_hz != 0) {
        const int32_t max = std::min(profile.max_loop_rate_hz, runtime::kMaxLoopRateHz);
        if (loop_rate_hz < runtime::kMinLoopRateHz || loop_rate_hz > max) {
            throw std::invalid_argument("loop rate = " + std::to_string(loop_rate_hz) +
                                        " Hz is out of range (allowed " + std::to_string(runtime::kMinLoopRateHz) +
                                        ".." + std::to_string(max) + " Hz on the " + std::string(profile.name) +
                                        ", or 0 for its default " + std::to_string(profile.default_loop_rate_hz) +
                                        " Hz)");
        }
        config.loop_rate_hz = loop_rate_hz;
    }
    // State reports can be no faster than the loop that makes them.
    config.report_rate_hz = std::min(config.report_rate_hz, config.loop_rate_hz);
    return config;
}

// The figures of the loop for DeviceStatus reports, with the tick rate measured over
// windows of about a second. DeviceRuntime::stats() computes the loop's percentiles too,
// so it is read at most every kStatsRefresh, not at each state report. Called by the
// service thread only.
class LoopMeter {
public:
    explicit LoopMeter(runtime::DeviceRuntime& rt) : runtime_(&rt) {}

    LoopFigures operator()() {
        const Clock::time_point now = Clock::now();
        if (started_ && now - read_at_ < kStatsRefresh) return figures_;
        read_at_ = now;
        const runtime::DeviceRuntimeStats s = runtime_->stats();
        figures_.loop_rate_hz = s.loop.rate_hz != 0 ? s.loop.rate_hz : runtime_->config().loop_rate_hz;
        figures_.overruns = s.loop.overruns;
        const int64_t ticks = s.pipeline.ticks;
        if (!started_) {
            started_ = true;
            window_start_ = now;
            window_ticks_ = ticks;
        } else if (now - window_start_ >= 1s) {
            const double seconds = std::chrono::duration<double>(now - window_start_).count();
            figures_.measured_rate_millihz = std::llround(static_cast<double>(ticks - window_ticks_) * 1000.0 / seconds);
            window_start_ = now;
            window_ticks_ = ticks;
        }
        return figures_;
    }

private:
    static constexpr auto kStatsRefresh = 100ms;
    runtime::DeviceRuntime* runtime_;
    bool started_ = false;
    Clock::time_point read_at_{};
    Clock::time_point window_start_{};
    int64_t window_ticks_ = 0;
    LoopFigures figures_{};
};

void refuse_busy(transport::Connection& connection) noexcept {
    try {
        connection.send(transport::Frame{transport::FrameKind::busy, {}});
    } catch (...) {
        // The second host left already: nothing to tell it.
    }
    connection.close();
}

}  // namespace

namespace {

// The profile as the device presents it: with pid_effects_only, a standard PID device's
// effect set and no local reflexes.
sim::DeviceProfile presented_profile(const PeripheralOptions& o) {
    sim::DeviceProfile p = profile_named(o.profile);
    if (o.pid_effects_only) {
        p.supported_types &= pid_effect_types();
        p.local_reflexes = false;
    }
    if (o.standard_pid_only) {
        p.supported_types &= protocol::standard_pid_effect_type_bits();
        p.local_reflexes = false;
    }
    return p;
}

}  // namespace

uint64_t pid_effect_types() noexcept {
    uint64_t bits = 0;
    for (const EffectType t : {EffectType::constant, EffectType::ramp, EffectType::sine, EffectType::square,
                               EffectType::triangle, EffectType::saw_up, EffectType::saw_down, EffectType::spring,
                               EffectType::damper, EffectType::inertia, EffectType::friction,
                               EffectType::force_profile}) {
        bits |= effect_type_bit(t);
    }
    return bits;
}

struct Peripheral::Impl {
    explicit Impl(const PeripheralOptions& o)
        : options(o),
          presented(presented_profile(o)),
          profile(&presented),
          caps(runtime::capabilities_for(*profile)),
          config(config_for(*profile, o.loop_rate_hz, o.host_watchdog)) {
        if (const std::string wrong = transport::check_fifo_priority("service_fifo_priority", o.service_fifo_priority);
            !wrong.empty()) {
            throw std::invalid_argument(wrong);
        }
        const sim::Grip grip = grip_named(o.hand);
        sim::TargetMotion motion = sim::TargetMotion::parse(o.motion, kMotionSpanS, profile->axis_count);
        auto backend = std::make_unique<runtime::SimBackend>(*profile, grip, std::move(motion));
        sim = backend.get();
        runtime::DeviceRuntimeOptions runtime_options = o.runtime;
        runtime_options.report_signal = &reports_ready;
        rt = std::make_unique<runtime::DeviceRuntime>(config, std::move(backend), runtime_options);
        session = std::make_unique<DeviceSession>(caps, rt->config(), *rt, LoopMeter(*rt));
        rt->start();
    }

    PeripheralOptions options;
    sim::DeviceProfile presented;  // the profile, as pid_effects_only presents it
    const sim::DeviceProfile* profile;
    runtime::Capabilities caps;
    runtime::RuntimeConfig config;
    // The service thread sleeps on it; the loop and an in-process host's frames ring it.
    // Declared before rt: the loop that rings it stops first.
    std::shared_ptr<transport::Doorbell> bell = std::make_shared<transport::Doorbell>();
    struct RingOnReports final : runtime::ReportSignal {
        explicit RingOnReports(transport::Doorbell* b) : bell(b) {}
        void reports_ready() noexcept override { bell->ring(); }
        transport::Doorbell* bell;
    } reports_ready{bell.get()};
    runtime::SimBackend* sim = nullptr;  // owned by rt
    std::unique_ptr<runtime::DeviceRuntime> rt;
    std::unique_ptr<DeviceSession> session;  // the service thread's alone while one runs

    std::mutex mutex;  // guards the threads, `current`, `listener` and `address`
    std::thread service;
    std::thread acceptor;
    transport::Connection* current = nullptr;  // the attached host's connection (service thread owns it)
    std::unique_ptr<transport::Listener> listener;
    std::optional<transport::Address> listen_address;
    std::atomic<bool> stopping{false};
    std::atomic<bool> attached{false};

    std::atomic<uint64_t> hosts_served{0};
    std::atomic<uint64_t> reports_received{0};
    std::atomic<uint64_t> reports_refused{0};
    std::atomic<uint64_t> frames_sent{0};
    std::atomic<uint64_t> reports_dropped{0};
    std::atomic<uint64_t> hosts_silent{0};
    std::atomic<uint64_t> hosts_dropped{0};
    std::condition_variable detached;  // a service thread finished its teardown (with mutex)

    void publish(const SessionCounters& c) {
        reports_received.store(c.reports_decoded, std::memory_order_relaxed);
        reports_refused.store(c.reports_refused, std::memory_order_relaxed);
        frames_sent.store(c.frames_sent, std::memory_order_relaxed);
    }

    void attach(std::unique_ptr<transport::Connection> host) {
        std::unique_lock lock(mutex);
        // A host arriving while the last one's teardown runs waits for it to end: kAdmitWait
        // for its service thread to see it gone, then the reset, however long the load makes
        // it (`current` is cleared when the teardown begins).
        const auto admitted = [&] { return stopping.load() || !attached.load(); };
        detached.wait_for(lock, kAdmitWait, admitted);
        if (!admitted() && current == nullptr) detached.wait_for(lock, kResetWait + kAdmitWait, admitted);
        if (stopping.load() || attached.load()) {
            lock.unlock();
            refuse_busy(*host);
            return;
        }
        if (service.joinable()) service.join();  // the last host's thread, done or finishing its reset
        attached.store(true);
        hosts_served.fetch_add(1, std::memory_order_relaxed);
        current = host.get();
        service = std::thread([this, h = std::move(host)]() mutable { serve_host(std::move(h)); });
    }

    void serve_host(std::unique_ptr<transport::Connection> host) {
        (void)transport::raise_thread_priority(options.service_fifo_priority);  // where the process may
        std::vector<transport::Frame> out;
        session->pump(out);  // what piled up while no host listened is not this host's
        out.clear();
        const int64_t timeout_us = rt->config().safety.host_timeout_us;
        const bool watchdog = timeout_us != kInfiniteUs;
        const auto silence_limit = std::chrono::microseconds(watchdog ? timeout_us : 0);
        Clock::time_point heard = Clock::now();
        // A connection that rings the doorbell on arrival: read without waiting, sleep on
        // the doorbell (a frame or a report wakes it; 1 ms at most, for the watchdog).
        auto* rings = dynamic_cast<transport::BellOnArrival*>(host.get());
        if (rings != nullptr) rings->ring_on_arrival(bell);
        try {
            while (!stopping.load(std::memory_order_relaxed)) {
                const uint32_t seen = bell->rings();  // before looking: a later ring wakes the wait
                const bool busy = session->in_flight() > 0;
                bool received = false;
                if (session->accepting()) {
                    if (auto frame = host->receive(busy || rings != nullptr ? 0ms : 1ms)) {
                        session->offer(std::move(*frame));
                        received = true;
                        heard = Clock::now();
                    }
                }
                if (watchdog && !received && session->accepting() && Clock::now() - heard > silence_limit) {
                    hosts_silent.fetch_add(1, std::memory_order_relaxed);
                    break;  // silent past the watchdog: the host is lost, detach it
                }
                session->pump(out);
                for (const transport::Frame& f : out) {
                    if (droppable(f)) {
                        if (!host->send_or_drop(f)) reports_dropped.fetch_add(1, std::memory_order_relaxed);
                    } else {
                        host->send(f);
                    }
                }
                out.clear();
                publish(session->counters());
                // Waiting on the runtime with nothing read (or no room to read): a short
                // nap, not a spin; on the doorbell, until the loop posts (acks are reports
                // too) or a frame comes.
                if (!received && rings != nullptr && session->accepting()) {
                    bell->wait(seen, 1ms);
                } else if (!received && (busy || !session->accepting())) {
                    std::this_thread::sleep_for(50us);
                }
            }
        } catch (const transport::TransportError& e) {
            // Disconnected, or a bad frame, a stalled partial frame or a host that does not
            // read (the transport closed it): the host is gone.
            if (e.kind() != transport::TransportError::Kind::disconnected ||
                std::string_view(e.what()).find("does not read") != std::string_view::npos)
                hosts_dropped.fetch_add(1, std::memory_order_relaxed);
        } catch (const std::exception&) {
            // A frame the session could not answer (an encode bug): drop this host rather
            // than the device; the reset below still runs.
        }
        {
            std::lock_guard lock(mutex);
            current = nullptr;
        }
        if (rings != nullptr) rings->ring_on_arrival(nullptr);
        host->close();
        host.reset();
        session->host_gone();
        const Clock::time_point deadline = Clock::now() + kResetWait;
        while (!session->idle() && Clock::now() < deadline) {
            session->pump(out);
            out.clear();
            std::this_thread::sleep_for(200us);
        }
        publish(session->counters());
        {
            std::lock_guard lock(mutex);
            attached.store(false);
        }
        detached.notify_all();
    }

    void serve(std::unique_ptr<transport::Listener> l) {
        std::lock_guard lock(mutex);
        if (acceptor.joinable()) throw std::logic_error("Peripheral::serve: already serving " + listen_address->to_string());
        listen_address = l->address();
        listener = std::move(l);
        acceptor = std::thread([this] { accept_loop(); });
    }

    void accept_loop() {
        while (!stopping.load()) {
            std::unique_ptr<transport::Connection> c;
            try {
                c = listener->accept(kAcceptPoll);
            } catch (const transport::TransportError&) {
                return;  // closed
            }
            if (c) attach(std::move(c));
        }
    }

    void stop() {
        {
            std::lock_guard lock(mutex);
            stopping.store(true);
            if (listener) listener->close();
            if (current != nullptr) current->close();
        }
        detached.notify_all();
        if (acceptor.joinable()) acceptor.join();
        if (service.joinable()) service.join();
        {
            std::lock_guard lock(mutex);
            listener.reset();
        }
        stopping.store(false);
    }
};

Peripheral::Peripheral(const PeripheralOptions& options) : impl_(std::make_unique<Impl>(options)) {}

Peripheral::~Peripheral() {
    impl_->stop();
    impl_->rt->stop();
}

void Peripheral::attach(std::unique_ptr<transport::Connection> host, HostReports form) {
    if (!host) throw std::invalid_argument("Peripheral::attach: no connection");
    if (impl_->options.standard_pid_only && form == HostReports::presented) {
        host = std::make_unique<StandardPidConnection>(std::move(host), joystick_layout(impl_->caps));
    }
    impl_->attach(std::move(host));
}

bool Peripheral::standard_pid_only() const noexcept { return impl_->options.standard_pid_only; }

void Peripheral::serve(std::unique_ptr<transport::Listener> listener) {
    if (!listener) throw std::invalid_argument("Peripheral::serve: no listener");
    impl_->serve(std::move(listener));
}

void Peripheral::stop() { impl_->stop(); }

bool Peripheral::host_attached() const noexcept { return impl_->attached.load(); }

const runtime::Capabilities& Peripheral::capabilities() const noexcept { return impl_->caps; }

PeripheralStats Peripheral::stats() const noexcept {
    PeripheralStats s;
    s.runtime = impl_->rt->stats();
    s.hosts_served = impl_->hosts_served.load(std::memory_order_relaxed);
    s.reports_received = impl_->reports_received.load(std::memory_order_relaxed);
    s.reports_refused = impl_->reports_refused.load(std::memory_order_relaxed);
    s.frames_sent = impl_->frames_sent.load(std::memory_order_relaxed);
    s.reports_dropped = impl_->reports_dropped.load(std::memory_order_relaxed);
    s.hosts_silent = impl_->hosts_silent.load(std::memory_order_relaxed);
    s.hosts_dropped = impl_->hosts_dropped.load(std::memory_order_relaxed);
    s.host_attached = impl_->attached.load();
    return s;
}

transport::Address Peripheral::address() const {
    std::lock_guard lock(impl_->mutex);
    if (!impl_->listen_address) throw std::logic_error("Peripheral::address: the device serves no listener");
    return *impl_->listen_address;
}

runtime::DeviceRuntime& Peripheral::runtime() noexcept { return *impl_->rt; }

bool Peripheral::set_buttons(uint32_t pressed) noexcept { return impl_->sim->set_buttons(pressed); }
bool Peripheral::set_hand_target(int32_t x, int32_t y, int32_t z) noexcept {
    return impl_->sim->set_hand_target(x, y, z);
}
int64_t Peripheral::hand_target_taken_us() const noexcept { return impl_->sim->hand_target_taken_us(); }
void Peripheral::set_grip(sim::Grip grip) noexcept { impl_->sim->set_grip(grip); }

bool Peripheral::set_hats(uint32_t pushed) noexcept { return impl_->sim->set_hats(pushed); }

namespace {

// The host's end of an in-process device, owning the device: closing it detaches the host
// (the device resets), destroying it also stops the device.
class InProcessDevice final : public transport::Connection {
public:
    InProcessDevice(std::unique_ptr<Peripheral> device, std::unique_ptr<transport::Connection> host)
        : device_(std::move(device)), host_(std::move(host)) {}
    ~InProcessDevice() override {
        host_->close();
        device_.reset();
    }
    InProcessDevice(const InProcessDevice&) = delete;
    InProcessDevice& operator=(const InProcessDevice&) = delete;

    void send(const transport::Frame& frame) override { host_->send(frame); }
    std::optional<transport::Frame> receive(std::chrono::milliseconds timeout) override {
        return host_->receive(timeout);
    }
    void close() noexcept override { host_->close(); }
    [[nodiscard]] std::string peer() const override { return host_->peer(); }

private:
    std::unique_ptr<Peripheral> device_;
    std::unique_ptr<transport::Connection> host_;
};

}  // namespace

std::unique_ptr<transport::Connection> open_in_process(const PeripheralOptions& options) {
    auto device = std::make_unique<Peripheral>(options);
    transport::ConnectionPair pair = transport::in_process_pair("sim:" + options.profile);
    device->attach(std::move(pair.device));
    return std::make_unique<InProcessDevice>(std::move(device), std::move(pair.host));
}

}  // namespace feel::peripheral
