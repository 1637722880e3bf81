// HostEmulation: host-rendered effects on one open device (host_emulation.hpp).
#include "emulation/host_emulation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "device_core.hpp"
#include "emulation/emulation_config.hpp"
#include "emulation/pid_emulation.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "host_errors.hpp"

namespace feel::host::emulation {

using Clock = std::chrono::steady_clock;

namespace {

// The renderer's handle of a record, or invalid_handle naming why there is none.
struct Held {
    Status status;
    std::shared_ptr<HostEmulation> emulation;
    EffectId id{};
};

Held held(DeviceCore& core, EffectRecord& record, const std::string& what) {
    std::lock_guard lock(core.mu);
    if (record.closed) return {Status::failure(ErrorKind::invalid_handle, what + ": its device was closed"), {}, {}};
    if (!core.connected) return {core.disconnected_status(what), {}, {}};
    if (!record.host_id.valid() || !core.emulation) {
        return {Status::failure(ErrorKind::invalid_handle, what + ": " + record.not_downloaded_reason), {}, {}};
    }
    return {Status::success(), core.emulation, record.host_id};
}

void arm_trigger(HostEmulation& em, const EffectRecord& record, EffectId id, uint32_t buttons, uint32_t hats) {
    em.triggers.arm(record.key, id, record.params.trigger, record.params.trigger_repeat_interval_us, buttons, hats);
}

}  // namespace

HostEmulation::HostEmulation(const DeviceCaps& caps, ForceLinkKind link_kind)
    : renderer(host_engine_config(caps)), link(link_kind), axis_count(caps.axis_count) {}

int64_t HostEmulation::now_us(Clock::time_point t) const noexcept {
    return std::chrono::duration_cast<std::chrono::microseconds>(t - epoch).count();
}

bool HostEmulation::update(Clock::time_point now, const protocol::JoystickInputReport& report,
                           int32_t force[kMaxAxes], std::vector<DynamicReport>& reports) {
    std::lock_guard lock(mu);
    const int64_t t_us = now_us(now);
    // Triggers first, so that a press plays from this update on.
    fired.clear();
    triggers.update(t_us, report.buttons, report.hats, fired);
    for (const EffectId id : fired) (void)renderer.start(id, runtime::kEffectIterations, false);
    float position[kMaxAxes] = {};
    for (int i = 0; i < axis_count; ++i) position[i] = report.position[i];
    const TickOutput& out = renderer.render(t_us, std::span<const float>(position, static_cast<size_t>(axis_count)),
                                            report.buttons, report.hats);
    DynamicReport dynamic;
    while (renderer.pop_report(dynamic)) reports.push_back(dynamic);
    const bool playing = renderer.playing();
    if (!playing && !was_playing) return false;
    was_playing = playing;
    for (int i = 0; i < kMaxAxes; ++i) {
        // The engine's output is clamped to ±10000 and never NaN; rounding keeps it there.
        force[i] = i < axis_count && playing ? static_cast<int32_t>(std::lround(out.force[i])) : 0;
        force[i] = std::clamp(force[i], -kFullScale, kFullScale);
    }
    return true;
}

Result<std::shared_ptr<HostEmulation>> emulation_of(DeviceCore& core, const std::string& what) {
    {
        std::lock_guard lock(core.mu);
        if (core.emulation) return core.emulation;
    }
    Result<ForceLinkKind> link = choose_force_link(core.caps, what);
    if (!link) return link.status();
    // The update rate is the report rate: the most the device sustains.
    const auto fastest = static_cast<int32_t>(runtime::report_rate_range(core.caps.loop_rate_hz).max);
    int32_t current = 0;
    {
        std::lock_guard lock(core.mu);
        current = core.caps.report_rate_hz;
    }
    if (current < fastest) {
        protocol::ReportRateReport r;
        r.rate_hz = static_cast<uint16_t>(fastest);
        if (Status s = core.command(r, what + ": raising the report rate for host emulation"); !s.ok()) return s;
        std::lock_guard lock(core.mu);
        core.caps.report_rate_hz = fastest;
    }
    auto em = std::make_shared<HostEmulation>(core.caps, link.value());
    std::lock_guard lock(core.mu);
    core.emulation = em;
    return em;
}

Status download(DeviceCore& core, EffectRecord& record, const std::string& what) {
    Result<std::shared_ptr<HostEmulation>> em = emulation_of(core, what);
    if (!em) return em.status();
    uint32_t buttons = 0, hats = 0;
    {
        std::lock_guard lock(core.mu);
        if (record.closed) return Status::failure(ErrorKind::invalid_handle, what + ": its device was closed");
        buttons = core.input.buttons;
        hats = core.input.hats;
    }
    HostEmulation& e = *em.value();
    std::lock_guard lock(e.mu);
    const CreateResult r = e.renderer.create(record.params, record.samples);
    if (!r.error.ok()) return status_from_error(r.error, what + " (host emulation)");
    arm_trigger(e, record, r.id, buttons, hats);
    std::lock_guard core_lock(core.mu);
    record.host_id = r.id;
    return Status::success();
}

Status unload(DeviceCore& core, EffectRecord& record) {
    std::shared_ptr<HostEmulation> em;
    EffectId id{};
    {
        std::lock_guard lock(core.mu);
        em = core.emulation;
        id = record.host_id;
        record.host_id = {};
        record.not_downloaded_reason = "the effect was unloaded (call download())";
    }
    if (!em || !id.valid()) return Status::success();
    std::lock_guard lock(em->mu);
    em->triggers.disarm(record.key);
    (void)em->renderer.destroy(id);
    return Status::success();
}

Status start(DeviceCore& core, EffectRecord& record, int32_t iterations, bool solo, const std::string& what) {
    Held h = held(core, record, what);
    if (!h.status.ok()) return h.status;
    if (solo) {
        // DIES_SOLO stops every other effect: the device's too.
        protocol::DeviceControlReport r;
        r.control = protocol::DeviceControlOp::stop_all_effects;
        if (Status s = core.command(r, what); !s.ok()) return s;
    }
    std::lock_guard lock(h.emulation->mu);
    return status_from_error(h.emulation->renderer.start(h.id, iterations, solo), what);
}

Status stop(DeviceCore& core, EffectRecord& record, const std::string& what) {
    Held h = held(core, record, what);
    if (!h.status.ok()) return h.status;
    std::lock_guard lock(h.emulation->mu);
    return status_from_error(h.emulation->renderer.stop(h.id), what);
}

Result<EffectStatusInfo> status(DeviceCore& core, EffectRecord& record, const std::string& what) {
    Held h = held(core, record, what);
    if (!h.status.ok()) return h.status;
    std::lock_guard lock(h.emulation->mu);
    return emulated_status(h.emulation->renderer.status(h.id));
}

Status update(DeviceCore& core, EffectRecord& record, const EffectParams& merged, std::span<const int16_t> samples,
              uint32_t field_mask, bool restart, const std::string& what) {
    Held h = held(core, record, what);
    if (!h.status.ok()) return h.status;
    uint32_t buttons = 0, hats = 0;
    {
        std::lock_guard lock(core.mu);
        buttons = core.input.buttons;
        hats = core.input.hats;
    }
    std::lock_guard lock(h.emulation->mu);
    if (Status s = status_from_error(h.emulation->renderer.update(h.id, merged, field_mask, restart, samples), what);
        !s.ok()) {
        return s;
    }
    const bool new_samples = merged.type == EffectType::force_profile && (field_mask & effect_field::kTypeSpecific);
    {
        std::lock_guard core_lock(core.mu);
        record.params = merged;
        if (new_samples) record.samples.assign(samples.begin(), samples.end());
    }
    if (field_mask & (effect_field::kTrigger | effect_field::kTriggerRepeat)) {
        arm_trigger(*h.emulation, record, h.id, buttons, hats);
    }
    return Status::success();
}

void on_device_command(DeviceCore& core, runtime::DeviceControl control) {
    std::shared_ptr<HostEmulation> em;
    {
        std::lock_guard lock(core.mu);
        em = core.emulation;
    }
    if (!em) return;
    std::vector<uint64_t> freed;
    {
        std::lock_guard lock(em->mu);
        switch (control) {
            case runtime::DeviceControl::stop_all: em->renderer.stop_all(); break;
            case runtime::DeviceControl::pause: em->renderer.pause(); break;
            case runtime::DeviceControl::resume: em->renderer.resume(); break;
            case runtime::DeviceControl::reset:
                em->renderer.stop_all();
                em->triggers.clear();
                break;
            default: break;
        }
    }
    if (control != runtime::DeviceControl::reset) return;
    // DISFFC_RESET frees every effect, the host's too: their handles keep the parameters
    // and download again.
    std::vector<std::pair<std::shared_ptr<EffectRecord>, EffectId>> held_ids;
    {
        std::lock_guard lock(core.mu);
        for (auto& [key, rec] : core.records) {
            if (!rec->host_id.valid()) continue;
            held_ids.emplace_back(rec, rec->host_id);
            rec->host_id = {};
            rec->not_downloaded_reason = "the device was reset, which freed the effect (call download())";
        }
    }
    std::lock_guard lock(em->mu);
    for (auto& [rec, id] : held_ids) (void)em->renderer.destroy(id);
}

void on_joystick(DeviceCore& core, const protocol::JoystickInputReport& report) {
    std::shared_ptr<HostEmulation> em;
    {
        std::lock_guard lock(core.mu);
        em = core.emulation;
    }
    if (!em) return;
    int32_t force[kMaxAxes] = {};
    std::vector<DynamicReport> reports;
    const bool due = em->update(Clock::now(), report, force, reports);
    if (due) {
        (void)core.send_unanswered(force_sample(em->axis_count, force));
        ++em->link_state.samples_sent;
    }
    // A host-rendered dynamic's reports go to subscribers as a device-rendered one's do.
    for (const DynamicReport& r : reports) {
        uint64_t key = 0;
        {
            std::lock_guard lock(core.mu);
            for (const auto& [k, rec] : core.records)
                if (rec->host_id.valid() && rec->host_id == r.effect) key = k;
        }
        DynamicEvent event;
        event.kind = r.kind;
        event.t_us = r.t_us;
        event.axis_count = r.axis_count;
        for (int i = 0; i < r.axis_count && i < kMaxAxes; ++i) {
            event.position[i] = r.position[i];
            event.velocity[i] = r.velocity[i];
            event.handle_velocity[i] = r.handle_velocity[i];
        }
        core.dispatch_dynamic(key, event);
    }
}

}  // namespace feel::host::emulation
