// The host's checks of an effect against the device's capabilities.
#include "effect_checks.hpp"

#include <string>

#include "emulation/emulation_config.hpp"
#include "feel/effect_validation.hpp"
#include "host_errors.hpp"

namespace feel::host {
namespace {

std::string axis_list(const DeviceCaps& caps) {
    std::string out;
    for (int i = 0; i < caps.axis_count; ++i) {
        if (i) out += ", ";
        out += axis_name(caps.axes[i].axis);
    }
    return out;
}

std::string supported_list(const DeviceCaps& caps) {
    std::string out;
    const char* classes[] = {"Conditions", "Waves", "Dynamics"};
    for (int c = 0; c < 3; ++c) {
        bool any = false;
        for (int i = 0; i < kEffectTypeCount; ++i) {
            const auto t = static_cast<EffectType>(i);
            if (static_cast<int>(effect_class(t)) == c && can_create(caps, t)) any = true;
        }
        if (!any) continue;
        if (!out.empty()) out += ", ";
        out += classes[c];
    }
    return out.empty() ? std::string("no effects") : out;
}

}  // namespace

std::string effect_label(EffectType type) { return std::string(effect_type_name(type)); }

bool can_create(const DeviceCaps& caps, EffectType type) noexcept {
    // A type the device does not play is rendered by the host (emulation/).
    return caps.supports(type) || emulation::host_renders(caps, type);
}

Status check_effect(const EffectParams& p, std::span<const int16_t> samples, const DeviceCaps& caps,
                    std::string_view what) {
    if (const Error e = validate_effect(p, samples)) return status_from_error(e, what);

    const std::string prefix(what);
    if (!can_create(caps, p.type)) {
        const Error e = Error::of(ErrorCode::not_supported, "type", "not played by this device");
        return Status::failure(ErrorKind::not_supported,
                               prefix + ": the " + caps.class_name + " device \"" + caps.device + "\" does not play " +
                                   effect_label(p.type) + " effects (it plays " + supported_list(caps) + ")",
                               e);
    }
    if (p.axis_count > caps.axis_count) {
        return status_from_error(Error::out_of_range("axis_count", p.axis_count, {1, caps.axis_count}),
                                 prefix + " (the device's axes are " + axis_list(caps) + ")");
    }
    for (int i = 0; i < p.axis_count; ++i) {
        const int index = axis_index(p.axes[i]);
        if (index >= caps.axis_count) {
            const std::string field = "axes[" + std::to_string(i) + "]";
            const Error e = Error::out_of_range(field, index, {0, caps.axis_count - 1});
            return Status::failure(ErrorKind::invalid_parameter,
                                   prefix + ": " + field + " = " + std::string(axis_name(p.axes[i])) +
                                       " is not an axis of this device (allowed " + axis_list(caps) + ")",
                                   e);
        }
    }
    if (p.trigger.kind == TriggerKind::button && p.trigger.index > caps.button_count) {
        const Error e = Error::out_of_range("trigger_button", p.trigger.index, {1, caps.button_count});
        const std::string allowed =
            caps.button_count == 0 ? "the device has no buttons" : "allowed 1.." + std::to_string(caps.button_count);
        return Status::failure(ErrorKind::invalid_parameter,
                               prefix + ": trigger_button = " + std::to_string(p.trigger.index) +
                                   " is out of range (" + allowed + ")",
                               e);
    }
    if (p.trigger.kind == TriggerKind::hat && p.trigger.index > caps.hat_count) {
        const Error e = Error::out_of_range("trigger_button", p.trigger.index, {1, caps.hat_count});
        const std::string allowed = caps.hat_count == 0 ? "the device has no hat switches"
                                                        : "allowed hat1..hat" + std::to_string(caps.hat_count);
        return Status::failure(ErrorKind::invalid_parameter,
                               prefix + ": trigger_button = hat" + std::to_string(p.trigger.index) +
                                   " is out of range (" + allowed + ")",
                               e);
    }
    if (p.type == EffectType::force_profile && p.custom.sample_count > caps.sample_memory) {
        const Error e = Error::out_of_range("custom.sample_count", p.custom.sample_count, {1, caps.sample_memory});
        return Status::failure(ErrorKind::invalid_parameter,
                               prefix + ": " + e.message() + ": more samples than the device's whole sample memory",
                               e);
    }
    return Status::success();
}

}  // namespace feel::host
