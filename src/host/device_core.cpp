// DeviceCore: round trips, the I/O thread, input state, host emulation of reflexes.
// device_core.hpp explains the threads and the locks.
#include "device_core.hpp"
#include "input_queue.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "emulation/host_emulation.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/effect_reports.hpp"
#include "feel/transport/thread_priority.hpp"
#include "host_errors.hpp"

namespace feel::host {

using protocol::AnyReport;
using protocol::CommandStatusReport;
using protocol::ReportId;
using transport::Frame;
using transport::FrameKind;

namespace {

// The device's host watchdog trips after SafetyConfig::host_timeout_us of silence (1 s by
// default, safety.hpp); a keep-alive after 100 ms of silence keeps an idle host well
// inside it, even with a few keep-alives lost to a busy socket.
constexpr auto kKeepAliveAfter = std::chrono::milliseconds(100);
// How long one receive() waits: bounds how late a repeat of an emulated reflex and a
// keep-alive can be, and how long close() waits for the thread to notice.
constexpr auto kReceiveSlice = std::chrono::milliseconds(5);

int64_t now_ns() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

bool trigger_pressed(const Trigger& t, uint32_t buttons, uint32_t hats) {
    if (t.kind == TriggerKind::none || t.index < 1 || t.index > 32) return false;
    const uint32_t bits = t.kind == TriggerKind::hat ? hats : buttons;
    return (bits >> (t.index - 1)) & 1u;
}

Clock::duration repeat_interval(const EffectRecord& r) {
    return std::chrono::microseconds(r.params.trigger_repeat_interval_us);
}

}  // namespace

DeviceCore::DeviceCore(std::unique_ptr<transport::Connection> connection, std::string address_,
                       OpenOptions options_)
    : address(std::move(address_)), options(std::move(options_)), connection_(std::move(connection)) {}

DeviceCore::~DeviceCore() { close(true); }

void DeviceCore::start() {
    last_send_ns_ = now_ns();
    io_ = std::thread([this] { run(); });
}

uint32_t DeviceCore::next_sequence() noexcept {
    uint32_t s = sequence_.fetch_add(1);
    if (s == 0) s = sequence_.fetch_add(1);  // 0 is allowed, but reads like "none" in logs
    return s;
}

bool DeviceCore::is_connected() const {
    std::lock_guard lock(mu);
    return connected;
}

Status DeviceCore::disconnected_status(const std::string& what) const {
    std::string reason;
    {
        std::lock_guard lock(mu);
        reason = disconnect_reason.empty() ? "the device at " + address + " went away" : disconnect_reason;
    }
    return Status::failure(ErrorKind::disconnected, what + ": " + reason);
}

Status DeviceCore::send_frame(Frame frame) {
    try {
        std::lock_guard lock(send_mu);
        connection_->send(frame);
        last_send_ns_ = now_ns();
        return Status::success();
    } catch (const transport::TransportError& e) {
        // The I/O thread may still be reading what the device said before it closed (a
        // `busy` frame): give it a moment to tell why, rather than "broken pipe".
        {
            std::unique_lock lock(mu);
            cv.wait_for(lock, std::chrono::milliseconds(200), [&] { return !connected; });
        }
        mark_disconnected(std::string("the connection to ") + address + " is gone: " + e.what());
        return disconnected_status("send");
    } catch (const std::exception& e) {
        return Status::failure(ErrorKind::protocol, std::string("send to ") + address + ": " + e.what());
    }
}

Result<protocol::CommandAnswer> DeviceCore::transact(AnyReport report, FrameKind kind) {
    const std::string name(protocol::report_name(protocol::report_id_of(report)));
    const uint32_t sequence = next_sequence();
    protocol::set_sequence(report, sequence);
    std::vector<uint8_t> bytes;
    try {
        bytes = protocol::encode(report);
    } catch (const std::exception& e) {
        // The host's checks should have caught it; say so rather than send garbage.
        return Status::failure(ErrorKind::invalid_parameter, name + ": " + e.what());
    }
    std::optional<protocol::CommandAnswer> answer;
    bool registered = false;
    {
        std::lock_guard lock(mu);
        if (connected) {
            waiting[sequence] = &answer;
            registered = true;
        }
    }
    if (!registered) return disconnected_status(name);
    if (Status s = send_frame(Frame{kind, std::move(bytes)}); !s.ok()) {
        std::lock_guard lock(mu);
        waiting.erase(sequence);
        return s;
    }
    std::unique_lock lock(mu);
    cv.wait_for(lock, options.timeout, [&] { return answer.has_value() || !connected; });
    waiting.erase(sequence);
    if (answer) return *answer;
    if (!connected) {
        lock.unlock();
        return disconnected_status(name);
    }
    return Status::failure(ErrorKind::timeout, name + ": the device at " + address + " did not answer within " +
                                                   std::to_string(options.timeout.count()) + " ms");
}

Status DeviceCore::command(AnyReport report, const std::string& what, FrameKind kind) {
    Result<protocol::CommandAnswer> r = transact(std::move(report), kind);
    if (!r) {
        Status s = r.status();
        s.message = what + ": " + s.message;
        return s;
    }
    return status_from_command(r.value(), what);
}

Result<AnyReport> DeviceCore::get_feature(ReportId id) {
    const auto id_byte = static_cast<uint8_t>(id);
    const std::string name(protocol::report_name(id));
    {
        std::lock_guard lock(mu);
        if (connected) {
            expected_feature = id_byte;
            feature_reply.reset();
            feature_refusal.reset();
        }
    }
    if (!is_connected()) return disconnected_status("get " + name);
    if (Status s = send_frame(Frame{FrameKind::get_feature, {id_byte}}); !s.ok()) return s;
    std::unique_lock lock(mu);
    cv.wait_for(lock, options.timeout,
                [&] { return feature_reply.has_value() || feature_refusal.has_value() || !connected; });
    expected_feature = -1;
    if (feature_refusal) {
        const protocol::CommandAnswer refusal = *feature_refusal;
        feature_refusal.reset();
        return status_from_command(refusal, "get " + name);
    }
    if (!feature_reply) {
        if (!connected) {
            lock.unlock();
            return disconnected_status("get " + name);
        }
        return Status::failure(ErrorKind::timeout, "get " + name + ": the device at " + address +
                                                       " did not answer within " +
                                                       std::to_string(options.timeout.count()) + " ms");
    }
    std::vector<uint8_t> bytes = std::move(*feature_reply);
    feature_reply.reset();
    lock.unlock();
    AnyReport out;
    if (const Error e = protocol::decode(bytes, out)) {
        return Status::failure(ErrorKind::protocol,
                               "get " + name + ": the device at " + address + " answered a report that does not decode: " +
                                   e.message(),
                               e);
    }
    if (protocol::report_id_of(out) != id) {
        return Status::failure(ErrorKind::protocol, "get " + name + ": the device at " + address +
                                                        " answered another report (" +
                                                        std::string(protocol::report_name(protocol::report_id_of(out))) +
                                                        ")");
    }
    return out;
}

Result<std::vector<uint8_t>> DeviceCore::get_descriptor() {
    {
        std::lock_guard lock(mu);
        if (connected) {
            descriptor_wanted = true;
            descriptor_reply.reset();
        }
    }
    if (!is_connected()) return disconnected_status("get the report descriptor");
    if (Status s = send_frame(Frame{FrameKind::get_descriptor, {}}); !s.ok()) return s;
    std::unique_lock lock(mu);
    cv.wait_for(lock, options.timeout, [&] { return descriptor_reply.has_value() || !connected; });
    descriptor_wanted = false;
    if (!descriptor_reply) {
        if (!connected) {
            lock.unlock();
            return disconnected_status("get the report descriptor");
        }
        return Status::failure(ErrorKind::timeout, "get the report descriptor: the device at " + address +
                                                       " did not answer within " +
                                                       std::to_string(options.timeout.count()) + " ms");
    }
    std::vector<uint8_t> bytes = std::move(*descriptor_reply);
    descriptor_reply.reset();
    return bytes;
}

Status DeviceCore::send_unanswered(AnyReport report) {
    protocol::set_sequence(report, next_sequence());
    std::vector<uint8_t> bytes;
    try {
        bytes = protocol::encode(report);
    } catch (const std::exception& e) {
        return Status::failure(ErrorKind::invalid_parameter,
                               std::string(protocol::report_name(protocol::report_id_of(report))) + ": " + e.what());
    }
    if (!is_connected()) return disconnected_status(std::string(protocol::report_name(protocol::report_id_of(report))));
    return send_frame(Frame{FrameKind::output_report, std::move(bytes)});
}

// --- records -----------------------------------------------------------------------------

std::shared_ptr<EffectRecord> DeviceCore::add_record(EffectParams params, std::vector<int16_t> samples) {
    auto record = std::make_shared<EffectRecord>();
    record->type = params.type;
    record->params = params;
    record->samples = std::move(samples);
    std::lock_guard lock(mu);
    record->key = next_key++;
    if (closed) record->closed = true;
    records.emplace(record->key, record);
    return record;
}

void DeviceCore::remove_record(uint64_t key) {
    std::lock_guard lock(mu);
    auto it = records.find(key);
    if (it == records.end()) return;
    if (it->second->block != 0) by_block.erase(it->second->block);
    records.erase(it);
}

void DeviceCore::set_downloaded(EffectRecord& record, uint16_t block, bool emulate) {
    std::lock_guard lock(mu);
    record.block = block;
    by_block[block] = record.key;
    record.emulate_trigger = emulate;
    record.host_started = false;
    record.device_playing = false;
    // A trigger already held when the reflex is armed is not a press (the device's reflex
    // table has the same rule): only the next press starts it.
    record.trigger_down = trigger_pressed(record.params.trigger, input.buttons, input.hats);
    record.next_repeat = Clock::now() + repeat_interval(record);
}

void DeviceCore::set_not_downloaded(EffectRecord& record, std::string reason) {
    std::lock_guard lock(mu);
    if (record.block != 0) {
        auto it = by_block.find(record.block);
        if (it != by_block.end() && it->second == record.key) by_block.erase(it);
    }
    record.block = 0;
    record.host_started = false;
    record.device_playing = false;
    record.not_downloaded_reason = std::move(reason);
}

// --- subscriptions ------------------------------------------------------------------------

uint64_t DeviceCore::subscribe(uint64_t effect_key, DynamicCallback callback) {
    std::lock_guard lock(dispatch_mu);
    const uint64_t id = next_subscriber++;
    subscribers.emplace(id, Subscriber{effect_key, std::move(callback)});
    return id;
}

void DeviceCore::unsubscribe(uint64_t id) noexcept {
    // Taking dispatch_mu waits for a callback in progress on the I/O thread: after this
    // returns the callback never runs again. (Recursive: a callback may unsubscribe itself.)
    std::lock_guard lock(dispatch_mu);
    subscribers.erase(id);
}

// --- close -----------------------------------------------------------------------------

void DeviceCore::close(bool free_effects) {
    std::lock_guard call(call_mu);
    {
        std::lock_guard lock(mu);
        if (closed) return;
    }
    if (free_effects) {
        std::vector<std::pair<uint16_t, std::shared_ptr<EffectRecord>>> blocks;
        {
            std::lock_guard lock(mu);
            for (auto& [key, record] : records) {
                if (record->block != 0) blocks.emplace_back(record->block, record);
            }
        }
        for (auto& [block, record] : blocks) {
            if (!is_connected()) break;
            protocol::BlockFreeReport free_report;
            free_report.block = block;
            (void)transact(free_report, FrameKind::output_report);
        }
    }
    stopping_ = true;
    if (connection_) connection_->close();
    if (io_.joinable()) {
        if (io_.get_id() == std::this_thread::get_id()) {
            io_.detach();  // closed from a callback: the thread ends once it returns
        } else {
            io_.join();
        }
    }
    std::lock_guard lock(mu);
    closed = true;
    if (connected) {
        connected = false;
        disconnect_reason = "the device at " + address + " was closed";
    }
    for (auto& [key, record] : records) {
        record->closed = true;
        record->block = 0;
        record->not_downloaded_reason = "its device was closed";
    }
    records.clear();
    by_block.clear();
    for (const std::shared_ptr<InputQueue>& q : input_queues) q->close();
    cv.notify_all();
}

// --- the I/O thread ----------------------------------------------------------------------

void DeviceCore::mark_disconnected(const std::string& reason) {
    std::lock_guard lock(mu);
    if (!connected) return;
    connected = false;
    disconnect_reason = busy ? "the device at " + address + " " + std::string(kBusyReason) : reason;
    cv.notify_all();
    for (const std::shared_ptr<InputQueue>& q : input_queues) q->close();
}

void DeviceCore::note_protocol_problem(std::string what) {
    std::lock_guard lock(mu);
    ++unexpected_frames;
    last_protocol_problem = std::move(what);
}

void DeviceCore::run() noexcept {
    (void)transport::raise_thread_priority(options.io_fifo_priority);  // where the process may
    std::vector<uint16_t> starts;
    while (!stopping_) {
        try {
            std::optional<Frame> frame = connection_->receive(kReceiveSlice);
            if (frame) handle(*frame);
        } catch (const transport::TransportError& e) {
            if (!stopping_) mark_disconnected(std::string("the device at ") + address + " went away: " + e.what());
            else mark_disconnected("the device at " + address + " was closed");
            return;
        } catch (const std::exception& e) {
            note_protocol_problem(e.what());
        }
        try {
            starts.clear();
            {
                std::lock_guard lock(mu);
                if (!connected) return;
                collect_repeats(Clock::now(), starts);
            }
            send_emulated_starts(starts);
            if (now_ns() - last_send_ns_.load() >= std::chrono::nanoseconds(kKeepAliveAfter).count()) {
                (void)send_unanswered(protocol::KeepAliveReport{});
            }
        } catch (const std::exception& e) {
            note_protocol_problem(e.what());
        }
    }
}

void DeviceCore::handle(const Frame& frame) {
    switch (frame.kind) {
        case FrameKind::input_report: {
            AnyReport report;
            const bool is_joystick =
                !frame.payload.empty() && frame.payload[0] == static_cast<uint8_t>(protocol::ReportId::joystick_input);
            if (is_joystick) {
                protocol::JoystickInputReport joy;
                protocol::JoystickLayout layout;
                {
                    std::lock_guard lock(mu);
                    layout = joystick;
                }
                if (const Error e = protocol::decode(frame.payload, layout, joy)) {
                    note_protocol_problem("a joystick input that does not decode: " + e.message());
                    return;
                }
                on_joystick(joy);
                return;
            }
            if (const Error e = protocol::decode(frame.payload, report)) {
                note_protocol_problem("an input report that does not decode: " + e.message());
                return;
            }
            std::visit(
                [this](const auto& r) {
                    using R = std::decay_t<decltype(r)>;
                    if constexpr (std::is_same_v<R, protocol::CommandStatusReport>) on_command_status(r);
                    else if constexpr (std::is_same_v<R, protocol::CommandErrorTextReport>) error_text.add(r);
                    else if constexpr (std::is_same_v<R, protocol::EffectStatesReport>) on_effect_states(r);
                    else if constexpr (std::is_same_v<R, protocol::JoystickInputReport>) on_joystick(r);
                    else if constexpr (std::is_same_v<R, protocol::DeviceStatusReport>) on_device_status(r);
                    else if constexpr (std::is_same_v<R, protocol::PidStateReport>) on_pid_state(r);
                    else if constexpr (std::is_same_v<R, protocol::DynamicReportReport>) on_dynamic(r);
                    else note_protocol_problem("a report that is not an input report came as one");
                },
                report);
            return;
        }
        case FrameKind::feature_reply: {
            std::lock_guard lock(mu);
            if (expected_feature >= 0 && !frame.payload.empty() && frame.payload[0] == expected_feature) {
                feature_reply = frame.payload;
                cv.notify_all();
            } else {
                ++unexpected_frames;
                last_protocol_problem = "a feature report nobody asked for";
            }
            return;
        }
        case FrameKind::descriptor_reply: {
            std::lock_guard lock(mu);
            if (descriptor_wanted) {
                descriptor_reply = frame.payload;
                cv.notify_all();
            } else {
                ++unexpected_frames;
                last_protocol_problem = "a report descriptor nobody asked for";
            }
            return;
        }
        case FrameKind::busy: {
            std::lock_guard lock(mu);
            busy = true;  // the device closes next; the disconnection names this reason
            return;
        }
        default:
            note_protocol_problem("a " + std::string(transport::frame_kind_name(frame.kind)) +
                                  " frame, which only a host sends");
            return;
    }
}

void DeviceCore::on_command_status(const CommandStatusReport& report) {
    const protocol::CommandAnswer status = error_text.finish(report);
    std::lock_guard lock(mu);
    auto it = waiting.find(status.sequence);
    if (it != waiting.end()) {
        *it->second = status;
        waiting.erase(it);
        cv.notify_all();
        return;
    }
    // A refused feature get is answered with a status naming the report (it has no
    // sequence of its own).
    if (status.code != ErrorCode::ok && expected_feature >= 0 &&
        static_cast<int>(status.command) == expected_feature) {
        feature_refusal = status;
        cv.notify_all();
        return;
    }
    // Unanswered commands: keep-alives, emulated starts, force samples. Only a refused
    // force sample matters to the game: it shows in its next stream_force().
    if (status.code != ErrorCode::ok && status.command == ReportId::download_force_sample) {
        stream_error = status_from_command(status, "stream_force");
    }
}

void DeviceCore::on_joystick(const protocol::JoystickInputReport& r) {
    std::vector<uint16_t> starts;
    {
        std::lock_guard lock(mu);
        for (int i = 0; i < kMaxAxes; ++i) input.position[i] = r.position[i];
        input.buttons = r.buttons;
        input.hats = r.hats;
        ++input.reports_received;
        // A round opens with its joystick: a status before it was a round without one.
        round_has_joystick = true;
        round_has_status = false;
        // Host emulation of reflexes (§1.2.c): a press edge starts the effect, as the
        // device's reflex table would. Like the device, presses are ignored while paused.
        const Clock::time_point now = Clock::now();
        for (auto& [key, rec] : records) {
            if (!rec->emulate_trigger || rec->block == 0) continue;
            const bool down = trigger_pressed(rec->params.trigger, r.buttons, r.hats);
            if (down && !rec->trigger_down && !input.paused) {
                starts.push_back(rec->block);
                rec->host_started = true;
                ++rec->emulated_starts;
                rec->next_repeat = now + repeat_interval(*rec);
            }
            rec->trigger_down = down;
        }
        collect_repeats(now, starts);
    }
    send_emulated_starts(starts);
    emulation::on_joystick(*this, r);
}

void DeviceCore::collect_repeats(Clock::time_point now, std::vector<uint16_t>& blocks) {
    if (input.paused) return;
    for (auto& [key, rec] : records) {
        if (!rec->emulate_trigger || rec->block == 0 || !rec->trigger_down) continue;
        if (rec->params.trigger_repeat_interval_us <= 0) continue;
        if (now < rec->next_repeat) continue;
        if (std::find(blocks.begin(), blocks.end(), rec->block) == blocks.end()) blocks.push_back(rec->block);
        rec->host_started = true;
        ++rec->emulated_starts;
        // Restart once however late, and skip the missed repeats (the device's rule).
        rec->next_repeat += repeat_interval(*rec);
        if (rec->next_repeat <= now) rec->next_repeat = now + repeat_interval(*rec);
    }
}

void DeviceCore::send_emulated_starts(const std::vector<uint16_t>& blocks) {
    for (const uint16_t block : blocks) {
        protocol::EffectOperationReport op;
        op.block = block;
        op.operation = protocol::EffectOperation::start;
        op.loop_count = protocol::kLoopEffectOwn;
        (void)send_unanswered(op);
    }
}

void DeviceCore::on_device_status(const protocol::DeviceStatusReport& r) {
    std::lock_guard lock(mu);
    ++input.reports_received;
    input.t_us = static_cast<int64_t>(r.t_us);
    input.axis_count = caps.axis_count;
    for (int i = 0; i < kMaxAxes; ++i) {
        input.force[i] = r.force[i];
        input.velocity[i] = static_cast<float>(r.velocity[i]);
    }
    input.fade_level = static_cast<float>(r.fade_level) / 10000.0f;
    input.handle_held = (r.safety_flags & 1u) != 0;
    input.hands_off = (r.safety_flags & 2u) != 0;
    input.host_lost = (r.safety_flags & 4u) != 0;
    input.paused = (r.safety_flags & 8u) != 0;
    input.actuators_enabled = (r.safety_flags & 16u) != 0;
    input.gain = r.gain;
    input.loop_rate_hz = r.loop_rate_hz;
    input.measured_loop_hz = static_cast<double>(r.measured_rate_millihz) / 1000.0;
    input.overruns = r.overruns;
    if (round_has_joystick) {
        round_has_status = true;
        round_report_number = r.report_number;
    }
}

void DeviceCore::on_effect_states(const protocol::EffectStatesReport& r) {
    std::lock_guard lock(mu);
    ++input.reports_received;
    if (r.page == 0) {
        input.playing_effects = r.playing_effects;
        input.resident_effects = r.resident_effects;
        input.dropped_reports = r.dropped_reports;
    }
    const int n = std::min<int>(r.effect_count, protocol::kEffectsPerStatusReport);
    for (int i = 0; i < n; ++i) {
        auto it = by_block.find(r.effect_block[i]);
        if (it == by_block.end()) continue;
        auto rec = records.find(it->second);
        if (rec == records.end()) continue;
        const auto state = static_cast<runtime::ReportedEffectState>(r.effect_state[i]);
        rec->second->device_playing =
            state == runtime::ReportedEffectState::playing || state == runtime::ReportedEffectState::delayed;
    }
    if (r.page + 1 >= r.pages) {
        // The round's last page: published if its joystick and its own status came first;
        // either way the next round starts afresh.
        if (round_has_joystick && round_has_status && r.report_number == round_report_number) {
            ++input_rounds;
            publish_input_round();
            cv.notify_all();
        }
        round_has_joystick = round_has_status = false;
    }
}

void DeviceCore::on_pid_state(const protocol::PidStateReport& r) {
    std::lock_guard lock(mu);
    ++input.reports_received;
    input.paused = r.device_paused;
    input.actuators_enabled = r.actuators_enabled;
    if (r.block == 0) return;
    auto it = by_block.find(r.block);
    if (it == by_block.end()) return;
    auto rec = records.find(it->second);
    if (rec != records.end()) rec->second->device_playing = r.effect_playing;
}

void DeviceCore::on_dynamic(const protocol::DynamicReportReport& r) {
    // A dynamic with more than kDynamicAxesPerReport axes comes in parts, first_axis 0
    // first, all with one t_us: the event waits for its last part.
    constexpr int kPerReport = protocol::kDynamicAxesPerReport;
    const int axes = std::min<int>(r.axis_count, kMaxAxes);
    if (r.first_axis == 0) {
        dynamic_first_part.reset();
        if (axes > kPerReport) {
            dynamic_first_part = r;
            return;
        }
    } else if (!dynamic_first_part || dynamic_first_part->block != r.block || dynamic_first_part->t_us != r.t_us ||
               r.first_axis != kPerReport) {
        dynamic_first_part.reset();
        note_protocol_problem("a dynamic report's later part without its first");
        return;
    }
    DynamicEvent event;
    uint64_t key = 0;
    {
        std::lock_guard lock(mu);
        ++input.reports_received;
        auto it = by_block.find(r.block);
        if (it != by_block.end()) key = it->second;
    }
    event.kind = r.final_report ? DynamicReport::Kind::final : DynamicReport::Kind::interim;
    event.t_us = static_cast<int64_t>(r.t_us);
    event.axis_count = axes;
    for (int i = 0; i < event.axis_count; ++i) {
        const bool in_first = r.first_axis != 0 && i < kPerReport;
        const protocol::DynamicReportReport& part = in_first ? *dynamic_first_part : r;
        const int slot = in_first ? i : i - r.first_axis;
        if (slot < 0 || slot >= kPerReport) continue;
        event.position[i] = static_cast<float>(part.position_centi[slot]) / 100.0f;
        event.velocity[i] = static_cast<float>(part.velocity_centi[slot]) / 100.0f;
        event.handle_velocity[i] = static_cast<float>(part.handle_velocity_centi[slot]) / 100.0f;
    }
    dynamic_first_part.reset();
    dispatch_dynamic(key, event);
}

void DeviceCore::dispatch_dynamic(uint64_t key, const DynamicEvent& event) {
    std::lock_guard lock(dispatch_mu);
    // Copy the ids first: a callback may unsubscribe (itself or another).
    std::vector<uint64_t> ids;
    ids.reserve(subscribers.size());
    for (const auto& [id, sub] : subscribers) {
        if (sub.effect_key == 0 || (key != 0 && sub.effect_key == key)) ids.push_back(id);
    }
    for (const uint64_t id : ids) {
        auto it = subscribers.find(id);
        if (it == subscribers.end()) continue;
        DynamicCallback callback = it->second.callback;  // survives the callback unsubscribing
        try {
            callback(event);
        } catch (...) {
            // A throwing callback must not end the I/O thread; its exception is dropped.
        }
    }
}

}  // namespace feel::host
