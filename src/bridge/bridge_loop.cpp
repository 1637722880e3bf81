// The bridge loop: the kernel's requests to the effect table, the device's state to input
// events.
//
// One thread does everything, in turn: wait up to input_poll_ms for the kernel (uinput
// requests block the game's ioctl until answered, so each is answered as it comes), then
// turn the device's latest input state (which the host's I/O thread keeps, no round trip)
// into EV_ABS and EV_KEY events when it changed. The host API serializes calls per device,
// so no lock is needed here.
#include <linux/input.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "bridge_effects.hpp"
#include "feel/bridge/bridge.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/transport/transport.hpp"
#include "ff_translation.hpp"
#include "uinput_backend.hpp"
#include "wire_log.hpp"

namespace feel::bridge {
namespace {

std::string ff_name(uint16_t bit) {
    switch (bit) {
        case FF_CONSTANT: return "constant";
        case FF_PERIODIC: return "periodic";
        case FF_RAMP: return "ramp";
        case FF_SPRING: return "spring";
        case FF_DAMPER: return "damper";
        case FF_INERTIA: return "inertia";
        case FF_FRICTION: return "friction";
        case FF_RUMBLE: return "rumble";
        case FF_GAIN: return "gain";
        case FF_AUTOCENTER: return "autocenter";
        case FF_SQUARE: return "square";
        case FF_TRIANGLE: return "triangle";
        case FF_SINE: return "sine";
        case FF_SAW_UP: return "saw_up";
        case FF_SAW_DOWN: return "saw_down";
        default: return std::to_string(bit);
    }
}

UinputSpec spec_of(const host::DeviceCaps& caps, const FfCapabilities& ff, const BridgeOptions& options) {
    UinputSpec spec;
    spec.name = options.name.empty() ? "feel " + caps.device + " (bridge)" : options.name;
    for (int32_t i = 0; i < caps.axis_count; ++i) spec.axes.push_back(abs_of_axis(i));
    for (int32_t b = 1; b <= caps.button_count; ++b) spec.buttons.push_back(key_of_button(b));
    spec.ff_bits = ff.bits;
    spec.max_effects = static_cast<uint32_t>(std::clamp<int32_t>(caps.effect_slots, 1, FF_MAX_EFFECTS));
    return spec;
}

}  // namespace

host::Result<host::Device> open_device(const std::string& address, std::ostream* wire_log) {
    if (wire_log == nullptr) return host::Device::open(address);
    const transport::Address where = transport::Address::parse(address);
    std::unique_ptr<transport::Connection> connection;
    try {
        if (where.kind == transport::Address::Kind::sim) {
            peripheral::PeripheralOptions options;
            options.profile = where.profile;
            connection = peripheral::open_in_process(options);
        } else {
            connection = transport::connect(where, std::chrono::milliseconds(2000));
        }
    } catch (const transport::TransportError& e) {
        return host::Status::failure(host::ErrorKind::disconnected, e.what());
    }
    return host::Device::attach(std::make_unique<WireLog>(std::move(connection), *wire_log), where.to_string());
}

BridgeStats run_bridge(host::Device& device, const BridgeOptions& options,
                       const std::function<void(const std::string&)>& say,
                       const std::function<void(const std::string&)>& warn, const std::atomic<bool>& stop) {
    if (options.input_poll_ms < 1 || options.input_poll_ms > 100) {
        throw std::invalid_argument("input_poll_ms = " + std::to_string(options.input_poll_ms) +
                                    " is out of range (allowed 1..100)");
    }
    const host::DeviceCaps& caps = device.capabilities();
    const FfCapabilities ff = ff_capabilities(caps);
    const UinputSpec spec = spec_of(caps, ff, options);
    UinputDevice uinput(spec, options.uinput_path);
    {
        std::ostringstream banner;
        banner << "feel bridge: " << caps.device << " (" << caps.class_name << ") at " << device.address() << " as "
               << (uinput.event_node().empty() ? "an input device" : uinput.event_node()) << " \"" << spec.name
               << "\": " << caps.axis_count << " axes, " << caps.button_count << " buttons, " << spec.max_effects
               << " effects; force feedback:";
        for (uint16_t bit : ff.bits) banner << ' ' << ff_name(bit);
        if (!ff.missing.empty()) {
            banner << "; not offered (the device lacks them):";
            for (const std::string& m : ff.missing) banner << ' ' << m;
        }
        say(banner.str());
    }

    BridgeStats stats;
    BridgeEffects effects(device, [&](const std::string& line) { warn("feel bridge: " + line); });
    int32_t sent_position[kMaxAxes] = {};
    uint32_t sent_buttons = 0;
    bool first_state = true;
    int64_t last_state_us = -1;
    while (!stop.load(std::memory_order_relaxed)) {
        for (const UinputRequest& r : uinput.wait(options.input_poll_ms)) {
            switch (r.kind) {
                case UinputRequest::Kind::upload: {
                    std::optional<ff_effect> e = uinput.begin_upload(r.request_id);
                    if (!e) break;  // the game gave up waiting
                    ++stats.uploads;
                    const int result = effects.upload(*e);
                    if (result != 0) ++stats.uploads_refused;
                    if (options.verbose) say("upload " + describe_ff_effect(*e) + (result == 0 ? ": ok" : ": refused"));
                    uinput.end_upload(r.request_id, *e, result);
                    break;
                }
                case UinputRequest::Kind::erase: {
                    std::optional<int16_t> id = uinput.begin_erase(r.request_id);
                    if (!id) break;
                    ++stats.erases;
                    uinput.end_erase(r.request_id, *id, effects.erase(*id));
                    if (options.verbose) say("erase id " + std::to_string(*id));
                    break;
                }
                case UinputRequest::Kind::play:
                    ++stats.plays;
                    effects.play(r.code, r.value);
                    if (options.verbose) {
                        say((r.value > 0 ? "play id " : "stop id ") + std::to_string(r.code) +
                            (r.value > 0 ? " " + std::to_string(r.value) + " times" : std::string()));
                    }
                    break;
                case UinputRequest::Kind::gain:
                    // ff-core keeps gain and autocenter within 0..0xFFFF; the clamp only narrows the type.
                    effects.set_gain(static_cast<uint16_t>(std::clamp(r.value, 0, 0xffff)));
                    if (options.verbose) say("gain " + std::to_string(r.value));
                    break;
                case UinputRequest::Kind::autocenter:
                    effects.set_autocenter(static_cast<uint16_t>(std::clamp(r.value, 0, 0xffff)));
                    if (options.verbose) say("autocenter " + std::to_string(r.value));
                    break;
            }
        }
        if (!device.connected()) throw std::runtime_error("the device at " + device.address() + " is gone");
        const host::InputState state = device.input();
        if (state.t_us == last_state_us) continue;
        last_state_us = state.t_us;
        for (int32_t i = 0; i < std::min(state.axis_count, caps.axis_count); ++i) {
            const auto v = static_cast<int32_t>(std::lround(state.position[i]));
            if (first_state || v != sent_position[i]) uinput.emit(EV_ABS, abs_of_axis(i), v);
            sent_position[i] = v;
        }
        for (int32_t b = 1; b <= caps.button_count; ++b) {
            const uint32_t bit = 1u << (b - 1);
            if (first_state || ((state.buttons ^ sent_buttons) & bit) != 0) {
                uinput.emit(EV_KEY, key_of_button(b), (state.buttons & bit) != 0 ? 1 : 0);
            }
        }
        sent_buttons = state.buttons;
        first_state = false;
        uinput.sync();
        ++stats.input_reports;
    }
    return stats;
}

}  // namespace feel::bridge
