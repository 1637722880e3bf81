// Device: open, capabilities, EnumEffects, create, device-wide commands, input, streaming.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <thread>

#include "descriptor_check.hpp"
#include "feel/protocol/pid_layout.hpp"
#include "device_core.hpp"
#include "device_info.hpp"
#include "effect_checks.hpp"
#include "effect_download.hpp"
#include "emulation/emulation_config.hpp"
#include "emulation/host_emulation.hpp"
#include "feel/host/device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/transport/thread_priority.hpp"
#include "feel/transport/transport.hpp"
#include "host_errors.hpp"

namespace feel::host {

using transport::FrameKind;

namespace {

constexpr Range kTimeoutMs{1, 60000};
constexpr Range kBusyWaitMs{0, 60000};
// How often open() asks a busy device again.
constexpr auto kBusyRetry = std::chrono::milliseconds(10);

Status no_device(const char* what) {
    return Status::failure(ErrorKind::invalid_handle,
                           std::string(what) + ": this Device is empty (default-constructed or moved from)");
}

Status check_options(const OpenOptions& o) {
    if (!kTimeoutMs.contains(o.timeout.count())) {
        const Error e = Error::out_of_range("timeout", o.timeout.count(), kTimeoutMs);
        return Status::failure(ErrorKind::invalid_parameter, "open: " + e.message() + " ms", e);
    }
    if (!kBusyWaitMs.contains(o.busy_wait.count())) {
        const Error e = Error::out_of_range("busy_wait", o.busy_wait.count(), kBusyWaitMs);
        return Status::failure(ErrorKind::invalid_parameter, "open: " + e.message() + " ms", e);
    }
    if (o.report_rate_hz != 0 && !Range{runtime::kMinReportRateHz, runtime::kMaxReportRateHz}.contains(o.report_rate_hz)) {
        const Error e = Error::out_of_range("report_rate_hz", o.report_rate_hz,
                                            {runtime::kMinReportRateHz, runtime::kMaxReportRateHz});
        return Status::failure(ErrorKind::invalid_parameter, "open: " + e.message() + " Hz, or 0 for the device's", e);
    }
    if (const std::string wrong = transport::check_fifo_priority("io_fifo_priority", o.io_fifo_priority); !wrong.empty()) {
        return Status::failure(ErrorKind::invalid_parameter, "open: " + wrong);
    }
    return Status::success();
}

std::string profile_names() {
    std::string out;
    for (const sim::DeviceProfile& p : sim::device_profiles()) {
        if (!out.empty()) out += ", ";
        out += p.name;
    }
    return out;
}

Status prefixed(Status s, const std::string& prefix) {
    s.message = prefix + ": " + s.message;
    return s;
}

protocol::DeviceControlOp control_op(runtime::DeviceControl c) {
    switch (c) {
        case runtime::DeviceControl::actuators_on: return protocol::DeviceControlOp::enable_actuators;
        case runtime::DeviceControl::actuators_off: return protocol::DeviceControlOp::disable_actuators;
        case runtime::DeviceControl::stop_all: return protocol::DeviceControlOp::stop_all_effects;
        case runtime::DeviceControl::reset: return protocol::DeviceControlOp::device_reset;
        case runtime::DeviceControl::pause: return protocol::DeviceControlOp::device_pause;
        case runtime::DeviceControl::resume: return protocol::DeviceControlOp::device_continue;
    }
    throw std::invalid_argument("unknown device control");
}

}  // namespace

// --- open ----------------------------------------------------------------------------------

Result<Device> Device::open(std::string_view address, const OpenOptions& options) {
    if (Status s = check_options(options); !s.ok()) return s;
    transport::Address parsed;
    try {
        parsed = transport::Address::parse(address);
    } catch (const std::invalid_argument& e) {
        return Status::failure(ErrorKind::invalid_parameter, std::string("open: ") + e.what());
    }
    const std::string name = parsed.to_string();
    std::unique_ptr<transport::Connection> connection;
    if (parsed.kind == transport::Address::Kind::sim) {
        if (sim::find_device_profile(parsed.profile) == nullptr) {
            return Status::failure(ErrorKind::invalid_parameter, "open " + name + ": unknown device profile \"" +
                                                                     parsed.profile + "\" (known: " +
                                                                     profile_names() + ")");
        }
        peripheral::PeripheralOptions po;
        po.profile = parsed.profile;
        po.hand = options.sim_hand;
        po.motion = options.sim_motion;
        po.pid_effects_only = options.sim_pid_effects_only;
        // The in-process device's loop shares the game's process: it may ask for SCHED_FIFO
        // for its own thread, but must not lock every page of the whole process in memory
        // (mlockall), which is the game's decision, not a library's.
        po.runtime.lock_memory = false;
        try {
            connection = peripheral::open_in_process(po);
        } catch (const std::invalid_argument& e) {
            return Status::failure(ErrorKind::invalid_parameter, "open " + name + ": " + e.what());
        } catch (const std::exception& e) {
            return Status::failure(ErrorKind::disconnected,
                                   "open " + name + ": the in-process device could not start: " + e.what());
        }
        return attach(std::move(connection), name, options);
    }
    // A device busy with another host is asked again until busy_wait has passed: the last
    // host may be in its teardown, or silent and about to be detached by the watchdog.
    const auto give_up = std::chrono::steady_clock::now() + options.busy_wait;
    for (;;) {
        try {
            connection = transport::connect(parsed, options.timeout);
        } catch (const transport::TransportError& e) {
            const ErrorKind kind =
                e.kind() == transport::TransportError::Kind::timeout ? ErrorKind::timeout : ErrorKind::disconnected;
            return Status::failure(kind, "open " + name + ": " + e.what());
        } catch (const std::invalid_argument& e) {
            return Status::failure(ErrorKind::invalid_parameter, "open " + name + ": " + e.what());
        } catch (const std::exception& e) {  // the system refused the socket itself
            return Status::failure(ErrorKind::disconnected, "open " + name + ": " + e.what());
        }
        Result<Device> device = attach(std::move(connection), name, options);
        const bool busy = !device && device.status().kind == ErrorKind::disconnected &&
                          device.status().message.find(DeviceCore::kBusyReason) != std::string::npos;
        if (!busy || std::chrono::steady_clock::now() + kBusyRetry > give_up) return device;
        std::this_thread::sleep_for(kBusyRetry);
    }
}

Result<Device> Device::attach(std::unique_ptr<transport::Connection> connection, std::string name,
                              const OpenOptions& options) {
    if (Status s = check_options(options); !s.ok()) return s;
    if (!connection) return Status::failure(ErrorKind::invalid_parameter, "open " + name + ": no connection");
    auto core = std::make_shared<DeviceCore>(std::move(connection), name, options);
    core->start();
    const std::string what = "open " + name;
    // Read the descriptor and the capabilities; on failure the core is closed (after the
    // caller lock is released: close() takes it too).
    const Status opened = [&]() -> Status {
        std::lock_guard call(core->call_mu);
        Result<std::vector<uint8_t>> descriptor = core->get_descriptor();
        if (!descriptor) return prefixed(descriptor.status(), what);
        protocol::JoystickLayout joystick;
        if (const std::string problem = check_report_descriptor(descriptor.value(), &joystick); !problem.empty()) {
            std::string pid_error;
            if (protocol::pid::PidLayout::from_bytes(descriptor.value(), pid_error)) {
                return Status::failure(ErrorKind::protocol,
                                       what + ": not a device of this feel protocol (" + problem +
                                           "), but a HID PID device: feel::host::PidDevice drives it with "
                                           "standard PID reports (docs/real-devices.md)");
            }
            return Status::failure(ErrorKind::protocol,
                                   what + ": the device speaks another version of the protocol: " + problem);
        }
        core->descriptor = std::move(descriptor.value());
        {
            std::lock_guard lock(core->mu);
            core->joystick = joystick;
        }
        Result<protocol::AnyReport> info = core->get_feature(protocol::ReportId::device_info);
        if (!info) return prefixed(info.status(), what);
        const auto& report = std::get<protocol::DeviceInfoReport>(info.value());
        if (report.vendor_revision != runtime::kProtocolVendorRevision) {
            // The vendor reports' layouts are frozen within a revision only (docs/protocol.md,
            // "Versioning"): another revision's reports may not mean what this host writes.
            return Status::failure(ErrorKind::protocol,
                                   what + ": the device speaks feel vendor revision " +
                                       std::to_string(report.vendor_revision) + ", this host speaks revision " +
                                       std::to_string(runtime::kProtocolVendorRevision) +
                                       " (\"" + std::string(runtime::kProtocolVersion) +
                                       "\"): update the host or the device's firmware so both speak the same revision");
        }
        std::lock_guard lock(core->mu);
        core->caps = caps_from_info(report);
        core->input.axis_count = core->caps.axis_count;
        return Status::success();
    }();
    if (!opened.ok()) {
        core->close(false);
        return opened;
    }
    Device device(core);
    if (options.report_rate_hz != 0) {
        if (Status s = device.set_report_rate(options.report_rate_hz); !s.ok()) {
            core->close(false);
            return prefixed(s, what);
        }
    }
    return device;
}

// --- capabilities ------------------------------------------------------------------------

const DeviceCaps& Device::capabilities() const noexcept {
    static const DeviceCaps kNone{};
    return core_ ? core_->caps : kNone;
}

std::string Device::address() const { return core_ ? core_->address : std::string(); }

std::vector<EffectSupport> Device::effects(std::optional<EffectClass> only) const {
    std::vector<EffectSupport> out;
    if (!core_) return out;
    for (int i = 0; i < kEffectTypeCount; ++i) {  // EffectType lists §6.4's order
        const auto t = static_cast<EffectType>(i);
        if (!can_create(core_->caps, t)) continue;
        if (only && effect_class(t) != *only) continue;
        out.push_back(EffectSupport{t, effect_class(t)});
    }
    return out;
}

bool Device::connected() const noexcept {
    if (!core_) return false;
    std::lock_guard lock(core_->mu);
    return core_->connected;
}

void Device::close() {
    if (core_) core_->close(true);
}

// --- effects -------------------------------------------------------------------------------

Result<Effect> Device::create_effect(const EffectParams& params, std::span<const int16_t> samples) {
    const std::string what = "create " + effect_label(params.type);
    if (!core_) return no_device(what.c_str());
    std::shared_ptr<EffectRecord> record;
    {
        std::lock_guard call(core_->call_mu);
        if (Status s = check_effect(params, samples, core_->caps, what); !s.ok()) return s;
        if (!core_->is_connected()) return core_->disconnected_status(what);
        record = core_->add_record(params, std::vector<int16_t>(samples.begin(), samples.end()));
        record->host_rendered = emulation::host_renders(core_->caps, params.type);
        if (Status s = record->host_rendered ? emulation::download(*core_, *record, what)
                                             : download_effect(*core_, *record, what);
            !s.ok()) {
            core_->remove_record(record->key);
            return s;
        }
    }
    Effect effect;
    effect.core_ = core_;
    effect.record_ = std::move(record);
    return effect;
}

Result<Effect> Device::create_effect(const format::EffectSpec& spec) {
    return create_effect(spec.params, spec.samples);
}

// --- device-wide commands ------------------------------------------------------------------

Status Device::set_gain(int32_t gain) {
    if (!core_) return no_device("set_gain");
    if (!range::kGain.contains(gain)) {
        return status_from_error(Error::out_of_range("gain", gain, range::kGain), "set_gain");
    }
    std::lock_guard call(core_->call_mu);
    protocol::DeviceGainReport r;
    r.gain = static_cast<uint16_t>(gain);
    return core_->command(r, "set_gain");
}

Status Device::command(runtime::DeviceControl control) {
    const std::string what = std::string("command ") + runtime::device_control_name(control);
    if (!core_) return no_device(what.c_str());
    if (static_cast<int>(control) >= runtime::kDeviceControlCount) {
        return status_from_error(Error::out_of_range("control", static_cast<int>(control),
                                                     {0, runtime::kDeviceControlCount - 1}),
                                 "command");
    }
    std::lock_guard call(core_->call_mu);
    protocol::DeviceControlReport r;
    r.control = control_op(control);
    Status s = core_->command(r, what);
    if (s.ok()) emulation::on_device_command(*core_, control);
    if (s.ok() && control == runtime::DeviceControl::reset) {
        // DISFFC_RESET frees every effect on the device: the host keeps their parameters
        // and the game downloads them again.
        std::vector<std::shared_ptr<EffectRecord>> all;
        {
            std::lock_guard lock(core_->mu);
            for (auto& [key, rec] : core_->records) all.push_back(rec);
        }
        for (auto& rec : all) {
            core_->set_not_downloaded(*rec, "the device was reset, which freed the effect (call download())");
        }
    }
    return s;
}

Result<PoolInfo> Device::pool() {
    if (!core_) return no_device("pool");
    std::lock_guard call(core_->call_mu);
    Result<protocol::AnyReport> r = core_->get_feature(protocol::ReportId::pid_pool);
    if (!r) return prefixed(r.status(), "pool");
    const auto& p = std::get<protocol::PidPoolReport>(r.value());
    PoolInfo info;
    info.total_bytes = static_cast<int32_t>(p.ram_pool_size);
    info.free_bytes = static_cast<int32_t>(p.ram_pool_available);
    info.max_effects = p.simultaneous_effects_max;
    info.free_effects = p.free_effects;
    // The PID Pool Report has no count of dynamics or conditions with memory: feel's devices
    // keep one of each per effect slot (EngineConfig's 0), so every free slot can take either.
    info.max_dynamics = info.max_stateful_conditions = info.max_effects;
    info.free_dynamics = info.free_stateful_conditions = info.free_effects;
    info.total_samples = static_cast<int32_t>(p.sample_memory);
    info.free_samples = static_cast<int32_t>(p.free_samples);
    return info;
}

Status Device::set_idf(runtime::IdfSettings settings) {
    if (!core_) return no_device("set_idf");
    std::lock_guard call(core_->call_mu);
    protocol::IdfSettingsReport r;
    r.settings = settings;
    return core_->command(r, "set_idf");
}

Status Device::set_report_rate(int32_t hz) {
    if (!core_) return no_device("set_report_rate");
    const Range allowed = runtime::report_rate_range(core_->caps.loop_rate_hz);
    if (!allowed.contains(hz)) {
        return status_from_error(Error::out_of_range("report_rate_hz", hz, allowed), "set_report_rate");
    }
    std::lock_guard call(core_->call_mu);
    protocol::ReportRateReport r;
    r.rate_hz = static_cast<uint16_t>(hz);
    Status s = core_->command(r, "set_report_rate");
    if (s.ok()) {
        std::lock_guard lock(core_->mu);
        core_->caps.report_rate_hz = hz;
    }
    return s;
}

// --- input -----------------------------------------------------------------------------------

InputState Device::input() const {
    if (!core_) return {};
    std::lock_guard lock(core_->mu);
    return core_->input;
}

Result<InputState> Device::wait_input(std::chrono::milliseconds timeout) {
    if (!core_) return no_device("wait_input");
    std::unique_lock lock(core_->mu);
    const uint64_t seen = core_->input_rounds;
    core_->cv.wait_for(lock, timeout, [&] { return core_->input_rounds != seen || !core_->connected; });
    if (core_->input_rounds != seen) return core_->input;
    if (!core_->connected) {
        lock.unlock();
        return core_->disconnected_status("wait_input");
    }
    return Status::failure(ErrorKind::timeout, "wait_input: no state report from " + core_->address + " within " +
                                                   std::to_string(timeout.count()) + " ms");
}

Status Device::stream_force(std::span<const int32_t> force) {
    if (!core_) return no_device("stream_force");
    const int32_t axes = core_->caps.axis_count;
    if (static_cast<int64_t>(force.size()) != axes) {
        const Error e = Error::out_of_range("force.size()", static_cast<int64_t>(force.size()), {axes, axes});
        return Status::failure(ErrorKind::invalid_parameter,
                               "stream_force: " + std::to_string(force.size()) + " forces for a " +
                                   std::to_string(axes) + "-axis device (allowed exactly " + std::to_string(axes) +
                                   ", one per axis in the order x, y, z, rx, ry, rz)",
                               e);
    }
    for (std::size_t i = 0; i < force.size(); ++i) {
        if (!range::kSignedLevel.contains(force[i])) {
            return status_from_error(
                Error::out_of_range("force[" + std::to_string(i) + "]", force[i], range::kSignedLevel), "stream_force");
        }
    }
    {
        // A sample the device refused since the last call (fire and forget).
        std::lock_guard lock(core_->mu);
        if (core_->stream_error) {
            Status s = std::move(*core_->stream_error);
            core_->stream_error.reset();
            return s;
        }
    }
    protocol::DownloadForceSampleReport r;
    r.axis_count = static_cast<uint8_t>(axes);
    for (std::size_t i = 0; i < force.size(); ++i) r.force[i] = static_cast<int16_t>(force[i]);
    return core_->send_unanswered(r);
}

Subscription Device::subscribe(DynamicCallback callback) {
    if (!core_ || !callback) return {};
    return Subscription(core_, core_->subscribe(0, std::move(callback)));
}

// --- Subscription ----------------------------------------------------------------------------

Subscription::Subscription(Subscription&& other) noexcept
    : core_(std::move(other.core_)), id_(std::exchange(other.id_, 0)) {}

Subscription& Subscription::operator=(Subscription&& other) noexcept {
    if (this != &other) {
        reset();
        core_ = std::move(other.core_);
        id_ = std::exchange(other.id_, 0);
    }
    return *this;
}

Subscription::~Subscription() { reset(); }

void Subscription::reset() noexcept {
    if (id_ != 0) {
        if (auto core = core_.lock()) core->unsubscribe(id_);
    }
    id_ = 0;
    core_.reset();
}

}  // namespace feel::host
