// Effect: the RAII handle of one effect on a device.
#include <string>

#include "device_core.hpp"
#include "effect_checks.hpp"
#include "effect_download.hpp"
#include "emulation/host_emulation.hpp"
#include "feel/host/device.hpp"
#include "feel/protocol/effect_reports.hpp"
#include "host_errors.hpp"

namespace feel::host {

using transport::FrameKind;

namespace {

Status empty_effect(const std::string& what) {
    return Status::failure(ErrorKind::invalid_handle,
                           what + ": this Effect is empty (default-constructed or moved from)");
}

}  // namespace

Effect::Effect(Effect&& other) noexcept : core_(std::move(other.core_)), record_(std::move(other.record_)) {}

Effect& Effect::operator=(Effect&& other) noexcept {
    if (this != &other) {
        Effect old(std::move(*this));  // unloads the effect this handle held, at scope end
        core_ = std::move(other.core_);
        record_ = std::move(other.record_);
    }
    return *this;
}

Effect::~Effect() {
    if (core_ && record_) {
        try {
            (void)unload();
        } catch (...) {
            // A destructor cannot report; the device frees the block when the host goes.
        }
        core_->remove_record(record_->key);
    }
    record_.reset();
    core_.reset();
}

bool Effect::valid() const noexcept {
    if (!core_ || !record_) return false;
    std::lock_guard lock(core_->mu);
    return !record_->closed;
}

bool Effect::downloaded() const noexcept {
    if (!core_ || !record_) return false;
    std::lock_guard lock(core_->mu);
    return !record_->closed && (record_->block != 0 || record_->host_id.valid());
}

EffectType Effect::type() const noexcept { return record_ ? record_->type : EffectType::constant; }

const EffectParams& Effect::parameters() const noexcept {
    static const EffectParams kNone{};
    return record_ ? record_->params : kNone;
}

uint16_t Effect::block() const noexcept {
    if (!core_ || !record_) return 0;
    std::lock_guard lock(core_->mu);
    return record_->block;
}

bool Effect::emulated() const noexcept {
    if (!core_ || !record_) return false;
    std::lock_guard lock(core_->mu);
    return record_->emulate_trigger || record_->host_rendered;
}

// The checks every call about a downloaded effect starts with: a live handle, an open
// device, a block. Returns ok and the block, or why not.
namespace {

struct Live {
    Status status;
    uint16_t block = 0;
};

Live live_block(DeviceCore& core, EffectRecord& record, const std::string& what) {
    std::string reason;
    {
        std::lock_guard lock(core.mu);
        if (record.closed) {
            return {Status::failure(ErrorKind::invalid_handle, what + ": its device was closed"), 0};
        }
        if (!core.connected) reason = "disconnected";
        else if (record.block == 0) reason = record.not_downloaded_reason;
        else return {Status::success(), record.block};
    }
    if (reason == "disconnected") return {core.disconnected_status(what), 0};
    return {Status::failure(ErrorKind::invalid_handle, what + ": " + reason), 0};
}

}  // namespace

Status Effect::download() {
    if (!core_ || !record_) return empty_effect("download");
    const std::string what = "download " + effect_label(record_->type);
    std::lock_guard call(core_->call_mu);
    {
        std::lock_guard lock(core_->mu);
        if (record_->closed) return Status::failure(ErrorKind::invalid_handle, what + ": its device was closed");
        if (record_->block != 0 || record_->host_id.valid()) return Status::success();  // already there
    }
    if (!core_->is_connected()) return core_->disconnected_status(what);
    if (record_->host_rendered) return emulation::download(*core_, *record_, what);
    return download_effect(*core_, *record_, what);
}

Status Effect::unload() {
    if (!core_ || !record_) return empty_effect("unload");
    const std::string what = "unload " + effect_label(record_->type);
    std::lock_guard call(core_->call_mu);
    if (record_->host_rendered) return emulation::unload(*core_, *record_);
    uint16_t block = 0;
    {
        std::lock_guard lock(core_->mu);
        if (record_->closed) return Status::failure(ErrorKind::invalid_handle, what + ": its device was closed");
        block = record_->block;
    }
    if (block == 0) return Status::success();  // nothing on the device
    if (!core_->is_connected()) {
        core_->set_not_downloaded(*record_, "the device went away");
        return core_->disconnected_status(what);
    }
    protocol::BlockFreeReport r;
    r.block = block;
    Status s = core_->command(r, what);
    core_->set_not_downloaded(*record_, "the effect was unloaded (call download())");
    // A block the device no longer has (freed by a reset or a lost host) is unloaded too.
    if (s.kind == ErrorKind::invalid_handle) return Status::success();
    return s;
}

Status Effect::start(int32_t iterations, bool solo) {
    if (!core_ || !record_) return empty_effect("start");
    const std::string what = "start " + effect_label(record_->type);
    if (iterations != runtime::kEffectIterations && iterations != kInfiniteIterations &&
        !(iterations >= range::kIterations.min && iterations <= range::kIterations.max)) {
        const Error e = Error::out_of_range("iterations", iterations, range::kIterations);
        return Status::failure(ErrorKind::invalid_parameter,
                               what + ": " + e.message() +
                                   ", or 0 for the effect's own count, or kInfiniteIterations",
                               e);
    }
    std::lock_guard call(core_->call_mu);
    if (record_->host_rendered) return emulation::start(*core_, *record_, iterations, solo, what);
    const Live live = live_block(*core_, *record_, what);
    if (!live.status.ok()) return live.status;
    protocol::EffectOperationReport r;
    r.block = live.block;
    r.operation = solo ? protocol::EffectOperation::start_solo : protocol::EffectOperation::start;
    r.loop_count = iterations == runtime::kEffectIterations ? protocol::kLoopEffectOwn : protocol::wire_iterations(iterations);
    Status s = core_->command(r, what);
    if (s.ok()) {
        std::lock_guard lock(core_->mu);
        record_->host_started = false;  // the game's own start: the device plays it
    }
    if (s.ok() && solo) emulation::on_device_command(*core_, runtime::DeviceControl::stop_all);
    return s;
}

Status Effect::stop() {
    if (!core_ || !record_) return empty_effect("stop");
    const std::string what = "stop " + effect_label(record_->type);
    std::lock_guard call(core_->call_mu);
    if (record_->host_rendered) return emulation::stop(*core_, *record_, what);
    const Live live = live_block(*core_, *record_, what);
    if (!live.status.ok()) return live.status;
    protocol::EffectOperationReport r;
    r.block = live.block;
    r.operation = protocol::EffectOperation::stop;
    Status s = core_->command(r, what);
    if (s.ok()) {
        std::lock_guard lock(core_->mu);
        record_->host_started = false;
    }
    return s;
}

Result<EffectStatusInfo> Effect::status() {
    if (!core_ || !record_) return empty_effect("status");
    const std::string what = "status of " + effect_label(record_->type);
    std::lock_guard call(core_->call_mu);
    if (record_->host_rendered) return emulation::status(*core_, *record_, what);
    const Live live = live_block(*core_, *record_, what);
    if (!live.status.ok()) return live.status;
    protocol::EffectStatusRequestReport q;
    q.block = live.block;
    Result<protocol::CommandAnswer> answer = core_->transact(q, FrameKind::output_report);
    if (!answer) {
        Status s = answer.status();
        s.message = what + ": " + s.message;
        return s;
    }
    const protocol::CommandAnswer& r = answer.value();
    if (Status s = status_from_command(r, what); !s.ok()) return s;
    if (r.effect_state > static_cast<uint8_t>(runtime::ReportedEffectState::emulated) ||
        r.last_end > static_cast<uint8_t>(PlayEnd::finished)) {
        return Status::failure(ErrorKind::protocol, what + ": the device answered an effect state that names nothing (" +
                                                        std::to_string(r.effect_state) + ")");
    }
    EffectStatusInfo info;
    info.state = static_cast<runtime::ReportedEffectState>(r.effect_state);
    info.iterations = r.iterations == protocol::kLoopInfinite ? kInfiniteIterations : r.iterations;
    info.completed_iterations = r.completed_iterations;
    info.elapsed_us = r.elapsed_us;
    info.last_end = static_cast<PlayEnd>(r.last_end);
    std::lock_guard lock(core_->mu);
    info.emulated = record_->emulate_trigger;
    const bool playing = info.state == runtime::ReportedEffectState::playing ||
                         info.state == runtime::ReportedEffectState::delayed;
    // The device plays what the host's emulated reflex started: the host, on the device's
    // behalf, is what made it play.
    if (record_->emulate_trigger && record_->host_started && playing) {
        info.state = runtime::ReportedEffectState::emulated;
    }
    return info;
}

Status Effect::set_parameters(const EffectParams& params, uint32_t field_mask, bool restart,
                              std::span<const int16_t> samples) {
    if (!core_ || !record_) return empty_effect("set_parameters");
    const std::string what = "set_parameters of " + effect_label(record_->type);
    if ((field_mask & ~effect_field::kAll) != 0) {
        const Error e = Error::out_of_range("field_mask", field_mask, {0, effect_field::kAll});
        return Status::failure(ErrorKind::invalid_parameter,
                               what + ": " + e.message() + ": bits beyond effect_field::kAll name no field", e);
    }
    if (params.type != record_->type) {
        const Error e = Error::invalid("type", "an effect's type never changes: create another effect");
        return Status::failure(ErrorKind::invalid_parameter,
                               what + ": type = " + effect_label(params.type) + " differs from the effect's " +
                                   effect_label(record_->type) + ": an effect's type never changes",
                               e);
    }
    std::lock_guard call(core_->call_mu);
    const EffectParams merged = merge_parameters(record_->params, params, field_mask);
    const bool new_samples = merged.type == EffectType::force_profile && (field_mask & effect_field::kTypeSpecific);
    const std::span<const int16_t> merged_samples = new_samples ? samples : std::span<const int16_t>(record_->samples);
    if (Status s = check_effect(merged, merged_samples, core_->caps, what); !s.ok()) return s;
    {
        std::lock_guard lock(core_->mu);
        if (record_->closed) return Status::failure(ErrorKind::invalid_handle, what + ": its device was closed");
        if (record_->block == 0 && !record_->host_id.valid()) {
            // Not on the device: keep the parameters for the next download().
            if (restart) {
                return Status::failure(ErrorKind::invalid_handle, what + ": cannot restart: " +
                                                                      record_->not_downloaded_reason);
            }
            record_->params = merged;
            if (new_samples) record_->samples.assign(samples.begin(), samples.end());
            return Status::success();
        }
    }
    if (!core_->is_connected()) return core_->disconnected_status(what);
    if (record_->host_rendered) {
        return emulation::update(*core_, *record_, merged, merged_samples, field_mask, restart, what);
    }
    return update_effect(*core_, *record_, merged, merged_samples, field_mask, restart, what);
}

Subscription Effect::subscribe(DynamicCallback callback) {
    if (!core_ || !record_ || !callback) return {};
    return Subscription(core_, core_->subscribe(record_->key, std::move(callback)));
}

}  // namespace feel::host
