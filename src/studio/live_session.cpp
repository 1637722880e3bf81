// One browser's live session (live_session.hpp).
#include "live_session.hpp"

#include <chrono>
#include <cmath>
#include <cstddef>
#include <exception>
#include <algorithm>
#include <iterator>
#include <optional>
#include <utility>

#include "feel/effect_type.hpp"
#include "feel/engine.hpp"
#include "import_request.hpp"
#include "export_request.hpp"
#include "protocol_check.hpp"

namespace feel::studio {
namespace {

using json = nlohmann::json;
constexpr size_t kMaxFrameSamples = 1000;  // the schema allows 2000

json error_reply(const std::string& message, std::string_view request = {}) {
    json e = {{"type", "error"}, {"message", message.substr(0, 2000)}};
    if (!request.empty()) e["request"] = request;
    return e;
}

// The fields of `after` that differ from `before`, as effect_field bits.
uint32_t changed_fields(const EffectParams& before, const EffectParams& after, bool samples_changed) {
    using namespace effect_field;
    uint32_t mask = 0;
    if (before.duration_us != after.duration_us) mask |= kDuration;
    if (before.start_delay_us != after.start_delay_us) mask |= kStartDelay;
    if (before.gain != after.gain) mask |= kGain;
    if (before.iterations != after.iterations) mask |= kIterations;
    bool axes = before.axis_count != after.axis_count;
    for (int a = 0; a < after.axis_count && !axes; ++a) axes = before.axes[a] != after.axes[a];
    if (axes) mask |= kAxes;
    if (!(before.direction == after.direction)) mask |= kDirection;
    if (!(before.trigger == after.trigger)) mask |= kTrigger;
    if (before.trigger_repeat_interval_us != after.trigger_repeat_interval_us) mask |= kTriggerRepeat;
    if (before.has_envelope != after.has_envelope || !(before.envelope == after.envelope)) mask |= kEnvelope;
    // The type's block: everything else. Copy the common fields over and compare the rest.
    EffectParams rest = before;
    rest.duration_us = after.duration_us;
    rest.start_delay_us = after.start_delay_us;
    rest.gain = after.gain;
    rest.iterations = after.iterations;
    rest.axis_count = after.axis_count;
    for (int a = 0; a < kMaxAxes; ++a) rest.axes[a] = after.axes[a];
    rest.direction = after.direction;
    rest.trigger = after.trigger;
    rest.trigger_repeat_interval_us = after.trigger_repeat_interval_us;
    rest.has_envelope = after.has_envelope;
    rest.envelope = after.envelope;
    if (!(rest == after) || samples_changed) mask |= kTypeSpecific;
    return mask;
}

// Splits a format message ("ORIGIN: sensation \"NAME\": effects[1].periodic.magnitude = ...")
// into the effect's index and the field path; the message itself is kept whole.
json locate(const std::string& message, bool compound) {
    json out = {{"effect", -1}, {"field", ""}, {"message", message}};
    const size_t s = message.find("sensation \"");
    if (s == std::string::npos) return out;
    const size_t close = message.find("\": ", s + 11);
    if (close == std::string::npos) return out;
    std::string rest = message.substr(close + 3);
    int effect = 0;
    if (rest.starts_with("effects[")) {
        const size_t end = rest.find(']');
        try {
            effect = std::stoi(rest.substr(8, end - 8));
        } catch (const std::exception&) {
            return out;
        }
        rest = end + 1 < rest.size() && rest[end + 1] == '.' ? rest.substr(end + 2) : "";
    } else if (compound) {
        effect = -1;
    }
    const size_t stop = rest.find_first_of(" :");
    out["effect"] = effect;
    out["field"] = rest.substr(0, stop);
    return out;
}

}  // namespace

void DynamicInbox::push(size_t effect, const host::DynamicEvent& e) {
    json position = json::array(), velocity = json::array(), handle_velocity = json::array();
    for (int a = 0; a < e.axis_count && a < kMaxAxes; ++a) {
        position.push_back(e.position[a]);
        velocity.push_back(e.velocity[a]);
        handle_velocity.push_back(e.handle_velocity[a]);
    }
    json r = {{"effect", effect},
              {"kind", e.kind == DynamicReport::Kind::interim ? "interim" : "final"},
              {"t_ms", static_cast<double>(e.t_us) / 1000.0},
              {"position", position},
              {"velocity", velocity},
              {"handle_velocity", handle_velocity}};
    std::lock_guard lock(mu);
    if (reports.size() >= kMax) reports.erase(reports.begin());
    reports.push_back(std::move(r));
}

std::vector<json> DynamicInbox::take() {
    std::lock_guard lock(mu);
    return std::exchange(reports, {});
}

LiveSession::LiveSession(std::shared_ptr<StudioDevice> device, const ProtocolSchema& schema)
    : device_(std::move(device)), schema_(schema), last_sample_(device_->newest_seq()) {}

LiveSession::~LiveSession() {
    // A lost browser stops what it started: its effects go (RAII), its buttons come up.
    if (buttons_ != 0) (void)device_->set_buttons(0);
    if (hats_ != 0) (void)device_->set_hats(0);
    slots_.clear();
}

const host::Effect* LiveSession::effect(size_t i) const noexcept {
    return i < slots_.size() && slots_[i].effect ? &*slots_[i].effect : nullptr;
}

EffectParams LiveSession::device_params(const Slot& slot) const {
    EffectParams p = slot.spec.params;
    if (!slot.armed) {
        p.trigger = {};
        p.trigger_repeat_interval_us = 0;
    }
    return p;
}

std::vector<json> LiveSession::handle(std::string_view text, Clock::time_point received) {
    json m;
    try {
        m = json::parse(text);
    } catch (const json::exception& e) {
        return {error_reply(std::string("malformed message: not JSON (") + e.what() + ")")};
    }
    if (auto problem = schema_.problem("client", m)) return {error_reply("malformed message: " + *problem)};
    const std::string type = m["type"].get<std::string>();
    try {
        if (type == "set_sensation") return {set_sensation(m)};
        if (type == "import_file") {
            if (!workspace_) return {error_reply("import_file: this session has no workspace to import into", type)};
            return {import_into_workspace(*workspace_, m)};
        }
        if (type == "export_code") return {export_reply(m)};  // export_request.hpp
        if (type == "pointer") {
            pointer_seq_ = m["seq"].get<int64_t>();
            const DeviceSample before = device_->newest();
            pointer_.taken_before_us = device_->hand_target_taken_us();
            pointer_.take_reported_us.reset();
            if (!device_->set_hand_target(m["x"].get<int32_t>(), m["y"].get<int32_t>())) {
                return {error_reply("the hand of a device in another process is a person's: the pad only shows it",
                                    type)};
            }
            pointer_.read = received;
            pointer_.applied = Clock::now();
            std::copy(std::begin(before.force), std::end(before.force), std::begin(pointer_.force));
            pointer_.answered = false;
            pointer_.min_fade = 1;
            return {};
        }
        if (type == "grip") {
            if (!device_->set_grip(m["grip"].get<std::string>())) {
                return {error_reply("the grip can only be changed on a simulated device", type)};
            }
            return {};
        }
        if (type == "gain") {
            const host::Status s = device_->device().set_gain(m["gain"].get<int32_t>());
            if (!s.ok()) return {error_reply(s.message, type)};
            return {};
        }
        if (type == "button" || type == "hat") {
            const bool is_button = type == "button";
            const int index = m[is_button ? "button" : "hat"].get<int>();
            uint32_t& mask = is_button ? buttons_ : hats_;
            const uint32_t bit = uint32_t{1} << (index - 1);
            const uint32_t next = m["down"].get<bool>() ? (mask | bit) : (mask & ~bit);
            const bool ok = is_button ? device_->set_buttons(next) : device_->set_hats(next);
            if (!ok) {
                const host::DeviceCaps& c = device_->device().capabilities();
                return {error_reply(type + " " + std::to_string(index) + ": the device has " +
                                        std::to_string(is_button ? c.button_count : c.hat_count) + " " + type +
                                        "s" + (device_->simulated() ? "" : " (press the device's own)"),
                                    type)};
            }
            mask = next;
            return {};
        }
        if (type == "stop_all") {
            for (Slot& s : slots_) {
                if (s.effect) (void)s.effect->stop();
                s.playing = false;
            }
            return {};
        }
        const auto index = m["effect"].get<size_t>();
        if (index >= slots_.size() || !slots_[index].effect) {
            return {error_reply(type + ": effect " + std::to_string(index) + " is not on the device (the sensation has " +
                                    std::to_string(slots_.size()) + " valid effects)",
                                type)};
        }
        Slot& slot = slots_[index];
        if (type == "play") {
            const host::Status s = slot.effect->start();
            if (!s.ok()) return {error_reply(s.message, type)};
            slot.playing = true;
            ++slot.starts;
        } else if (type == "stop") {
            const host::Status s = slot.effect->stop();
            if (!s.ok()) return {error_reply(s.message, type)};
            slot.playing = false;
        } else if (type == "arm") {
            slot.armed = m["on"].get<bool>();
            const EffectParams p = device_params(slot);
            const host::Status s = slot.effect->set_parameters(
                p, effect_field::kTrigger | effect_field::kTriggerRepeat, false);
            if (!s.ok()) return {error_reply(s.message, type)};
        }
        return {};
    } catch (const std::exception& e) {
        return {error_reply(type + ": " + e.what(), type)};
    }
}

json LiveSession::set_sensation(const json& m) {
    const auto started = std::chrono::steady_clock::now();
    const json& effects = m["effects"];
    const std::string name = m["name"].get<std::string>();
    const std::string origin = m.contains("file") ? m["file"].get<std::string>() : std::string("(unsaved)");
    json reply = {{"type", "validated"}, {"seq", m["seq"]}, {"ok", true}, {"errors", json::array()},
                  {"apply_us", 0}, {"restarted", json::array()}};
    format::Sensation parsed;
    if (!effects.empty()) {
        const bool compound = effects.size() > 1;
        json sensation = compound ? json{{"effects", effects}} : effects[0];
        const json file = {{"format", "feel/1"}, {"sensations", {{name, sensation}}}};
        try {
            parsed = format::parse_sensation_file(file.dump(), origin).sensations.front();
        } catch (const format::FormatError& e) {
            reply["ok"] = false;
            reply["errors"].push_back(locate(e.what(), compound));
            return reply;  // the device keeps the last valid sensation
        }
    }
    // Valid: bring the device's effects in line, by index.
    while (slots_.size() > parsed.effects.size()) slots_.pop_back();
    slots_.resize(parsed.effects.size());
    for (size_t i = 0; i < parsed.effects.size(); ++i) {
        bool restarted = false;
        if (auto problem = apply(i, parsed.effects[i], restarted)) {
            reply["ok"] = false;
            json where = {{"effect", static_cast<int>(i)}, {"field", ""}, {"message", *problem}};
            reply["errors"].push_back(where);
        }
        if (restarted) reply["restarted"].push_back(i);
    }
    reply["apply_us"] =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
    return reply;
}

std::optional<std::string> LiveSession::apply(size_t index, const format::EffectSpec& spec, bool& restarted) {
    Slot& slot = slots_[index];
    const bool samples_changed = slot.spec.samples != spec.samples;
    const EffectParams before = slot.effect ? slot.effect->parameters() : EffectParams{};
    slot.spec = spec;
    const EffectParams wanted = device_params(slot);
    if (slot.effect && slot.effect->valid() && before.type == wanted.type && before.axis_count == wanted.axis_count) {
        const uint32_t mask = changed_fields(before, wanted, samples_changed);
        if (mask == 0) return std::nullopt;
        const host::Status s = slot.effect->set_parameters(wanted, mask, false, spec.samples);
        if (s.ok()) return std::nullopt;
        if (s.kind != host::ErrorKind::invalid_parameter && s.kind != host::ErrorKind::not_supported) {
            return s.message;
        }
        // A change the effect cannot take in place: a new effect below.
    }
    const bool was_playing = slot.playing;
    slot.effect.reset();
    auto made = device_->device().create_effect(wanted, spec.samples);
    if (!made) {
        slot.playing = false;
        return made.status().message;
    }
    slot.effect = std::move(made.value());
    slot.reports = slot.effect->subscribe(
        [inbox = inbox_, index](const host::DynamicEvent& e) { inbox->push(index, e); });
    if (was_playing) {
        if (slot.effect->start().ok()) {
            ++slot.starts;
            restarted = true;
        } else {
            slot.playing = false;
        }
    }
    return std::nullopt;
}

json LiveSession::effect_states() {
    json out = json::array();
    for (Slot& s : slots_) {
        json e = {{"state", "none"}, {"starts", s.starts}, {"armed", s.armed}, {"elapsed_us", 0}};
        if (s.effect) {
            auto st = s.effect->status();
            if (st) {
                e["state"] = runtime::reported_effect_state_name(st->state);
                e["elapsed_us"] = st->elapsed_us;
                if (st->state == runtime::ReportedEffectState::stopped) s.playing = false;
            }
        }
        out.push_back(e);
    }
    return out;
}

namespace {

int64_t steady_us(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration_cast<std::chrono::microseconds>(t.time_since_epoch()).count();
}

double us_between(std::chrono::steady_clock::time_point from, std::chrono::steady_clock::time_point to) {
    return std::chrono::duration<double, std::micro>(to - from).count();
}

// Wall-clock µs of a steady time: the browser's performance.timeOrigin + now() is on the
// wall clock, so the two sockets' shares can be told apart on one machine.
double wall_us(std::chrono::steady_clock::time_point t) {
    const auto wall_now = std::chrono::system_clock::now();
    const auto steady_now = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::micro>(wall_now.time_since_epoch()).count() - us_between(t, steady_now);
}

}  // namespace

// The force of report `s` moved from the one when the pointer's target was set by more than
// the browser's probe threshold (0.2% of full scale): the report answers the pointer.
static bool force_moved(const DeviceSample& s, const float (&before)[kMaxAxes]) {
    for (int a = 0; a < s.axis_count && a < kMaxAxes; ++a) {
        if (std::fabs(s.force[a] - before[a]) > 20) return true;
    }
    return false;
}

bool LiveSession::pointer_answer_ready() const {
    if (pointer_.answered) return false;
    const DeviceSample s = device_->newest();
    return s.seq > last_sample_ && s.host_us >= steady_us(pointer_.applied) &&
           after_take(s, device_->hand_target_taken_us()) && force_moved(s, pointer_.force);
}

// A report can answer the newest pointer message only if its tick came after the device's
// loop took that message's target: a force still moving from the previous target (a hand
// still settling) is not this message's answer. A device in another process cannot say
// when it took a target (a person's hand holds it): any report after the message counts.
bool LiveSession::after_take(const DeviceSample& s, int64_t taken_us) const {
    if (!device_->simulated()) return true;
    return taken_us >= 0 && taken_us != pointer_.taken_before_us && s.t_us >= taken_us;
}

json LiveSession::state_frame(bool* pointer_answered, bool* news) {
    std::vector<DeviceSample> samples = device_->samples_after(last_sample_);
    if (samples.size() > kMaxFrameSamples) {  // a browser that fell behind gets the newest
        samples.erase(samples.begin(), samples.end() - static_cast<std::ptrdiff_t>(kMaxFrameSamples));
    }
    json rows = json::array();
    json force = json::array(), position = json::array();
    uint32_t buttons = 0;
    double t_us = 0;
    // The first report, taken after the pointer's target was handed to the hand, whose
    // force moved (by more than the browser's probe threshold, 0.2% of full scale).
    std::optional<int64_t> force_seen_us;
    int64_t force_seen_transit_us = 0;
    int64_t force_seen_device_us = 0;  // that report's tick, device time
    const int64_t applied_us = steady_us(pointer_.applied);
    // read before the reports: a report of the taking tick implies the take is stored
    const int64_t taken_us = device_->hand_target_taken_us();
    bool changed = false;
    for (const DeviceSample& s : samples) {
        json row = json::array({static_cast<double>(s.t_us) / 1000.0});
        bool row_changed = !shown_.any || s.buttons != shown_.buttons;
        shown_.any = true;
        shown_.buttons = s.buttons;
        for (int a = 0; a < s.axis_count; ++a) {
            const long f = std::lround(s.force[a]);
            row_changed = row_changed || f != shown_.force[a];
            shown_.force[a] = f;
            row.push_back(f);
        }
        for (int a = 0; a < s.axis_count; ++a) {
            const long x = std::lround(s.position[a]);
            row_changed = row_changed || x != shown_.position[a];
            shown_.position[a] = x;
            row.push_back(x);
        }
        changed = changed || row_changed;
        rows.push_back(std::move(row));
        last_sample_ = s.seq;
        const int64_t offset = s.host_us - s.t_us;
        if (!min_offset_us_ || offset < *min_offset_us_) min_offset_us_ = offset;
        if (!pointer_.answered && !force_seen_us && s.host_us >= applied_us) {
            const bool answers = after_take(s, taken_us);
            if (answers && !pointer_.take_reported_us) pointer_.take_reported_us = s.host_us;
            pointer_.min_fade = std::min(pointer_.min_fade, s.fade_level);
            if (answers && force_moved(s, pointer_.force)) {
                force_seen_us = s.host_us;
                force_seen_transit_us = offset - *min_offset_us_;
                force_seen_device_us = s.t_us;
            }
        }
    }
    // The newest state even when no report came since the last frame (a sampler that waited
    // for a core): a frame without a position would leave the pad with none.
    const DeviceSample newest = samples.empty() ? device_->newest() : samples.back();
    if (newest.seq != 0) {
        const DeviceSample& s = newest;
        for (int a = 0; a < s.axis_count; ++a) {
            force.push_back(s.force[a]);
            position.push_back(s.position[a]);
        }
        buttons = s.buttons;
        t_us = static_cast<double>(s.t_us);
    }
    // Effect states cost a round trip each to the device: 10 times a second.
    if (const auto now = Clock::now(); now - effect_states_at_ >= std::chrono::milliseconds(100)) {
        last_effect_states_ = effect_states();
        effect_states_at_ = now;
    }
    std::string effects_key;
    for (const json& e : last_effect_states_) {
        effects_key += e["state"].get<std::string>() + ':' + std::to_string(e["starts"].get<int64_t>()) +
                       (e["armed"].get<bool>() ? "a;" : ";");
    }
    if (effects_key != shown_.effects) {
        changed = true;
        shown_.effects = std::move(effects_key);
    }
    std::vector<json> dynamics = inbox_->take();
    changed = changed || !dynamics.empty() || !pointer_written_.is_null();
    // Without news the reports were all the newest one but for their time: the page needs
    // only that one (its plot draws a flat line through the rest).
    if (!changed && rows.size() > 1) rows.erase(rows.begin(), rows.end() - 1);
    // The quiet's last report goes ahead of the news that ends it, so that the plot knows
    // the quiet lasted until then (an onset lies after it), unless a keep-alive sent it.
    if (!changed) {
        if (!rows.empty()) quiet_row_ = rows.back();
    } else if (!quiet_row_.is_null()) {
        rows.insert(rows.begin(), std::exchange(quiet_row_, nullptr));
    }
    const auto built = Clock::now();
    const double pointer_age_us = pointer_seq_ == 0 ? 0.0 : us_between(pointer_.read, built);
    json frame = {{"type", "state"},       {"t_us", t_us}, {"samples", rows},
                  {"position", position},  {"force", force},     {"buttons", buttons},
                  {"pointer_seq", pointer_seq_}, {"pointer_age_us", pointer_age_us},
                  {"effects", last_effect_states_}, {"dynamics", std::move(dynamics)},
                  {"dropped_reports", device_->dropped_reports()}};
    if (force_seen_us) {
        pointer_.answered = true;
        // Of the device hop, on the device's own clock (exact): the loop's tick that took
        // the target -> the tick whose report has the new force (the handle's motion). -1
        // when the device cannot say (a device in another process).
        const int64_t loop_us = taken_us < 0 ? -1 : force_seen_device_us - taken_us;
        // The software path on the server's clock: the target set -> the report of the
        // tick that took it in the sampler (the wait for the tick, the report's way out).
        // -1 when the device cannot say.
        const int64_t software_us =
            pointer_.take_reported_us && device_->simulated() ? *pointer_.take_reported_us - applied_us : -1;
        frame["pointer_hops"] = {{"seq", pointer_seq_},
                                 {"read_wall_us", wall_us(pointer_.read)},
                                 {"built_wall_us", wall_us(built)},
                                 {"apply_us", us_between(pointer_.read, pointer_.applied)},
                                 {"device_us", static_cast<double>(*force_seen_us - applied_us)},
                                 {"transit_us", static_cast<double>(force_seen_transit_us)},
                                 {"loop_us", static_cast<double>(loop_us)},
                                 {"software_us", static_cast<double>(software_us)},
                                 {"taken_t_us", static_cast<double>(taken_us)},
                                 {"min_fade", pointer_.min_fade},
                                 {"frame_us", static_cast<double>(steady_us(built) - *force_seen_us)}};
    }
    if (pointer_answered) *pointer_answered = force_seen_us.has_value();
    if (news) *news = changed || force_seen_us.has_value();
    if (!pointer_written_.is_null()) frame["pointer_written"] = std::exchange(pointer_written_, nullptr);
    return frame;
}

void LiveSession::note_pointer_written(int64_t seq, size_t ahead, double write_us) {
    pointer_written_ = {{"seq", seq}, {"ahead", ahead}, {"write_us", write_us}};
}

}  // namespace feel::studio
