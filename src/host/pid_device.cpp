// PidDevice: any HID PID device, driven by the layout of its own descriptor
// (feel/host/pid_device.hpp).
//
// Design. The caller's thread sends and, for the two gets a PID host makes (PID Block Load
// after Create New Effect, PID Pool), waits on a condition variable for the reply the I/O
// thread files. The I/O thread is the only reader of the connection: it files replies,
// reads each Input report's buttons and hats for the reflexes the host runs (a trigger the
// device cannot name: the block is started with Effect Operation, emulation/trigger_watch.hpp)
// and, once host emulation runs, renders the report and sends the force
// (emulation/pid_emulation.hpp). Both threads send, under send_mu. A device that goes away
// wakes every wait with the transport's reason.
#include "feel/host/pid_device.hpp"

#include <atomic>
#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#include "descriptor_check.hpp"
#include "emulation/pid_emulation.hpp"
#include "emulation/sense_clock.hpp"
#include "emulation/trigger_watch.hpp"
#include "feel/effect_validation.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/protocol/pid_effect_reports.hpp"
#include "feel/transport/thread_priority.hpp"
#include "feel/transport/transport.hpp"
#include "host_errors.hpp"
#include "pid_device_core.hpp"

namespace feel::host {

using protocol::pid::PidLayout;
using protocol::pid::PidReport;
using transport::Frame;
using transport::FrameKind;

namespace {

Status encode_error(const std::string& what, const std::string& error, ErrorKind kind = ErrorKind::invalid_parameter) {
    return Status::failure(kind, what + ": " + error);
}

}  // namespace

Result<PidDevice> PidDevice::open(std::string_view address, const OpenOptions& options) {
    transport::Address parsed;
    try {
        parsed = transport::Address::parse(address);
    } catch (const std::invalid_argument& e) {
        return Status::failure(ErrorKind::invalid_parameter, std::string("open: ") + e.what());
    }
    const std::string name = parsed.to_string();
    std::unique_ptr<transport::Connection> connection;
    try {
        if (parsed.kind == transport::Address::Kind::sim) {
            peripheral::PeripheralOptions po;
            po.profile = parsed.profile;
            po.hand = options.sim_hand;
            po.motion = options.sim_motion;
            po.pid_effects_only = options.sim_pid_effects_only;
            po.runtime.lock_memory = false;
            connection = peripheral::open_in_process(po);
        } else {
            connection = transport::connect(parsed, options.timeout);
        }
    } catch (const transport::TransportError& e) {
        return Status::failure(e.kind() == transport::TransportError::Kind::timeout ? ErrorKind::timeout
                                                                                    : ErrorKind::disconnected,
                               "open " + name + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        return Status::failure(ErrorKind::invalid_parameter, "open " + name + ": " + e.what());
    } catch (const std::exception& e) {
        return Status::failure(ErrorKind::disconnected, "open " + name + ": " + e.what());
    }
    return attach(std::move(connection), name, options);
}

Result<PidDevice> PidDevice::attach(std::unique_ptr<transport::Connection> connection, std::string name,
                                    const OpenOptions& options) {
    const auto epoch = std::chrono::steady_clock::now();
    return attach(std::move(connection), std::move(name), options, [epoch] {
        return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - epoch).count();
    });
}

namespace {

// What host emulation can do on a device of this layout (PidCaps::emulated_types).
void describe_emulation(const PidLayout& layout, PidCaps& caps) {
    // (caps.max_effects and caps.axes are already read.)
    caps.input_axes = layout.input_axes();
    bool force_axis = false;
    for (const Axis a : caps.input_axes) force_axis |= std::find(caps.axes.begin(), caps.axes.end(), a) != caps.axes.end();
    if (caps.input_axes.empty()) {
        caps.emulation_problem = "its descriptor declares no Input report with a position (Generic Desktop X..Rz), "
                                 "so the host has nothing to render on";
    } else if (!caps.supports(EffectType::constant)) {
        caps.emulation_problem = "it does not play Constant Force, the effect the host streams its force through";
    } else if (!force_axis) {
        caps.emulation_problem = "no axis both reports a position and takes a force (Set Effect's Axes Enable)";
    } else if (caps.max_effects >= PidDevice::kHostHandleBase) {
        // Its blocks (at most the pool's Simultaneous Effects Max) would reach the host's handles.
        caps.emulation_problem = "it may hold " + std::to_string(caps.max_effects) +
                                 " effects, and its blocks would reach the host's handles (" +
                                 std::to_string(PidDevice::kHostHandleBase) + ")";
    } else {
        caps.emulated_types = kAllEffectTypes & ~caps.supported_types;
    }
}

}  // namespace

Result<PidDevice> PidDevice::attach(std::unique_ptr<transport::Connection> connection, std::string name,
                                    const OpenOptions& options, HostClock clock) {
    if (!connection) return Status::failure(ErrorKind::invalid_parameter, "open " + name + ": no connection");
    if (!clock) return Status::failure(ErrorKind::invalid_parameter, "open " + name + ": no clock");
    auto core = std::make_shared<PidDeviceCore>(std::move(connection), name, options);
    core->clock = std::move(clock);
    core->start();
    const std::string what = "open " + name;
    std::lock_guard call(core->call_mu);
    Result<std::vector<uint8_t>> descriptor =
        core->get(FrameKind::get_descriptor, FrameKind::descriptor_reply, -1, what + ": read the report descriptor");
    if (!descriptor) return descriptor.status();
    std::string error;
    std::optional<PidLayout> layout = PidLayout::from_bytes(descriptor.value(), error);
    if (!layout) return Status::failure(ErrorKind::not_supported, what + ": " + error);
    core->layout = std::move(*layout);
    core->layout_known.store(true, std::memory_order_release);
    PidCaps& caps = core->caps;
    caps.address = name;
    caps.feel_device = check_report_descriptor(descriptor.value()).empty();
    caps.supported_types = core->layout.supported_types();
    caps.effect_types = core->layout.effect_types();
    caps.axes = core->layout.axes();
    caps.max_effects = static_cast<int32_t>(std::min<int64_t>(core->layout.max_block_index(), INT32_MAX));
    if (core->layout.report(PidReport::pool).present) {
        Result<std::vector<uint8_t>> pool = core->get_feature(PidReport::pool, what + ": get PID Pool");
        if (!pool) return pool.status();
        const protocol::pid::Pool p = protocol::pid::read_pool(core->layout, pool.value());
        caps.has_pool_report = true;
        if (p.simultaneous_effects_max && *p.simultaneous_effects_max > 0)
            caps.max_effects = static_cast<int32_t>(std::min<int64_t>(*p.simultaneous_effects_max, caps.max_effects));
        if (p.ram_pool_size) caps.pool_bytes = static_cast<int32_t>(std::min<int64_t>(*p.ram_pool_size, INT32_MAX));
        if (p.device_managed_pool) caps.device_managed_pool = *p.device_managed_pool;
    }
    caps.profile = options.emulation_profile;
    if (caps.profile.empty() && name.rfind("sim:", 0) == 0) caps.profile = name.substr(4);
    describe_emulation(core->layout, caps);
    return PidDevice(std::move(core));
}

const PidCaps& PidDevice::capabilities() const noexcept { return core_->caps; }
const PidLayout& PidDevice::layout() const noexcept { return core_->layout; }
std::string PidDevice::address() const { return core_->address; }

bool PidDevice::connected() const noexcept {
    std::lock_guard lock(core_->mu);
    return core_->connected;
}

Result<uint16_t> PidDevice::create_effect(const EffectParams& params, std::span<const int16_t> samples) {
    const std::string what = "create " + std::string(effect_type_name(params.type));
    if (const Error e = validate_effect(params, samples)) {
        return Status::failure(ErrorKind::invalid_parameter, what + ": " + e.message(), e);
    }
    if (!core_->caps.supports(params.type)) {
        if ((core_->caps.emulated_types & effect_type_bit(params.type)) != 0) return create_emulated(params, samples, what);
        return Status::failure(ErrorKind::not_supported,
                               what + ": the device at " + core_->address + " does not play " +
                                   std::string(effect_type_name(params.type)) +
                                   " (its descriptor's Effect Type does not list it), and the host cannot render it "
                                   "there: " + core_->caps.emulation_problem);
    }
    std::string error;
    const EffectParams device_params = core_->for_device(params);
    const protocol::pid::ProfileSamples profile = core_->samples_of(samples);
    // Everything is encoded before the device is asked for a block, so that a refusal
    // leaves no block behind (block 1 stands in; the layout is the same for any block).
    if (protocol::pid::effect_reports(core_->layout, 1, device_params, error, profile).empty()) {
        return encode_error(what, error);
    }
    int64_t byte_count = 0;
    if (params.type == EffectType::force_profile) {
        const std::optional<int64_t> bytes = protocol::pid::custom_force_bytes(core_->layout, params, profile, error);
        if (!bytes) return encode_error(what, error);
        byte_count = *bytes;
    }
    std::lock_guard call(core_->call_mu);
    std::optional<std::vector<uint8_t>> create =
        protocol::pid::create_new_effect(core_->layout, params.type, error, byte_count);
    if (!create) return encode_error(what, error, ErrorKind::not_supported);
    if (Status s = core_->send(FrameKind::set_feature, std::move(*create), what + ": Create New Effect"); !s.ok()) return s;
    // A device may stall the get while it is still placing the effect (feel's USB device
    // does after 1 s without its answer): asking again reads the same Block Load.
    Result<std::vector<uint8_t>> load = core_->get_feature(PidReport::block_load, what + ": get PID Block Load");
    for (int retry = 0; retry < 2 && !load && load.status().kind == ErrorKind::protocol; ++retry)
        load = core_->get_feature(PidReport::block_load, what + ": get PID Block Load");
    if (!load) return load.status();
    const std::optional<protocol::pid::BlockLoad> block = protocol::pid::read_block_load(core_->layout, load.value());
    if (!block) return Status::failure(ErrorKind::protocol, what + ": PID Block Load from " + core_->address + " is too short");
    using BlockStatus = protocol::pid::BlockLoad::Status;
    if (block->status == BlockStatus::full)
        return Status::failure(ErrorKind::device_full, what + ": the device's effect memory is full (PID Block Load: full)");
    if (block->status != BlockStatus::success || block->block == 0) {
        return Status::failure(ErrorKind::protocol, what + ": PID Block Load says " +
                                                        (block->status == BlockStatus::error ? "error" : "no status") +
                                                        " (block " + std::to_string(block->block) + ")");
    }
    for (const protocol::pid::OutgoingReport& r :
         protocol::pid::effect_reports(core_->layout, block->block, device_params, error, profile)) {
        if (Status s = core_->send(FrameKind::output_report, r.bytes,
                                   what + ": " + std::string(protocol::pid::pid_report_name(r.report)));
            !s.ok()) {
            return s;
        }
    }
    std::lock_guard lock(core_->mu);
    core_->effects[block->block] = {params, std::vector<int16_t>(samples.begin(), samples.end())};
    core_->arm_host_trigger(block->block, params);
    return block->block;
}

Status PidDevice::set_effect(uint16_t block, const EffectParams& params, std::span<const int16_t> samples) {
    const std::string what = "set effect " + std::to_string(block);
    if (const Error e = validate_effect(params, samples)) {
        return Status::failure(ErrorKind::invalid_parameter, what + ": " + e.message(), e);
    }
    if (emulated(block)) {
        Result<HostEffect> h = host_effect(block, what);
        if (!h) return h.status();
        if (Status s = check_emulable(params, *h->em, what); !s.ok()) return s;
        std::lock_guard lock(h->em->mu);
        if (Status s = status_from_error(h->em->renderer.update(h->id, params, effect_field::kAll, false, samples), what);
            !s.ok()) {
            return s;
        }
        h->em->arm_trigger(block, h->id, params);
        return Status::success();
    }
    std::lock_guard call(core_->call_mu);
    {
        std::lock_guard lock(core_->mu);
        auto it = core_->effects.find(block);
        if (it == core_->effects.end())
            return Status::failure(ErrorKind::invalid_handle, what + ": this host created no effect in block " + std::to_string(block));
        if (it->second.params.type != params.type) {
            return Status::failure(ErrorKind::invalid_parameter,
                                   what + ": type " + std::string(effect_type_name(params.type)) + " differs from the effect's " +
                                       std::string(effect_type_name(it->second.params.type)) + " (create a new effect)");
        }
    }
    std::string error;
    const std::vector<protocol::pid::OutgoingReport> reports = protocol::pid::effect_reports(
        core_->layout, block, core_->for_device(params), error, core_->samples_of(samples));
    if (reports.empty()) return encode_error(what, error);
    for (const protocol::pid::OutgoingReport& r : reports) {
        if (Status s = core_->send(FrameKind::output_report, r.bytes, what); !s.ok()) return s;
    }
    std::lock_guard lock(core_->mu);
    core_->effects[block] = {params, std::vector<int16_t>(samples.begin(), samples.end())};
    core_->arm_host_trigger(block, params);
    return Status::success();
}

Status PidDevice::start(uint16_t block, int32_t iterations, bool solo) {
    const std::string what = "start effect " + std::to_string(block);
    if (emulated(block)) {
        Result<HostEffect> h = host_effect(block, what);
        if (!h) return h.status();
        if (solo) {
            // Solo stops every other effect of this host, the device's too (not the link's).
            for (const uint16_t other : effects())
                if (!emulated(other)) (void)stop(other);
        }
        std::lock_guard lock(h->em->mu);
        return status_from_error(h->em->renderer.start(h->id, iterations, solo), what);
    }
    int32_t loops = iterations;
    {
        std::lock_guard lock(core_->mu);
        auto it = core_->effects.find(block);
        if (it == core_->effects.end())
            return Status::failure(ErrorKind::invalid_handle, what + ": this host created no effect in block " + std::to_string(block));
        if (loops == runtime::kEffectIterations) loops = it->second.params.iterations;
    }
    if (loops != kInfiniteIterations && loops < 1) {
        return Status::failure(ErrorKind::invalid_parameter,
                               what + ": iterations " + std::to_string(iterations) + " (allowed 0 for the effect's own, 1.., or infinite)");
    }
    std::string error;
    std::optional<std::vector<uint8_t>> op = protocol::pid::effect_operation(
        core_->layout, block, solo ? protocol::pid::Operation::start_solo : protocol::pid::Operation::start, loops, error);
    if (!op) return encode_error(what, error);
    std::lock_guard call(core_->call_mu);
    return core_->send(FrameKind::output_report, std::move(*op), what);
}

Status PidDevice::stop(uint16_t block) {
    const std::string what = "stop effect " + std::to_string(block);
    if (emulated(block)) {
        Result<HostEffect> h = host_effect(block, what);
        if (!h) return h.status();
        std::lock_guard lock(h->em->mu);
        return status_from_error(h->em->renderer.stop(h->id), what);
    }
    std::string error;
    std::optional<std::vector<uint8_t>> op =
        protocol::pid::effect_operation(core_->layout, block, protocol::pid::Operation::stop, 1, error);
    if (!op) return encode_error(what, error);
    std::lock_guard call(core_->call_mu);
    return core_->send(FrameKind::output_report, std::move(*op), what);
}

Status PidDevice::free_effect(uint16_t block) {
    const std::string what = "free effect " + std::to_string(block);
    if (emulated(block)) {
        Result<HostEffect> h = host_effect(block, what);
        if (!h) return h.status();
        std::lock_guard lock(h->em->mu);
        h->em->handles.erase(block);
        h->em->triggers.disarm(block);
        return status_from_error(h->em->renderer.destroy(h->id), what);
    }
    {
        std::lock_guard lock(core_->mu);
        if (core_->link_blocks.count(block) != 0) {
            return Status::failure(ErrorKind::invalid_handle,
                                   what + ": block " + std::to_string(block) + " is host emulation's force link");
        }
        if (core_->effects.erase(block) == 0)
            return Status::failure(ErrorKind::invalid_handle, what + ": this host created no effect in block " + std::to_string(block));
        core_->host_triggers.disarm(block);
    }
    std::string error;
    std::optional<std::vector<uint8_t>> report = protocol::pid::block_free(core_->layout, block, error);
    if (!report) return encode_error(what, error);
    std::lock_guard call(core_->call_mu);
    return core_->send(FrameKind::output_report, std::move(*report), what);
}

Status PidDevice::set_gain(int32_t gain) {
    std::string error;
    if (!core_->layout.report(PidReport::device_gain).present)
        return Status::failure(ErrorKind::not_supported, "set gain: the device declares no Device Gain report");
    std::optional<std::vector<uint8_t>> report = protocol::pid::device_gain(core_->layout, gain, error);
    if (!report) return encode_error("set gain", error);
    std::lock_guard call(core_->call_mu);
    return core_->send(FrameKind::output_report, std::move(*report), "set gain");
}

Status PidDevice::command(runtime::DeviceControl control) {
    std::string error;
    if (!core_->layout.report(PidReport::device_control).present)
        return Status::failure(ErrorKind::not_supported, "device control: the device declares no PID Device Control report");
    std::optional<std::vector<uint8_t>> report = protocol::pid::device_control(core_->layout, control, error);
    if (!report) return encode_error("device control", error, ErrorKind::not_supported);
    std::lock_guard call(core_->call_mu);
    if (Status s = core_->send(FrameKind::output_report, std::move(*report), "device control"); !s.ok()) return s;
    std::shared_ptr<emulation::PidEmulation> em = core_->emulation_now();
    if (control == runtime::DeviceControl::reset) {
        // A reset frees every block (PID 1.0, DC Device Reset): the link's too, so the
        // host's effects go with them (a new one sets the link up again).
        std::lock_guard lock(core_->mu);
        core_->effects.clear();
        core_->host_triggers.clear();
        core_->link_blocks.clear();
        core_->emulation.reset();
        return Status::success();
    }
    if (!em) return Status::success();
    {
        std::lock_guard lock(em->mu);
        if (control == runtime::DeviceControl::stop_all) em->renderer.stop_all();
        if (control == runtime::DeviceControl::pause) em->renderer.pause();
        if (control == runtime::DeviceControl::resume) em->renderer.resume();
    }
    if (control == runtime::DeviceControl::stop_all) {
        // Stop All stopped the link's Constant Force effects too: they carry on at 0.
        for (const emulation::PidEmulation::LinkAxis& l : em->link()) {
            std::optional<std::vector<uint8_t>> op = protocol::pid::effect_operation(
                core_->layout, l.block, protocol::pid::Operation::start, kInfiniteIterations, error);
            if (!op) return encode_error("device control: restarting host emulation's force link", error);
            if (Status s = core_->send(FrameKind::output_report, std::move(*op), "device control: restarting the force link");
                !s.ok()) {
                return s;
            }
        }
    }
    return Status::success();
}

Result<protocol::pid::Pool> PidDevice::pool() {
    if (!core_->layout.report(PidReport::pool).present)
        return Status::failure(ErrorKind::not_supported, "pool: the device declares no PID Pool report");
    std::lock_guard call(core_->call_mu);
    Result<std::vector<uint8_t>> bytes = core_->get_feature(PidReport::pool, "get PID Pool");
    if (!bytes) return bytes.status();
    return protocol::pid::read_pool(core_->layout, bytes.value());
}

std::vector<uint16_t> PidDevice::effects() const {
    std::shared_ptr<emulation::PidEmulation> em;
    std::vector<uint16_t> out;
    {
        std::lock_guard lock(core_->mu);
        for (const auto& [block, effect] : core_->effects)
            if (core_->link_blocks.count(block) == 0) out.push_back(block);
        em = core_->emulation;
    }
    if (em) {
        std::lock_guard lock(em->mu);
        for (const auto& [handle, id] : em->handles) out.push_back(handle);
    }
    return out;
}

Result<EffectStatusInfo> PidDevice::status(uint16_t handle) {
    const std::string what = "status of effect " + std::to_string(handle);
    if (!emulated(handle)) {
        std::lock_guard lock(core_->mu);
        const auto it = core_->effects.find(handle);
        if (it != core_->effects.end() && core_->host_triggers.armed(handle)) {
            // The device plays it, and the host runs its reflex (starts it on each press the
            // Input report shows): "emulated", which is what the host does for it.
            EffectStatusInfo info;
            info.state = runtime::ReportedEffectState::emulated;
            info.emulated = true;
            info.iterations = it->second.params.iterations;
            return info;
        }
        return Status::failure(ErrorKind::not_supported,
                               what + ": a standard PID device reports no per-effect status to this host "
                                      "(only host-rendered effects and device effects whose trigger the host runs "
                                      "have one)");
    }
    Result<HostEffect> h = host_effect(handle, what);
    if (!h) return h.status();
    std::lock_guard lock(h->em->mu);
    return emulation::emulated_status(h->em->renderer.status(h->id));
}

bool PidDevice::trigger_emulated(uint16_t handle) const {
    if (emulated(handle)) {
        const std::shared_ptr<emulation::PidEmulation> em = core_->emulation_now();
        if (!em) return false;
        std::lock_guard lock(em->mu);
        return em->triggers.armed(handle);
    }
    std::lock_guard lock(core_->mu);
    return core_->host_triggers.armed(handle);
}

PidEmulationStats PidDevice::emulation_stats() const {
    PidEmulationStats out;
    const std::shared_ptr<emulation::PidEmulation> em = core_->emulation_now();
    if (!em) return out;
    std::lock_guard lock(em->mu);
    out.active = true;
    out.updates = em->updates;
    out.levels_sent = em->levels_sent;
    for (const emulation::PidEmulation::LinkAxis& l : em->link()) out.link_blocks.push_back(l.block);
    return out;
}

void PidDevice::observe_emulation(EmulationObserver observer) {
    std::lock_guard lock(core_->mu);
    core_->emulation_observer = std::move(observer);
}

Result<PidDevice::HostEffect> PidDevice::host_effect(uint16_t handle, const std::string& what) const {
    std::shared_ptr<emulation::PidEmulation> em = core_->emulation_now();
    if (em) {
        std::lock_guard lock(em->mu);
        auto it = em->handles.find(handle);
        if (it != em->handles.end()) return HostEffect{em, it->second};
    }
    return Status::failure(ErrorKind::invalid_handle,
                           what + ": this host renders no effect with handle " + std::to_string(handle) +
                               " (freed, or freed by a device reset)");
}

Status PidDevice::check_emulable(const EffectParams& params, const emulation::PidEmulation& em, const std::string& what) {
    for (int32_t i = 0; i < params.axis_count; ++i) {
        if (!em.links(params.axes[i])) {
            return Status::failure(ErrorKind::invalid_parameter,
                                   what + ": axis " + std::string(axis_name(params.axes[i])) +
                                       " both reports no position or takes no force on " + core_->address +
                                       " (host emulation renders on the axes that do both)");
        }
    }
    return Status::success();
}

Result<std::shared_ptr<emulation::PidEmulation>> PidDevice::ensure_link(const std::string& what) {
    std::lock_guard setup(core_->emulation_mu);
    if (std::shared_ptr<emulation::PidEmulation> em = core_->emulation_now()) return em;
    std::vector<emulation::PidEmulation::LinkAxis> link;
    const PidCaps& caps = core_->caps;
    for (const Axis a : caps.input_axes) {
        if (std::find(caps.axes.begin(), caps.axes.end(), a) == caps.axes.end()) continue;
        // One Constant Force along this axis alone, endless, level 0 until the first update.
        EffectParams p;
        p.type = EffectType::constant;
        p.duration_us = kInfiniteUs;
        p.axis_count = 1;
        p.axes[0] = a;
        p.direction.kind = DirectionKind::none;
        p.constant.magnitude = 0;
        Result<uint16_t> block = create_effect(p);
        if (block) {
            Status s = start(*block, kInfiniteIterations);
            if (!s.ok()) block = s;
        }
        if (!block) {
            for (const emulation::PidEmulation::LinkAxis& made : link) (void)free_effect(made.block);
            return Status::failure(block.status().kind, what + ": setting up host emulation's force link: " +
                                                            block.status().message);
        }
        link.push_back({a, *block, 0});
    }
    auto em = std::make_shared<emulation::PidEmulation>(emulation::pid_engine_config(caps.profile, core_->layout),
                                                        std::move(link));
    std::lock_guard lock(core_->mu);
    for (const emulation::PidEmulation::LinkAxis& l : em->link()) core_->link_blocks.insert(l.block);
    core_->emulation = em;
    return em;
}

Result<uint16_t> PidDevice::create_emulated(const EffectParams& params, std::span<const int16_t> samples,
                                            const std::string& what) {
    Result<std::shared_ptr<emulation::PidEmulation>> em = ensure_link(what);
    if (!em) return em.status();
    emulation::PidEmulation& e = *em.value();
    if (Status s = check_emulable(params, e, what); !s.ok()) return s;
    std::lock_guard lock(e.mu);
    std::lock_guard core_lock(core_->mu);
    if (core_->next_handle == 0xFFFF)
        return Status::failure(ErrorKind::device_full, what + ": the host's effect handles are used up (close and open again)");
    const CreateResult r = e.renderer.create(params, samples);
    if (!r.error.ok()) return status_from_error(r.error, what + " (host emulation)");
    const uint16_t handle = core_->next_handle++;
    e.handles[handle] = r.id;
    e.arm_trigger(handle, r.id, params);
    return handle;
}

void PidDevice::close() {
    if (!core_) return;
    std::vector<uint16_t> blocks;
    {
        std::lock_guard lock(core_->mu);
        for (const auto& [block, effect] : core_->effects) blocks.push_back(block);
        core_->link_blocks.clear();
        core_->emulation.reset();  // nothing more is rendered or sent
    }
    for (const uint16_t block : blocks) (void)free_effect(block);
    core_->close();
}

}  // namespace feel::host
