// FunctionFsServer: feel's HID PID function served in userspace through FunctionFS.
//
// Design. One I/O thread owns the three FunctionFS files: ep0 (events and control
// transfers), ep1 (interrupt IN) and ep2 (interrupt OUT). The endpoints use Linux AIO
// (libaio) with an eventfd, so that one poll() sees ep0's events and the endpoints'
// completions together; there is no thread per endpoint.
//
// Order. A host sends feature reports on ep0 and output reports on the interrupt OUT
// endpoint, and the two paths are independent: the device session keys everything on the
// block index each report carries, never on arrival order. One order does matter: when the
// host waits for an OUT transfer to finish before it starts a control transfer (hid-pidff
// resets the device with output reports, waits, then asks for PID Pool), the OUT report
// must reach the session first. So each round reads ep0's events first, then collects the
// endpoint completions, and hands the session the completions before the events: every OUT
// transfer that finished before a SETUP was read is ahead of it.
//
// Host sessions. ENABLE (the host configured the device) opens a connection to the
// Peripheral; DISABLE, UNBIND or the server stopping closes it, and the Peripheral resets
// the device (every effect stopped and freed) as it does for a lost host. The connection is
// a transport::Connection, so the USB host is served by the same DeviceSession as a host on
// a socket.
//
// Control transfers. A GET_REPORT(Feature) becomes a get_feature frame; the reply comes back
// through the connection's send() as a feature_reply and is written to ep0, cut at wLength
// (usbhid rounds wLength up to 64; the reply starts with the report id). While the reply is
// pending ep0 is left alone (FunctionFS keeps the request open). A reply that does not come
// within kReplyTimeout, or a get the session refuses (its error status names get_feature),
// stalls the request. SET_REPORT's data stage is read at once and becomes an output_report
// or set_feature frame; its error, if any, travels as the session's CommandStatus on the
// interrupt IN endpoint, as for any report. Requests the function does not serve are
// stalled: FunctionFS stalls when the data stage is done in the wrong direction.
//
// Bounded. The host's frames wait in a queue of at most kInboundFrames (beyond that the I/O
// thread stops reading the OUT endpoint until the Peripheral catches up, which pushes back
// on the host through USB flow control); input reports wait in at most kInputQueue, the
// oldest dropped and counted when the host does not read them (a HID host reads its
// interrupt IN endpoint only while someone has the device open); the periodic state
// reports keep only their latest, so that they never crowd out an answer.
//
// Never blocked. The I/O thread must come back to its loop whatever the host does, or
// stop() never returns (`feel device` hung once on SIGTERM in the VM after the flood
// probe). FunctionFS's AIO submission is not always asynchronous: io_submit() on an
// endpoint that is not enabled (the host disabled the function, or the gadget was just
// unbound, and the DISABLE event is not read yet) waits inside the kernel until the
// endpoint is enabled again, unless the file is O_NONBLOCK (f_fs.c, ffs_epfile_io). So the
// endpoints are opened O_NONBLOCK: such a submission completes at once with EAGAIN, and
// that endpoint is left alone for kEndpointRetry (a couple of ticks: no spin until the
// DISABLE event is read, and no gap worth a report should the kernel answer EAGAIN for
// another reason; the log counts those answered while enabled), or until the host
// configures the device again. A transfer the host never takes (an IN report nobody reads, an OUT read while the
// host sends nothing) stays in flight without blocking anyone; io_destroy() cancels it.
// ep0's data stages block until the host's controller runs them, which it does at once,
// and unbinding the gadget ends them; the wait for the last host's reset is cut short by
// stop().
#include <fcntl.h>
#include <libaio.h>
#include <linux/usb/functionfs.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "feel/peripheral/device_session.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"
#include "feel/protocol/report_text.hpp"
#include "feel/protocol/standard_pid.hpp"
#include "feel/usb/usb_device.hpp"
#include "ffs_descriptors.hpp"
#include "hid_requests.hpp"
#include "pid_commit_order.hpp"
#include "report_assembler.hpp"

namespace feel::usb {
namespace {

using namespace std::chrono_literals;
using transport::Frame;
using transport::FrameKind;

constexpr std::size_t kInboundFrames = 64;
constexpr std::size_t kInputQueue = 256;  // answers and events; the session has at most 256 in flight
constexpr auto kReplyTimeout = 1000ms;
constexpr auto kHostHandover = 3000ms;  // how long a new host waits for the last one's reset
constexpr auto kEndpointRetry = 2ms;    // an endpoint that answered EAGAIN (not enabled) rests this long
constexpr std::size_t kBufferBytes = 4096;

std::string errno_text(int e) { return std::strerror(e); }

double monotonic_s() {
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

void write_all(int fd, const std::vector<uint8_t>& bytes, const std::string& what) {
    const ssize_t n = ::write(fd, bytes.data(), bytes.size());
    if (n != static_cast<ssize_t>(bytes.size())) {
        throw std::runtime_error("FunctionFS refused the " + what + ": " + errno_text(errno));
    }
}

// A line of the device log, with the monotonic time the VM's judges also read.
class ReportLog {
public:
    explicit ReportLog(std::ostream* out) : out_(out) {}
    void line(const std::string& text) {
        if (out_ == nullptr) return;
        std::lock_guard lock(mutex_);
        char stamp[32];
        std::snprintf(stamp, sizeof stamp, "%.6f ", monotonic_s());
        *out_ << stamp << text << '\n' << std::flush;
    }
    [[nodiscard]] bool enabled() const noexcept { return out_ != nullptr; }

private:
    std::ostream* out_;
    std::mutex mutex_;
};

// What the I/O thread and the Peripheral's service thread share for one host session.
struct Channel {
    std::mutex mutex;
    std::condition_variable arrived;
    std::deque<Frame> inbound;            // host -> device frames, in order
    bool closed = false;
    // Device -> host, interrupt IN. Answers and events (CommandStatus, PID State, dynamics'
    // reports) wait in order; the periodic state (Joystick Input, each Device Status page)
    // keeps only its latest report, which supersedes the ones the host did not read yet.
    std::deque<std::vector<uint8_t>> input_events;
    std::map<uint16_t, std::vector<uint8_t>> input_state;  // (report id << 8) | page -> latest
    std::optional<std::vector<uint8_t>> reply;       // device -> host, ep0 data stage
    bool reply_refused = false;                      // the session refused the pending get
    bool reply_pending = false;
    uint64_t input_dropped = 0;
    int wake_fd = -1;                     // the I/O thread's eventfd
    ReportLog* log = nullptr;
    // The device presents itself as a plain PID device (Peripheral::standard_pid_only):
    // what goes to the host is translated to the standard form, vendor reports kept back.
    bool standard_pid = false;

    void wake() const noexcept {
        const uint64_t one = 1;
        [[maybe_unused]] const ssize_t n = ::write(wake_fd, &one, sizeof one);
    }
};

// The Peripheral's end of a USB host session.
class UsbHostConnection final : public transport::Connection {
public:
    UsbHostConnection(std::shared_ptr<Channel> channel, std::string peer)
        : channel_(std::move(channel)), peer_(std::move(peer)) {}
    ~UsbHostConnection() override { close(); }

    void send(const Frame& frame) override {
        std::unique_lock lock(channel_->mutex);
        if (channel_->closed) throw transport::TransportError(transport::TransportError::Kind::disconnected, peer_ + " is gone");
        switch (frame.kind) {
            case FrameKind::input_report: {
                note_refusal(frame.payload);
                note_status(frame.payload);
                std::vector<uint8_t> bytes = frame.payload;
                if (channel_->standard_pid && !protocol::feel_to_standard_pid(frame.payload, bytes)) break;  // vendor
                if (const std::optional<uint16_t> key = state_key(bytes)) {
                    auto [it, fresh] = channel_->input_state.try_emplace(*key, bytes);
                    if (!fresh) {
                        it->second = std::move(bytes);  // the unread one is superseded
                        ++channel_->input_dropped;
                    }
                    break;
                }
                if (channel_->input_events.size() >= kInputQueue) {
                    channel_->input_events.pop_front();
                    ++channel_->input_dropped;
                }
                channel_->input_events.push_back(std::move(bytes));
                break;
            }
            case FrameKind::feature_reply: {
                if (channel_->log != nullptr) {
                    protocol::AnyReport report;
                    if (!protocol::decode(frame.payload, report)) {
                        channel_->log->line("feature_reply " + protocol::describe_report(report));
                    }
                }
                std::vector<uint8_t> bytes = frame.payload;
                if (channel_->standard_pid && !protocol::feel_to_standard_pid(frame.payload, bytes)) {
                    channel_->reply_refused = channel_->reply_pending;  // no standard form: stall the request
                    break;
                }
                if (channel_->reply_pending) channel_->reply = std::move(bytes);
                break;
            }
            case FrameKind::descriptor_reply:
                if (channel_->reply_pending) channel_->reply = frame.payload;
                break;
            default: break;  // busy: the Peripheral closes this connection next
        }
        lock.unlock();
        channel_->wake();
    }

    std::optional<Frame> receive(std::chrono::milliseconds timeout) override {
        std::unique_lock lock(channel_->mutex);
        channel_->arrived.wait_for(lock, timeout, [&] { return channel_->closed || !channel_->inbound.empty(); });
        if (!channel_->inbound.empty()) {
            Frame f = std::move(channel_->inbound.front());
            channel_->inbound.pop_front();
            lock.unlock();
            channel_->wake();  // room again: the I/O thread may read OUT again
            return f;
        }
        if (channel_->closed) throw transport::TransportError(transport::TransportError::Kind::disconnected, peer_ + " is gone");
        return std::nullopt;
    }

    void close() noexcept override {
        {
            std::lock_guard lock(channel_->mutex);
            channel_->closed = true;
        }
        channel_->arrived.notify_all();
    }

    [[nodiscard]] std::string peer() const override { return peer_; }

private:
    // A CommandStatus with an error, joined with the Command Error Text before it: logged
    // with its field and rule; one naming get_feature / get_descriptor refuses the control
    // transfer waiting for its reply (called with the mutex held).
    void note_refusal(const std::vector<uint8_t>& bytes) {
        protocol::AnyReport report;
        if (protocol::decode(bytes, report)) return;
        if (const auto* text = std::get_if<protocol::CommandErrorTextReport>(&report)) {
            error_text_.add(*text);
            return;
        }
        const auto* status = std::get_if<protocol::CommandStatusReport>(&report);
        if (status == nullptr || status->code == ErrorCode::ok) return;
        const protocol::CommandAnswer answer = error_text_.finish(*status);
        const std::string field(answer.field_text());
        if (channel_->log != nullptr) {
            channel_->log->line("refused " + protocol::describe_report(report) + " field=\"" + field + "\" rule=\"" +
                                std::string(answer.rule_text()) + "\"");
        }
        if (channel_->reply_pending && (field.rfind("get_feature", 0) == 0 || field.rfind("get_descriptor", 0) == 0)) {
            channel_->reply_refused = true;
        }
    }

    // The periodic state reports' slot: Joystick Input, Device Status, and Effect States
    // per page.
    static std::optional<uint16_t> state_key(const std::vector<uint8_t>& bytes) {
        if (bytes.empty()) return std::nullopt;
        const uint8_t id = bytes[0];
        if (id == static_cast<uint8_t>(protocol::ReportId::joystick_input) ||
            id == static_cast<uint8_t>(protocol::ReportId::device_status)) {
            return static_cast<uint16_t>(id << 8);
        }
        if (id != static_cast<uint8_t>(protocol::ReportId::effect_states)) return std::nullopt;
        protocol::AnyReport report;
        if (protocol::decode(bytes, report)) return std::nullopt;
        return static_cast<uint16_t>((id << 8) | std::get<protocol::EffectStatesReport>(report).page);
    }

    // DeviceStatus: the log gets a "motor" line when the motors' force goes from
    // zero to non-zero or back (the latency measurement's end point, docs/usb-device.md) and
    // a "loop" line each second with the loop's measured rate and overruns.
    void note_status(const std::vector<uint8_t>& bytes) {
        if (channel_->log == nullptr || bytes.empty() ||
            bytes[0] != static_cast<uint8_t>(protocol::ReportId::device_status)) {
            return;
        }
        protocol::AnyReport report;
        if (protocol::decode(bytes, report)) return;
        const auto& status = std::get<protocol::DeviceStatusReport>(report);
        if (channel_->standard_pid) {
            // A plain PID device tells its host nothing of its forces: the log keeps each
            // state report's, for the VM's host emulation case (tests/linux).
            channel_->log->line("state t_us=" + std::to_string(status.t_us) + " force[0]=" +
                                std::to_string(status.force[0]) + " force[1]=" + std::to_string(status.force[1]));
        }
        bool pushing = false;
        for (const int16_t f : status.force) pushing = pushing || f != 0;
        if (pushing != pushing_) {
            pushing_ = pushing;
            std::string line = "motor t_us=" + std::to_string(status.t_us);
            for (std::size_t i = 0; i < std::size(status.force); ++i) {
                line += " force[" + std::to_string(i) + "]=" + std::to_string(status.force[i]);
            }
            channel_->log->line(line);
        }
        if (status.t_us >= next_loop_line_us_) {
            next_loop_line_us_ = status.t_us + 1'000'000;
            channel_->log->line("loop t_us=" + std::to_string(status.t_us) + " rate_hz=" +
                                std::to_string(status.loop_rate_hz) +
                                " measured_millihz=" + std::to_string(status.measured_rate_millihz) +
                                " overruns=" + std::to_string(status.overruns));
        }
    }

    std::shared_ptr<Channel> channel_;
    std::string peer_;
    bool pushing_ = false;
    uint64_t next_loop_line_us_ = 0;
    protocol::CommandAnswerJoiner error_text_;  // guarded by the channel's mutex, as note_refusal
};

}  // namespace

struct FunctionFsServer::Impl {
    peripheral::Peripheral& device;
    std::string dir;
    ReportLog log;
    std::vector<uint8_t> report_descriptor;

    int ep0 = -1, ep_in = -1, ep_out = -1;
    int aio_fd = -1, wake_fd = -1;
    io_context_t aio{};
    std::thread thread;
    std::atomic<bool> stopping{false};

    // I/O thread state.
    bool enabled = false;
    std::shared_ptr<Channel> channel;
    iocb out_cb{}, in_cb{};
    bool out_busy = false, in_busy = false;
    // An endpoint that answered EAGAIN is not enabled: not tried again before this time.
    std::chrono::steady_clock::time_point out_rest_until{}, in_rest_until{};
    uint64_t eagain_while_enabled = 0;  // this host session's, logged when it ends
    uint16_t last_state_key = 0;  // the state slot sent last (round robin)
    alignas(64) uint8_t out_buf[kBufferBytes]{};
    alignas(64) uint8_t in_buf[kBufferBytes]{};
    detail::ReportAssembler assembler{detail::kFullSpeedPacketBytes};
    detail::PidCommitOrder commit_order;  // hid-pidff's Set Effect first, put into feel's order
    std::size_t out_packet = detail::kFullSpeedPacketBytes;
    // The control transfer waiting for the session's reply.
    struct PendingGet {
        detail::ControlAction action;
        std::chrono::steady_clock::time_point deadline;
    };
    std::optional<PendingGet> pending;

    std::atomic<uint64_t> hosts{0}, setups{0}, stalled{0}, output_reports{0}, input_reports{0}, input_dropped{0};
    std::atomic<bool> configured{false};

    Impl(peripheral::Peripheral& d, std::string directory, std::ostream* log_out)
        : device(d), dir(std::move(directory)), log(log_out) {
        // The device's own descriptor (its profile's axes, buttons and hats), the same bytes
        // its session answers get_descriptor with.
        // A plain PID device's has PID's reports alone (protocol/standard_pid.hpp).
        const protocol::JoystickLayout layout = peripheral::joystick_layout(device.capabilities());
        report_descriptor = device.standard_pid_only() ? protocol::standard_pid_descriptor(layout)
                                                       : protocol::report_descriptor(layout);
    }

    int open_file(const std::string& name, int flags) const {
        const std::string path = dir + "/" + name;
        const int fd = ::open(path.c_str(), flags);
        if (fd < 0) throw std::runtime_error("cannot open " + path + ": " + errno_text(errno) +
                                             " (is a FunctionFS instance mounted at " + dir + "?)");
        return fd;
    }

    void open_function(const FunctionOptions& options) {
        ep0 = open_file("ep0", O_RDWR);
        write_all(ep0, detail::function_descriptors(report_descriptor.size()), "descriptors written to " + dir + "/ep0");
        write_all(ep0, detail::function_strings(options.interface_name), "strings written to " + dir + "/ep0");
        // O_NONBLOCK: a submission to an endpoint that is not enabled must not wait for it
        // (the design note, "Never blocked").
        ep_in = open_file("ep1", O_RDWR | O_NONBLOCK);
        ep_out = open_file("ep2", O_RDWR | O_NONBLOCK);
        aio_fd = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
        wake_fd = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
        if (aio_fd < 0 || wake_fd < 0) throw std::runtime_error("eventfd: " + errno_text(errno));
        if (const int r = io_setup(8, &aio); r < 0) throw std::runtime_error("io_setup: " + errno_text(-r));
    }

    void close_all() noexcept {
        if (aio != io_context_t{}) {
            io_destroy(aio);  // cancels what is in flight and waits for it
            aio = {};
        }
        for (int* fd : {&ep_out, &ep_in, &ep0, &aio_fd, &wake_fd}) {
            if (*fd >= 0) ::close(*fd);
            *fd = -1;
        }
    }

    // --- host sessions -----------------------------------------------------------------
    void host_arrived() {
        host_gone();
        // The packet size of this connection's speed, from the endpoint's active descriptor.
        usb_endpoint_descriptor desc{};
        if (::ioctl(ep_out, FUNCTIONFS_ENDPOINT_DESC, &desc) == 0 && desc.wMaxPacketSize > 0) {
            out_packet = std::min<std::size_t>(desc.wMaxPacketSize & 0x7FF, kBufferBytes);
        }
        assembler.set_packet_bytes(out_packet);
        assembler.reset();
        enabled = true;
        configured = true;
        out_rest_until = in_rest_until = {};
        ++hosts;
        // The last host's reset must finish before the Peripheral takes a new one.
        const auto until = std::chrono::steady_clock::now() + kHostHandover;
        while (device.host_attached() && std::chrono::steady_clock::now() < until &&
               !stopping.load(std::memory_order_relaxed)) {
            std::this_thread::sleep_for(5ms);
        }
        channel = std::make_shared<Channel>();
        channel->wake_fd = wake_fd;
        channel->log = log.enabled() ? &log : nullptr;
        channel->standard_pid = device.standard_pid_only();
        log.line("host configured the device (max packet " + std::to_string(out_packet) + " bytes)");
        // The translation to and from the standard form is done here, at the endpoints, so
        // that the log and the commit order see feel's reports.
        device.attach(std::make_unique<UsbHostConnection>(channel, "usb:" + dir), peripheral::HostReports::feel_form);
    }

    void host_gone() {
        enabled = false;
        configured = false;
        if (pending) pending.reset();
        if (channel) {
            {
                std::lock_guard lock(channel->mutex);
                channel->closed = true;
            }
            channel->arrived.notify_all();
            channel.reset();
            log.line("host gone (" + std::to_string(eagain_while_enabled) +
                     " endpoint transfers answered EAGAIN while the device was configured)");
            eagain_while_enabled = 0;
        }
        assembler.reset();
        commit_order.reset();
    }

    // --- endpoints ---------------------------------------------------------------------
    bool inbound_has_room() {
        if (!channel) return false;
        std::lock_guard lock(channel->mutex);
        return channel->inbound.size() < kInboundFrames;
    }

    void submit_out() {
        if (!enabled || out_busy || std::chrono::steady_clock::now() < out_rest_until || !inbound_has_room()) return;
        io_prep_pread(&out_cb, ep_out, out_buf, out_packet, 0);
        io_set_eventfd(&out_cb, aio_fd);
        iocb* list[1] = {&out_cb};
        if (io_submit(aio, 1, list) == 1) out_busy = true;
    }

    void submit_in() {
        if (!enabled || in_busy || !channel || std::chrono::steady_clock::now() < in_rest_until) return;
        std::vector<uint8_t> next;
        {
            // Answers and events first; then the state slot least recently sent.
            std::lock_guard lock(channel->mutex);
            if (!channel->input_events.empty()) {
                next = std::move(channel->input_events.front());
                channel->input_events.pop_front();
            } else if (!channel->input_state.empty()) {
                auto it = channel->input_state.upper_bound(last_state_key);
                if (it == channel->input_state.end()) it = channel->input_state.begin();
                last_state_key = it->first;
                next = std::move(it->second);
                channel->input_state.erase(it);
            } else {
                return;
            }
        }
        const std::size_t n = std::min(next.size(), kBufferBytes);
        std::memcpy(in_buf, next.data(), n);
        io_prep_pwrite(&in_cb, ep_in, in_buf, n, 0);
        io_set_eventfd(&in_cb, aio_fd);
        iocb* list[1] = {&in_cb};
        if (io_submit(aio, 1, list) == 1) in_busy = true;
    }

    void push_frame(Frame frame) {
        if (!channel) return;
        if (channel->standard_pid && (frame.kind == FrameKind::output_report || frame.kind == FrameKind::set_feature)) {
            // A plain PID device's report, in feel's form for the session (vendor fields 0).
            std::vector<uint8_t> feel;
            if (const Error e = protocol::standard_pid_to_feel(frame.payload, feel)) {
                log.line(std::string(transport::frame_kind_name(frame.kind)) + " refused (not a report of this " +
                         "standard PID device): " + e.message());
                return;
            }
            frame.payload = std::move(feel);
        }
        if (log.enabled()) {
            protocol::AnyReport report;
            if (!frame.payload.empty() && !protocol::decode(frame.payload, report)) {
                log.line(std::string(transport::frame_kind_name(frame.kind)) + " " + protocol::describe_report(report));
            } else if (frame.kind != FrameKind::get_feature && frame.kind != FrameKind::get_descriptor) {
                log.line(std::string(transport::frame_kind_name(frame.kind)) + " undecodable, " +
                         std::to_string(frame.payload.size()) + " bytes, id " +
                         std::to_string(frame.payload.empty() ? 0 : frame.payload[0]));
            } else if (frame.kind == FrameKind::get_feature) {
                log.line("get_feature id " + std::to_string(frame.payload.empty() ? 0 : frame.payload[0]) + " " +
                         std::string(protocol::report_name(static_cast<protocol::ReportId>(frame.payload[0]))));
            }
        }
        enqueue(commit_order.on_frame(std::move(frame), std::chrono::steady_clock::now()));
    }

    void enqueue(std::vector<Frame> frames) {
        if (frames.empty() || !channel) return;
        {
            std::lock_guard lock(channel->mutex);
            for (Frame& f : frames) channel->inbound.push_back(std::move(f));
        }
        channel->arrived.notify_one();
    }

    // An endpoint that answered EAGAIN: not enabled (or, if the device is configured, busy).
    void rest(std::chrono::steady_clock::time_point& until) {
        until = std::chrono::steady_clock::now() + kEndpointRetry;
        if (enabled) ++eagain_while_enabled;
    }

    // Completed endpoint I/O, without waiting.
    void collect_completions() {
        uint64_t count = 0;
        [[maybe_unused]] const ssize_t n = ::read(aio_fd, &count, sizeof count);
        io_event events[4];
        timespec zero{};
        for (;;) {
            const int got = io_getevents(aio, 0, 4, events, &zero);
            if (got <= 0) break;
            for (int i = 0; i < got; ++i) {
                const auto result = static_cast<long>(events[i].res);
                if (events[i].obj == &out_cb) {
                    out_busy = false;
                    if (result == -EAGAIN) rest(out_rest_until);
                    if (result < 0 || !enabled) continue;  // disabled, or the host reset the endpoint
                    if (assembler.add({out_buf, static_cast<std::size_t>(result)})) {
                        ++output_reports;
                        push_frame(Frame{FrameKind::output_report, assembler.take()});
                    }
                } else if (events[i].obj == &in_cb) {
                    in_busy = false;
                    if (result == -EAGAIN) rest(in_rest_until);
                    if (result >= 0) ++input_reports;
                }
            }
        }
    }

    // --- ep0 ---------------------------------------------------------------------------
    void stall(const detail::ControlAction& action) {
        ++stalled;
        log.line("stall " + action.reason);
        // FunctionFS stalls a request whose data stage goes the wrong way.
        uint8_t none = 0;
        if (action.device_to_host) {
            [[maybe_unused]] const ssize_t n = ::read(ep0, &none, 0);
        } else {
            [[maybe_unused]] const ssize_t n = ::write(ep0, &none, 0);
        }
    }

    void reply(const uint8_t* bytes, std::size_t size, uint16_t limit) {
        const std::size_t n = std::min<std::size_t>(size, limit);
        [[maybe_unused]] const ssize_t w = ::write(ep0, bytes, n);
    }

    void setup(const usb_ctrlrequest& raw) {
        ++setups;
        detail::SetupPacket s;
        s.request_type = raw.bRequestType;
        s.request = raw.bRequest;
        s.value = le16toh(raw.wValue);
        s.index = le16toh(raw.wIndex);
        s.length = le16toh(raw.wLength);
        const detail::ControlAction action = detail::classify_setup(s);
        using Kind = detail::ControlAction::Kind;
        switch (action.kind) {
            case Kind::stall: stall(action); return;
            case Kind::acknowledge: {
                uint8_t none = 0;
                [[maybe_unused]] const ssize_t n = ::read(ep0, &none, 0);  // a zero-length read acks
                return;
            }
            case Kind::report_descriptor:
                reply(report_descriptor.data(), report_descriptor.size(), action.length);
                log.line("report descriptor sent (" + std::to_string(report_descriptor.size()) + " bytes)");
                return;
            case Kind::hid_descriptor: {
                const auto hid = detail::hid_class_descriptor(static_cast<uint16_t>(report_descriptor.size()));
                reply(hid.data(), hid.size(), action.length);
                return;
            }
            case Kind::set_output:
            case Kind::set_feature: {
                std::vector<uint8_t> data(action.length);
                const ssize_t n = ::read(ep0, data.data(), data.size());
                if (n < 0) {
                    log.line("SET_REPORT data stage failed: " + errno_text(errno));
                    return;
                }
                data.resize(static_cast<std::size_t>(n));
                if (!channel) return;
                push_frame(Frame{action.kind == Kind::set_output ? FrameKind::output_report : FrameKind::set_feature,
                                 std::move(data)});
                return;
            }
            case Kind::get_feature: {
                if (!channel) {
                    stall(action);
                    return;
                }
                if (channel->standard_pid && !protocol::is_standard_pid_report(action.report_id)) {
                    detail::ControlAction a = action;
                    a.kind = Kind::stall;
                    a.reason = "GET_REPORT(Feature) of report id " + std::to_string(action.report_id) +
                               ": not a report of this standard PID device";
                    stall(a);
                    return;
                }
                {
                    std::lock_guard lock(channel->mutex);
                    channel->reply.reset();
                    channel->reply_refused = false;
                    channel->reply_pending = true;
                }
                pending = PendingGet{action, std::chrono::steady_clock::now() + kReplyTimeout};
                push_frame(Frame{FrameKind::get_feature, {action.report_id}});
                return;
            }
        }
    }

    // The pending GET_REPORT: its reply arrived, or it was refused, or it timed out.
    void finish_pending() {
        if (!pending || !channel) return;
        std::optional<std::vector<uint8_t>> bytes;
        bool refused = false;
        {
            std::lock_guard lock(channel->mutex);
            bytes = std::move(channel->reply);
            channel->reply.reset();
            refused = channel->reply_refused;
            if (bytes || refused) channel->reply_pending = false;
        }
        if (bytes) {
            reply(bytes->data(), bytes->size(), pending->action.length);
            pending.reset();
        } else if (refused || std::chrono::steady_clock::now() >= pending->deadline) {
            detail::ControlAction a = pending->action;
            a.kind = detail::ControlAction::Kind::stall;
            a.reason = "GET_REPORT(Feature) of report id " + std::to_string(a.report_id) +
                       (refused ? ": the device refused it (see its status)" : ": no reply within 1 s");
            {
                std::lock_guard lock(channel->mutex);
                channel->reply_pending = false;
            }
            pending.reset();
            stall(a);
        }
    }

    void handle_event(const usb_functionfs_event& e) {
        switch (e.type) {
            case FUNCTIONFS_SETUP: setup(e.u.setup); break;
            case FUNCTIONFS_ENABLE: host_arrived(); break;
            case FUNCTIONFS_DISABLE:
            case FUNCTIONFS_UNBIND: host_gone(); break;
            default: break;  // BIND, SUSPEND, RESUME: nothing to do
        }
    }

    void run() {
        std::vector<usb_functionfs_event> events;
        while (!stopping.load(std::memory_order_relaxed)) {
            pollfd fds[3] = {{aio_fd, POLLIN, 0}, {wake_fd, POLLIN, 0}, {ep0, POLLIN, 0}};
            const nfds_t count = pending ? 2 : 3;  // ep0 rests while a reply is pending
            int timeout_ms = pending ? 5 : 100;
            const auto deadline = commit_order.next_deadline();
            if (deadline != detail::PidCommitOrder::Clock::time_point::max()) {
                const auto wait = std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
                timeout_ms = std::clamp(static_cast<int>(wait.count()), 0, timeout_ms);
            }
            const int r = ::poll(fds, count, timeout_ms);
            if (r < 0 && errno != EINTR) break;
            events.clear();
            if (count == 3 && (fds[2].revents & POLLIN) != 0) {
                usb_functionfs_event buf[4];
                const ssize_t n = ::read(ep0, buf, sizeof buf);
                if (n > 0) {
                    events.assign(buf, buf + static_cast<std::size_t>(n) / sizeof(usb_functionfs_event));
                }
            }
            collect_completions();  // OUT reports that finished before those events come first
            for (const usb_functionfs_event& e : events) handle_event(e);
            if ((fds[1].revents & POLLIN) != 0) {
                uint64_t v = 0;
                [[maybe_unused]] const ssize_t n = ::read(wake_fd, &v, sizeof v);
            }
            enqueue(commit_order.on_time(std::chrono::steady_clock::now()));
            finish_pending();
            if (channel) {
                std::lock_guard lock(channel->mutex);
                input_dropped = channel->input_dropped;
            }
            submit_in();
            submit_out();
        }
        host_gone();
    }
};

FunctionFsServer::FunctionFsServer(peripheral::Peripheral& device, const std::string& ffs_dir,
                                   const FunctionOptions& options, std::ostream* log)
    : impl_(std::make_unique<Impl>(device, ffs_dir, log)) {
    try {
        impl_->open_function(options);
    } catch (...) {
        impl_->close_all();
        throw;
    }
    impl_->thread = std::thread([this] { impl_->run(); });
}

FunctionFsServer::~FunctionFsServer() { stop(); }

void FunctionFsServer::stop() noexcept {
    if (impl_->thread.joinable()) {
        impl_->stopping = true;
        impl_->thread.join();
    }
    impl_->close_all();
}

FunctionStats FunctionFsServer::stats() const noexcept {
    FunctionStats s;
    s.hosts = impl_->hosts;
    s.setups = impl_->setups;
    s.stalled = impl_->stalled;
    s.output_reports = impl_->output_reports;
    s.input_reports = impl_->input_reports;
    s.input_dropped = impl_->input_dropped;
    return s;
}

bool FunctionFsServer::host_configured() const noexcept { return impl_->configured; }

}  // namespace feel::usb
