// EffectParams and device commands as a PID device's own reports (pid_effect_reports.hpp).
#include "feel/protocol/pid_effect_reports.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "hid_usages.hpp"

namespace feel::protocol::pid {
namespace {

namespace u = usage::pid;

std::optional<std::vector<uint8_t>> finish(const PidReportWriter& w, std::string& error) {
    if (!w.ok()) {
        error = w.error();
        return std::nullopt;
    }
    return w.bytes();
}

bool has_periodic_block(EffectType t) { return is_periodic(t); }
bool has_condition_block(EffectType t) {
    return t == EffectType::spring || t == EffectType::damper || t == EffectType::inertia || t == EffectType::friction;
}

// The polar angle (hundredths of a degree, compass: from +y clockwise) of a 2-axis vector.
int32_t polar_of(int32_t x, int32_t y) {
    double degrees = std::atan2(static_cast<double>(x), static_cast<double>(y)) * 180.0 / 3.14159265358979323846;
    if (degrees < 0) degrees += 360.0;
    const auto centi = static_cast<int32_t>(std::lround(degrees * 100.0));
    return centi >= 36000 ? 0 : centi;
}

// Trigger Button and Trigger Repeat Interval (PID 1.0: the button that starts the effect,
// and how often it starts again while held). No trigger leaves Trigger Button 0: "none" on
// a 0..n field, the null on a 1..n one.
bool trigger_fields(const PidLayout& layout, const EffectParams& p, PidReportWriter& w, std::string& error) {
    if (p.trigger.kind == TriggerKind::none) return true;
    if (p.trigger.kind == TriggerKind::hat) {
        error = "trigger: a hat switch; PID's Trigger Button names a button only (the host runs hat triggers)";
        return false;
    }
    const FieldPlace button = layout.find(PidReport::set_effect, u::kTriggerButton);
    if (!button) {
        error = "trigger: the device's Set Effect has no Trigger Button (0x53) (the host runs such triggers)";
        return false;
    }
    if (p.trigger.index < button.field->logical_min || p.trigger.index > button.field->logical_max) {
        error = "trigger.index: button " + std::to_string(p.trigger.index) + " is out of the device's Trigger Button range (allowed " +
                std::to_string(button.field->logical_min) + ".." + std::to_string(button.field->logical_max) + ")";
        return false;
    }
    w.set(u::kTriggerButton, p.trigger.index, Scale::raw);
    const bool repeats = p.trigger_repeat_interval_us != 0;
    if (repeats && !layout.find(PidReport::set_effect, u::kTriggerRepeatInterval)) {
        error = "trigger_repeat_interval_us: the device's Set Effect has no Trigger Repeat Interval (0x54)";
        return false;
    }
    w.set(u::kTriggerRepeatInterval, p.trigger_repeat_interval_us, Scale::time, false);
    if (!w.ok()) {
        error = "trigger_repeat_interval_us " + std::to_string(p.trigger_repeat_interval_us) + ": " + w.error();
        return false;
    }
    return true;
}

bool set_effect_report(const PidLayout& layout, uint16_t block, const EffectParams& p, uint32_t type_usage,
                       std::vector<OutgoingReport>& out, std::string& error) {
    PidReportWriter w(layout, PidReport::set_effect);
    w.set(u::kEffectBlockIndex, block, Scale::raw);
    w.select(u::kEffectType, type_usage);
    w.set_time_or_infinite(u::kDuration, p.duration_us);
    w.set(u::kGain, p.gain, Scale::level);
    // Optional fields: absent is fine when the value is their default.
    w.set(u::kStartDelay, p.start_delay_us, Scale::time, p.start_delay_us != 0);
    if (!w.ok()) {
        error = w.error();
        return false;
    }
    if (!trigger_fields(layout, p, w, error)) return false;
    // A custom force's sample period is Set Effect's too (PID 1.0 has it in both).
    w.set(u::kSamplePeriod, p.type == EffectType::force_profile ? p.custom.sample_period_us : 0, Scale::time, false);
    // Axes Enable: the effect's axes.
    for (int i = 0; i < p.axis_count && i < kMaxAxes; ++i) {
        const uint32_t axis_usage = usage::gd::kX + static_cast<uint32_t>(p.axes[i]);
        const std::vector<Axis>& named = layout.axes();
        if (!named.empty() && std::find(named.begin(), named.end(), p.axes[i]) == named.end()) {
            error = "axes[" + std::to_string(i) + "]: the device's Axes Enable does not name axis " +
                    std::string(axis_name(p.axes[i]));
            return false;
        }
        if (!w.set(axis_usage, 1, Scale::raw, false, u::kAxesEnable)) break;
    }
    // Direction: PID's polar angle (Ordinal 1 of Direction), from where the force comes,
    // clockwise from +y in hundredths of a degree, as feel's polar direction is (§6.5).
    int32_t angle = 0;
    bool directed = true;
    switch (p.direction.kind) {
        case DirectionKind::none: directed = false; break;
        case DirectionKind::polar: angle = p.direction.value[0]; break;
        case DirectionKind::cartesian:
            if (p.axis_count != 2) {
                error = "direction: a cartesian direction on " + std::to_string(p.axis_count) +
                        " axes has no PID polar angle (allowed: 2 axes, or a polar direction)";
                return false;
            }
            angle = polar_of(p.direction.value[0], p.direction.value[1]);
            break;
        case DirectionKind::spherical:
        case DirectionKind::moments:
            error = "direction: spherical and moment directions are feel's; a standard PID device takes a polar angle";
            return false;
    }
    w.set(u::kDirectionEnable, directed ? 1 : 0, Scale::raw, directed);
    if (directed) w.set(usage::ordinal(1), angle, Scale::angle, true, u::kDirection);
    if (!w.ok()) {
        error = w.error();
        return false;
    }
    out.push_back({PidReport::set_effect, w.bytes()});
    return true;
}

bool condition_reports(const PidLayout& layout, uint16_t block, const EffectParams& p,
                       std::vector<OutgoingReport>& out, std::string& error) {
    // With a direction, one block applies along it (§3.1): axis 0's alone.
    const int blocks = is_directed_condition(p) ? 1 : p.axis_count;
    for (int i = 0; i < blocks; ++i) {
        const ConditionBlock& c = p.conditions[i];
        const std::string where = "conditions[" + std::to_string(i) + "]";
        if (c.offset_mode == OffsetMode::relative) {
            error = where + ".offset_mode: relative offsets are feel's; a standard PID device measures from the center";
            return false;
        }
        PidReportWriter w(layout, PidReport::set_condition);
        w.set(u::kEffectBlockIndex, block, Scale::raw);
        // The axis: Parameter Block Offset (hid-pidff's way), or Type Specific Block Offset.
        if (layout.find(PidReport::set_condition, u::kParameterBlockOffset)) {
            w.set(u::kParameterBlockOffset, i, Scale::raw);
        } else if (i > 0) {
            error = where + ": the device's Set Condition names no axis (no Parameter Block Offset): one block only";
            return false;
        }
        w.set(u::kCpOffset, c.offset, Scale::level);
        w.set(u::kPositiveCoefficient, c.pos_coefficient, Scale::level);
        w.set(u::kPositiveSaturation, c.pos_saturation, Scale::level, c.pos_saturation != kFullScale);
        w.set(u::kDeadBand, c.deadband, Scale::level, c.deadband != 0);
        // A device without the negative side plays the positive one on both.
        w.set(u::kNegativeCoefficient, c.neg_coefficient, Scale::level, c.neg_coefficient != c.pos_coefficient);
        w.set(u::kNegativeSaturation, c.neg_saturation, Scale::level, c.neg_saturation != c.pos_saturation);
        if (!w.ok()) {
            error = where + ": " + w.error();
            return false;
        }
        out.push_back({PidReport::set_condition, w.bytes()});
    }
    return true;
}

// A force profile as the device's sample stream: the elements of its Custom Force Data, in
// order, and the Sample Count (ProfileSamples says both formats).
struct SampleStream {
    std::vector<int16_t> elements;
    int64_t sample_count = 0;
};

bool sample_stream(const PidLayout& layout, const EffectParams& p, const ProfileSamples& samples, SampleStream& out,
                   std::string& error) {
    const CustomBlock& c = p.custom;
    if (samples.values.size() != static_cast<std::size_t>(c.sample_count) || c.channels < 1 ||
        c.sample_count % c.channels != 0) {
        error = "custom.samples: " + std::to_string(samples.values.size()) + " samples passed, custom.sample_count is " +
                std::to_string(c.sample_count) + " on " + std::to_string(c.channels) + " channels";
        return false;
    }
    if (samples.feel_format) {
        out.elements.assign(samples.values.begin(), samples.values.end());
        out.sample_count = c.sample_count;
        return true;
    }
    // One value per axis of the device's sample format; channel i drives the effect's axis i.
    const std::vector<Axis> format = layout.sample_axes();
    if (c.channels == 1 && p.axis_count > 1) {
        error = "custom.channels: 1 channel on " + std::to_string(p.axis_count) +
                " axes (along a direction); a standard device's sample holds one value per axis: give one channel "
                "per axis (custom.channels = " + std::to_string(p.axis_count) + ")";
        return false;
    }
    std::vector<int> slot(static_cast<std::size_t>(c.channels), -1);
    for (int i = 0; i < c.channels; ++i) {
        const auto at = std::find(format.begin(), format.end(), p.axes[i]);
        if (at == format.end()) {
            error = "axes[" + std::to_string(i) + "]: the device's custom force sample (Download Force Sample) has no " +
                    std::string(axis_name(p.axes[i])) + " value";
            return false;
        }
        slot[static_cast<std::size_t>(i)] = static_cast<int>(at - format.begin());
    }
    const std::size_t frames = static_cast<std::size_t>(c.sample_count / c.channels);
    out.elements.assign(frames * format.size(), 0);
    for (std::size_t f = 0; f < frames; ++f)
        for (std::size_t i = 0; i < slot.size(); ++i)
            out.elements[f * format.size() + static_cast<std::size_t>(slot[i])] =
                samples.values[f * static_cast<std::size_t>(c.channels) + i];
    out.sample_count = static_cast<int64_t>(frames);
    return true;
}

std::optional<int64_t> stream_bytes(const PidLayout& layout, const SampleStream& stream) {
    const FieldPlace data = layout.find(PidReport::custom_force_data, u::kCustomForceData);
    if (!data) return std::nullopt;
    return (static_cast<int64_t>(stream.elements.size()) * data.field->report_size + 7) / 8;
}

// Custom Force Data reports (the stream, a report's worth of elements at a time), then Set
// Custom Force.
bool custom_force_reports(const PidLayout& layout, uint16_t block, const EffectParams& p, const ProfileSamples& samples,
                          std::vector<OutgoingReport>& out, std::string& error) {
    SampleStream stream;
    if (!sample_stream(layout, p, samples, stream, error)) return false;
    const FieldPlace data = layout.find(PidReport::custom_force_data, u::kCustomForceData);
    if (!data) {
        error = "custom: the device declares no Custom Force Data (0x69)";
        return false;
    }
    const std::size_t per_report = data.field->report_count - data.element;
    for (std::size_t at = 0; at < stream.elements.size(); at += per_report) {
        const std::size_t n = std::min(per_report, stream.elements.size() - at);
        PidReportWriter w(layout, PidReport::custom_force_data);
        w.set(u::kEffectBlockIndex, block, Scale::raw);
        w.set(u::kCustomForceDataOffset, static_cast<int64_t>(at), Scale::raw);
        if (samples.feel_format) w.set(usage::vendor::kDataCount, static_cast<int64_t>(n), Scale::raw);
        for (std::size_t k = 0; k < n; ++k)
            w.set_element(u::kCustomForceData, static_cast<uint32_t>(k), stream.elements[at + k], Scale::level);
        if (!w.ok()) {
            error = "custom.samples[" + std::to_string(at) + ".." + std::to_string(at + n - 1) + "]: " + w.error();
            return false;
        }
        out.push_back({PidReport::custom_force_data, w.bytes()});
    }
    PidReportWriter w(layout, PidReport::set_custom_force);
    w.set(u::kEffectBlockIndex, block, Scale::raw);
    if (samples.feel_format) w.set(usage::vendor::kChannels, p.custom.channels, Scale::raw);
    w.set(u::kSampleCount, stream.sample_count, Scale::raw);
    if (!w.ok()) {
        error = "custom.sample_count: " + std::to_string(stream.sample_count) + " samples: " + w.error();
        return false;
    }
    const FieldPlace period = layout.find(PidReport::set_custom_force, u::kSamplePeriod);
    if (period && time_to_logical(*period.field, p.custom.sample_period_us) == 0) {
        error = "custom.sample_period_us: " + std::to_string(p.custom.sample_period_us) +
                " µs is below the device's Sample Period resolution (its field counts " +
                (time_to_logical(*period.field, 1000) == 1 ? std::string("milliseconds") : std::string("coarser units")) + ")";
        return false;
    }
    w.set(u::kSamplePeriod, p.custom.sample_period_us, Scale::time);
    if (!w.ok()) {
        error = "custom.sample_period_us: " + w.error();
        return false;
    }
    out.push_back({PidReport::set_custom_force, w.bytes()});
    return true;
}

}  // namespace

bool device_runs_trigger(const PidLayout& layout, const Trigger& trigger) noexcept {
    return trigger.kind == TriggerKind::button && layout.find(PidReport::set_effect, u::kTriggerButton);
}

std::optional<int64_t> custom_force_bytes(const PidLayout& layout, const EffectParams& params,
                                          const ProfileSamples& samples, std::string& error) {
    SampleStream stream;
    if (!sample_stream(layout, params, samples, stream, error)) return std::nullopt;
    const std::optional<int64_t> bytes = stream_bytes(layout, stream);
    if (!bytes) {
        error = "custom: the device declares no Custom Force Data (0x69)";
        return std::nullopt;
    }
    if (const FieldPlace count = layout.find(PidReport::create_new_effect, usage::gd::kByteCount)) {
        if (*bytes > count.field->logical_max) {
            error = "custom.sample_count: " + std::to_string(params.custom.sample_count) + " samples are " +
                    std::to_string(*bytes) + " bytes of Custom Force Data; the device's Create New Effect Byte Count "
                    "holds " + std::to_string(count.field->logical_min) + ".." + std::to_string(count.field->logical_max);
            return std::nullopt;
        }
    }
    return bytes;
}

std::optional<std::vector<uint8_t>> create_new_effect(const PidLayout& layout, EffectType type, std::string& error,
                                                      int64_t byte_count) {
    const std::optional<uint32_t> type_usage = pid_type_usage(type);
    if (!type_usage || !layout.supports(type)) {
        error = "the device does not play " + std::string(effect_type_name(type)) + " (its descriptor's Effect Type lists " +
                std::to_string(layout.effect_types().size()) + " types)";
        return std::nullopt;
    }
    PidReportWriter w(layout, PidReport::create_new_effect);
    w.select(u::kEffectType, *type_usage);
    w.set(usage::gd::kByteCount, byte_count, Scale::raw, false);
    return finish(w, error);
}

std::vector<OutgoingReport> effect_reports(const PidLayout& layout, uint16_t block, const EffectParams& p,
                                           std::string& error, const ProfileSamples& samples) {
    std::vector<OutgoingReport> out;
    const std::optional<uint32_t> type_usage = pid_type_usage(p.type);
    if (!type_usage || !layout.supports(p.type)) {
        error = "type: the device does not play " + std::string(effect_type_name(p.type));
        return {};
    }
    auto writer_error = [&](const PidReportWriter& w, std::string_view where) {
        error = std::string(where) + ": " + w.error();
        return std::vector<OutgoingReport>{};
    };
    if (p.type == EffectType::force_profile) {
        if (!custom_force_reports(layout, block, p, samples, out, error)) return {};
    } else if (has_condition_block(p.type)) {
        if (!condition_reports(layout, block, p, out, error)) return {};
    } else if (has_periodic_block(p.type)) {
        PidReportWriter w(layout, PidReport::set_periodic);
        w.set(u::kEffectBlockIndex, block, Scale::raw);
        w.set(u::kMagnitude, p.periodic.magnitude, Scale::level);
        w.set(u::kOffset, p.periodic.offset, Scale::level, p.periodic.offset != 0);
        w.set(u::kPhase, p.periodic.phase, Scale::angle, p.periodic.phase != 0);
        w.set(u::kPeriod, p.periodic.period_us, Scale::time);
        if (!w.ok()) return writer_error(w, "periodic");
        out.push_back({PidReport::set_periodic, w.bytes()});
    } else if (p.type == EffectType::constant) {
        std::string why;
        std::optional<std::vector<uint8_t>> bytes = set_constant_force(layout, block, p.constant.magnitude, why);
        if (!bytes) {
            error = "constant: " + why;
            return {};
        }
        out.push_back({PidReport::set_constant_force, std::move(*bytes)});
    } else if (p.type == EffectType::ramp) {
        PidReportWriter w(layout, PidReport::set_ramp_force);
        w.set(u::kEffectBlockIndex, block, Scale::raw);
        w.set(u::kRampStart, p.ramp.start, Scale::level);
        w.set(u::kRampEnd, p.ramp.end, Scale::level);
        if (!w.ok()) return writer_error(w, "ramp");
        out.push_back({PidReport::set_ramp_force, w.bytes()});
    }
    if (supports_envelope(p.type) && !has_condition_block(p.type)) {
        const bool present = layout.report(PidReport::set_envelope).present;
        if (p.has_envelope && !present) {
            error = "envelope: the device declares no Set Envelope report";
            return {};
        }
        if (present) {
            // Always sent, so that a block reused from an effect with an envelope loses it:
            // times 0 are no envelope.
            const Envelope e = p.has_envelope ? p.envelope : Envelope{};
            PidReportWriter w(layout, PidReport::set_envelope);
            w.set(u::kEffectBlockIndex, block, Scale::raw);
            w.set(u::kAttackLevel, e.impulse_level, Scale::level);
            w.set(u::kAttackTime, e.settle_time_us, Scale::time);
            w.set(u::kFadeLevel, e.fade_level, Scale::level);
            w.set(u::kFadeTime, e.fade_time_us, Scale::time);
            if (!w.ok()) return writer_error(w, "envelope");
            out.push_back({PidReport::set_envelope, w.bytes()});
        }
    }
    if (!set_effect_report(layout, block, p, *type_usage, out, error)) return {};
    return out;
}

std::optional<std::vector<uint8_t>> effect_operation(const PidLayout& layout, uint16_t block, Operation operation,
                                                     int32_t loop_count, std::string& error) {
    PidReportWriter w(layout, PidReport::effect_operation);
    w.set(u::kEffectBlockIndex, block, Scale::raw);
    const uint32_t op = operation == Operation::start        ? u::kOpEffectStart
                        : operation == Operation::start_solo ? u::kOpEffectStartSolo
                                                             : u::kOpEffectStop;
    w.select(u::kEffectOperation, op);
    if (operation != Operation::stop) {
        const FieldPlace loop = layout.find(PidReport::effect_operation, u::kLoopCount);
        if (loop_count == kInfiniteIterations) {
            if (!loop) {
                error = "Effect Operation: the device has no Loop Count, so it cannot play until stopped";
                return std::nullopt;
            }
            const uint32_t size = std::min<uint32_t>(loop.field->report_size, 62);
            const int64_t all_ones = (int64_t{1} << size) - 1;
            // The field's null when it has one (out of range), else its maximum: PID's 8-bit
            // Loop Count reads 255 as "until stopped".
            if (all_ones > loop.field->logical_max) {
                w.set_time_or_infinite(u::kLoopCount, kInfiniteUs);
            } else {
                w.set(u::kLoopCount, loop.field->logical_max, Scale::raw);
            }
        } else {
            if (loop && loop_count >= loop.field->logical_max && (int64_t{1} << loop.field->report_size) - 1 ==
                                                                      loop.field->logical_max) {
                error = "iterations: " + std::to_string(loop_count) + " on this device's Loop Count (0.." +
                        std::to_string(loop.field->logical_max) + ", whose maximum means until stopped): allowed 1.." +
                        std::to_string(loop.field->logical_max - 1) + " or infinite";
                return std::nullopt;
            }
            w.set(u::kLoopCount, loop_count, Scale::raw, loop_count != 1);
        }
    }
    return finish(w, error);
}

std::optional<std::vector<uint8_t>> set_constant_force(const PidLayout& layout, uint16_t block, int32_t magnitude,
                                                       std::string& error) {
    PidReportWriter w(layout, PidReport::set_constant_force);
    w.set(u::kEffectBlockIndex, block, Scale::raw);
    w.set(u::kMagnitude, magnitude, Scale::level);
    return finish(w, error);
}

std::optional<std::vector<uint8_t>> block_free(const PidLayout& layout, uint16_t block, std::string& error) {
    PidReportWriter w(layout, PidReport::block_free);
    w.set(u::kEffectBlockIndex, block, Scale::raw);
    return finish(w, error);
}

std::optional<std::vector<uint8_t>> device_control(const PidLayout& layout, runtime::DeviceControl control,
                                                   std::string& error) {
    uint32_t usage_value = u::kDcStopAllEffects;
    switch (control) {
        case runtime::DeviceControl::actuators_on: usage_value = u::kDcEnableActuators; break;
        case runtime::DeviceControl::actuators_off: usage_value = u::kDcDisableActuators; break;
        case runtime::DeviceControl::stop_all: usage_value = u::kDcStopAllEffects; break;
        case runtime::DeviceControl::reset: usage_value = u::kDcDeviceReset; break;
        case runtime::DeviceControl::pause: usage_value = u::kDcDevicePause; break;
        case runtime::DeviceControl::resume: usage_value = u::kDcDeviceContinue; break;
    }
    PidReportWriter w(layout, PidReport::device_control);
    w.select(u::kPidDeviceControl, usage_value);
    return finish(w, error);
}

std::optional<std::vector<uint8_t>> device_gain(const PidLayout& layout, int32_t gain, std::string& error) {
    if (gain < 0 || gain > kFullScale) {
        error = "gain " + std::to_string(gain) + " is out of range (allowed 0..10000)";
        return std::nullopt;
    }
    PidReportWriter w(layout, PidReport::device_gain);
    w.set(u::kDeviceGain, gain, Scale::level);
    return finish(w, error);
}

std::optional<BlockLoad> read_block_load(const PidLayout& layout, std::span<const uint8_t> bytes) {
    const std::optional<int64_t> block = read_field(layout, PidReport::block_load, bytes, u::kEffectBlockIndex);
    if (!block || *block < 0 || *block > 0xFFFF) return std::nullopt;
    BlockLoad out;
    out.block = static_cast<uint16_t>(*block);
    const std::optional<uint32_t> status = read_selection(layout, PidReport::block_load, bytes, u::kBlockLoadStatus);
    if (status == u::kBlockLoadSuccess) out.status = BlockLoad::Status::success;
    else if (status == u::kBlockLoadFull) out.status = BlockLoad::Status::full;
    else if (status == u::kBlockLoadError) out.status = BlockLoad::Status::error;
    out.ram_pool_available = read_field(layout, PidReport::block_load, bytes, u::kRamPoolAvailable);
    return out;
}

Pool read_pool(const PidLayout& layout, std::span<const uint8_t> bytes) {
    Pool out;
    out.ram_pool_size = read_field(layout, PidReport::pool, bytes, u::kRamPoolSize);
    out.simultaneous_effects_max = read_field(layout, PidReport::pool, bytes, u::kSimultaneousEffectsMax);
    if (auto v = read_field(layout, PidReport::pool, bytes, u::kDeviceManagedPool)) out.device_managed_pool = *v != 0;
    if (auto v = read_field(layout, PidReport::pool, bytes, u::kSharedParameterBlocks)) out.shared_parameter_blocks = *v != 0;
    return out;
}

}  // namespace feel::protocol::pid
