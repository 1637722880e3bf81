// PidDeviceCore: the I/O thread's loop (files replies, drains Input reports for the host's
// reflexes and its emulation's renders) and the send/get primitives PidDevice's calls use.
// The design: pid_device.cpp.
#include "pid_device_core.hpp"

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

namespace feel::host {

using protocol::pid::PidLayout;
using protocol::pid::PidReport;
using transport::Frame;
using transport::FrameKind;

void PidDeviceCore::start() {
    io = std::thread([this] { run(); });
}

std::shared_ptr<emulation::PidEmulation> PidDeviceCore::emulation_now() {
    std::lock_guard lock(mu);
    return emulation;
}

bool PidDeviceCore::handle(Frame& f) {
    if (f.kind == FrameKind::busy) {
        mark_gone("the device " + address + " is in use by another host");
        return false;
    }
    if (f.kind == FrameKind::input_report) {
        protocol::pid::JoystickReading reading;
        if (!layout_known.load(std::memory_order_acquire)) return true;  // before attach() read it
        if (!protocol::pid::read_joystick(layout, f.payload, reading)) return true;
        drain.push_back(reading);
        drain_arrivals.push_back(clock());
        return true;
    }
    if (f.kind != FrameKind::feature_reply && f.kind != FrameKind::descriptor_reply) return true;
    std::lock_guard lock(mu);
    const bool id_matches = f.kind == FrameKind::descriptor_reply || (!f.payload.empty() && f.payload[0] == wanted_id);
    if (f.kind == wanted_kind && id_matches) {
        reply = std::move(f.payload);
        cv.notify_all();
    }
    return true;
}

bool PidDeviceCore::render_drain(emulation::PidEmulation* em) {
    if (drain.empty()) return false;
    drain_sense.resize(drain.size());
    sense_clock.place(drain_arrivals, drain_sense);
    for (std::size_t i = 0; i < drain.size(); ++i) {
        std::lock_guard lock(mu);
        buttons = drain[i].buttons;
        hats = drain[i].hats;
        host_triggers.update(drain_sense[i], drain[i].buttons, drain[i].hats, fired);
    }
    if (em != nullptr) {
        std::lock_guard lock(em->mu);
        for (std::size_t i = 0; i < drain.size(); ++i) em->render(drain_sense[i], drain[i]);
    }
    return em != nullptr;
}

void PidDeviceCore::observe(const std::vector<std::pair<uint16_t, int32_t>>& sent, bool stalled, int64_t stall_us,
                            const protocol::pid::JoystickReading& stall_at) {
    PidDevice::EmulationObserver observer;
    {
        std::lock_guard lock(mu);
        observer = emulation_observer;
    }
    if (!observer) return;
    PidEmulationUpdate u;
    if (stalled) {
        u.stalled = true;
        u.arrival_us = u.sense_us = stall_us;
        for (int a = 0; a < kMaxAxes; ++a) u.position[a] = stall_at.position[a];
        u.sent = sent;
        observer(u);
        return;
    }
    for (std::size_t i = 0; i < drain.size(); ++i) {
        u.arrival_us = drain_arrivals[i];
        u.sense_us = drain_sense[i];
        for (int a = 0; a < kMaxAxes; ++a) u.position[a] = drain[i].position[a];
        if (i + 1 == drain.size()) u.sent = sent;
        observer(u);
    }
}

std::vector<std::pair<uint16_t, int32_t>> PidDeviceCore::send_due(emulation::PidEmulation& em) {
    std::vector<std::pair<uint16_t, int32_t>> due;
    {
        std::lock_guard lock(em.mu);
        em.take_due(due);
    }
    for (const auto& [block, level] : due) {
        std::string error;
        std::optional<std::vector<uint8_t>> bytes = protocol::pid::set_constant_force(layout, block, level, error);
        if (bytes) (void)send(FrameKind::output_report, std::move(*bytes), "host emulation: Set Constant Force");
    }
    return due;
}

void PidDeviceCore::run() noexcept {
    (void)transport::raise_thread_priority(options.io_fifo_priority);  // where the process may
    // When the last frame came (steady clock): the host's clock is read once per Input
    // report (its arrival) and once per stall render, never to find out whether one is
    // due, so a caller's clock (a test's, a probe's) sees one reading per report.
    auto last_frame = std::chrono::steady_clock::now();
    while (!stopping) {
        try {
            const std::shared_ptr<emulation::PidEmulation> em = emulation_now();
            // While emulating, wake often enough to notice a device that went quiet.
            std::optional<Frame> f = connection->receive(std::chrono::milliseconds(em ? 1 : 50));
            if (!f) {
                // A silent device: once it has a report period, only a silence longer
                // than a loaded link's gaps (whose reports come later, in a burst) gets
                // a render on the last positions; a stand-in render there would feed
                // the velocity estimate a handle standing still.
                const auto stall = std::chrono::microseconds(sense_clock.learned() ? emulation::kPeriodicStallUs
                                                                                   : emulation::kStallUs);
                if (em && std::chrono::steady_clock::now() - last_frame >= stall) {
                    last_frame = std::chrono::steady_clock::now();  // the next look a stall later
                    int64_t t = 0;
                    bool stalled = false;
                    protocol::pid::JoystickReading at;
                    {
                        std::lock_guard lock(em->mu);
                        if (em->has_reading()) {
                            t = sense_clock.place_silence(clock());
                            stalled = em->render_if_stalled(t);
                            at = em->last_reading();
                        }
                    }
                    if (stalled) observe(send_due(*em), true, t, at);
                }
                continue;
            }
            last_frame = std::chrono::steady_clock::now();
            drain.clear();
            drain_arrivals.clear();
            if (!handle(*f)) return;
            // Everything already queued is read before the force goes: the newest force,
            // never a backlog.
            while (!drain.empty()) {
                std::optional<Frame> more = connection->receive(std::chrono::milliseconds(0));
                if (!more) break;
                if (!handle(*more)) return;
            }
            if (render_drain(em.get())) observe(send_due(*em), false, 0);
            start_fired();
        } catch (const std::exception& e) {
            mark_gone(std::string("the device is gone: ") + e.what());
            return;
        }
    }
}

void PidDeviceCore::start_fired() {
    for (const uint16_t block : fired) {
        int32_t loops = 1;
        {
            std::lock_guard lock(mu);
            auto it = effects.find(block);
            if (it == effects.end()) continue;
            loops = it->second.params.iterations;
        }
        std::string error;
        std::optional<std::vector<uint8_t>> op =
            protocol::pid::effect_operation(layout, block, protocol::pid::Operation::start, loops, error);
        if (op) (void)send(FrameKind::output_report, std::move(*op), "trigger: start effect " + std::to_string(block));
    }
    fired.clear();
}

protocol::pid::ProfileSamples PidDeviceCore::samples_of(std::span<const int16_t> values) const {
    return {values, caps.feel_device};
}

EffectParams PidDeviceCore::for_device(const EffectParams& params) const {
    EffectParams p = params;
    if (!protocol::pid::device_runs_trigger(layout, p.trigger)) {
        p.trigger = {};
        p.trigger_repeat_interval_us = 0;
    }
    return p;
}

void PidDeviceCore::arm_host_trigger(uint16_t block, const EffectParams& params) {
    if (protocol::pid::device_runs_trigger(layout, params.trigger)) {
        host_triggers.disarm(block);
        return;
    }
    host_triggers.arm(block, block, params.trigger, params.trigger_repeat_interval_us, buttons, hats);
}

void PidDeviceCore::mark_gone(std::string why) {
    std::lock_guard lock(mu);
    if (connected) gone_reason = std::move(why);
    connected = false;
    cv.notify_all();
}

Status PidDeviceCore::gone(const std::string& what) const {
    std::lock_guard lock(mu);
    return Status::failure(ErrorKind::disconnected,
                           what + ": " + (gone_reason.empty() ? "the device at " + address + " went away" : gone_reason));
}

Status PidDeviceCore::send(FrameKind kind, std::vector<uint8_t> bytes, const std::string& what) {
    {
        std::lock_guard lock(mu);
        if (!connected) return Status::failure(ErrorKind::disconnected, what + ": " + gone_reason);
    }
    try {
        std::lock_guard lock(send_mu);
        connection->send(Frame{kind, std::move(bytes)});
        return Status::success();
    } catch (const transport::TransportError& e) {
        mark_gone(e.what());
        return gone(what);
    } catch (const std::exception& e) {
        return Status::failure(ErrorKind::protocol, what + ": " + e.what());
    }
}

Result<std::vector<uint8_t>> PidDeviceCore::get(FrameKind request, FrameKind reply_kind, int id, const std::string& what) {
    {
        std::lock_guard lock(mu);
        wanted_kind = reply_kind;
        wanted_id = id;
        reply.reset();
    }
    std::vector<uint8_t> payload;
    if (id >= 0) payload.push_back(static_cast<uint8_t>(id));
    if (Status s = send(request, std::move(payload), what); !s.ok()) return s;
    std::unique_lock lock(mu);
    cv.wait_for(lock, options.timeout, [&] { return reply.has_value() || !connected; });
    wanted_kind = FrameKind::busy;
    if (reply) {
        std::vector<uint8_t> out = std::move(*reply);
        reply.reset();
        return out;
    }
    if (!connected) {
        lock.unlock();
        return gone(what);
    }
    return Status::failure(ErrorKind::timeout, what + ": the device at " + address + " did not answer within " +
                                                   std::to_string(options.timeout.count()) + " ms");
}

Result<std::vector<uint8_t>> PidDeviceCore::get_feature(PidReport r, const std::string& what) {
    return get(FrameKind::get_feature, FrameKind::feature_reply, layout.report(r).id, what);
}

void PidDeviceCore::close() noexcept {
    stopping = true;
    if (connection) connection->close();
    if (io.joinable()) io.join();
    std::lock_guard lock(mu);
    connected = false;
    if (gone_reason.empty()) gone_reason = "the device was closed";
}

}  // namespace feel::host
