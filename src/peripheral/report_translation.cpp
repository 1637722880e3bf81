// Host reports -> effect block parameters (report_translation.hpp).
#include "report_translation.hpp"

#include <algorithm>
#include <type_traits>
#include <utility>
#include <variant>

#include "feel/units.hpp"

namespace feel::peripheral::detail {
namespace {

using protocol::ReportId;

std::string block_words(uint16_t block, EffectType type) {
    return "block " + std::to_string(block) + " holds a " + std::string(effect_type_name(type)) + " effect";
}

bool is_condition_with_blocks(EffectType t) noexcept {
    return t == EffectType::spring || t == EffectType::damper || t == EffectType::inertia ||
           t == EffectType::friction || t == EffectType::angle_spring;
}

// The types each type block is for, as words for the refusal.
const char* fitting_types(ReportId id) noexcept {
    switch (id) {
        case ReportId::set_condition: return "spring, damper, inertia, friction and angle_spring effects";
        case ReportId::set_periodic: return "periodic and sweep effects";
        case ReportId::set_sweep: return "sweep effects";
        case ReportId::set_constant_force: return "constant, vector_force and smart_pop effects";
        case ReportId::set_ramp_force: return "ramp effects";
        case ReportId::set_custom_force:
        case ReportId::custom_force_data: return "force_profile effects";
        case ReportId::set_texture: return "texture effects";
        case ReportId::set_wall: return "axis_wall and angle_wall effects";
        case ReportId::set_barrier: return "axis_barrier and angle_barrier effects";
        case ReportId::set_dynamic: return "dynamic effects";
        case ReportId::set_control_law: return "dynamic_control_law effects";
        case ReportId::set_envelope: return "the effect types with an envelope (§6.4: waves but the force profile)";
        default: break;
    }
    return "no effect type";
}

bool fits(ReportId id, EffectType t) noexcept {
    switch (id) {
        case ReportId::set_condition: return is_condition_with_blocks(t);
        case ReportId::set_periodic: return is_periodic(t) || is_sweep(t);
        case ReportId::set_sweep: return is_sweep(t);
        case ReportId::set_constant_force:
            return t == EffectType::constant || t == EffectType::vector_force || t == EffectType::smart_pop;
        case ReportId::set_ramp_force: return t == EffectType::ramp;
        case ReportId::set_custom_force:
        case ReportId::custom_force_data: return t == EffectType::force_profile;
        case ReportId::set_texture: return t == EffectType::texture;
        case ReportId::set_wall: return t == EffectType::axis_wall || t == EffectType::angle_wall;
        case ReportId::set_barrier: return t == EffectType::axis_barrier || t == EffectType::angle_barrier;
        case ReportId::set_dynamic: return effect_class(t) == EffectClass::dynamic;
        case ReportId::set_control_law: return t == EffectType::dynamic_control_law;
        case ReportId::set_envelope: return supports_envelope(t);
        default: break;
    }
    return false;
}

int64_t wire_time(uint32_t us) noexcept { return us == protocol::kWireInfinite ? kInfiniteUs : int64_t{us}; }

Refusal missing(uint16_t block, EffectType type, std::string report, const std::string& what) {
    return Refusal::of(ErrorCode::invalid_parameter, std::move(report),
                       block_words(block, type) + " whose " + what +
                           " has not arrived: send it before the first Set Effect");
}

}  // namespace

Refusal Refusal::out_of_range(std::string field, int64_t value, Range allowed) {
    Refusal r;
    r.code = ErrorCode::invalid_parameter;
    r.field = std::move(field);
    r.has_range = true;
    r.value = value;
    r.allowed = allowed;
    return r;
}

Refusal Refusal::of(ErrorCode code, std::string field, std::string rule) {
    Refusal r;
    r.code = code;
    r.field = std::move(field);
    r.rule = std::move(rule);
    return r;
}

std::string_view report_key(ReportId id) noexcept {
    switch (id) {
        case ReportId::set_effect: return "set_effect";
        case ReportId::set_envelope: return "set_envelope";
        case ReportId::set_condition: return "set_condition";
        case ReportId::set_periodic: return "set_periodic";
        case ReportId::set_constant_force: return "set_constant_force";
        case ReportId::set_ramp_force: return "set_ramp_force";
        case ReportId::set_custom_force: return "set_custom_force";
        case ReportId::custom_force_data: return "custom_force_data";
        case ReportId::download_force_sample: return "download_force_sample";
        case ReportId::effect_operation: return "effect_operation";
        case ReportId::block_free: return "block_free";
        case ReportId::device_control: return "device_control";
        case ReportId::device_gain: return "device_gain";
        case ReportId::set_texture: return "set_texture";
        case ReportId::set_wall: return "set_wall";
        case ReportId::set_barrier: return "set_barrier";
        case ReportId::set_sweep: return "set_sweep";
        case ReportId::set_dynamic: return "set_dynamic";
        case ReportId::set_control_law: return "set_control_law";
        case ReportId::reflex: return "reflex";
        case ReportId::idf_settings: return "idf_settings";
        case ReportId::report_rate: return "report_rate";
        case ReportId::keep_alive: return "keep_alive";
        case ReportId::effect_status_request: return "effect_status_request";
        case ReportId::create_new_effect: return "create_new_effect";
        case ReportId::block_load: return "block_load";
        case ReportId::pid_pool: return "pid_pool";
        case ReportId::device_info: return "device_info";
        case ReportId::joystick_input: return "joystick_input";
        case ReportId::pid_state: return "pid_state";
        case ReportId::command_status: return "command_status";
        case ReportId::device_status: return "device_status";
        case ReportId::dynamic_report: return "dynamic_report";
        case ReportId::command_error_text: return "command_error_text";
        case ReportId::effect_states: return "effect_states";
    }
    return "report";
}

uint16_t report_block(const protocol::AnyReport& report) noexcept {
    return std::visit(
        [](const auto& r) -> uint16_t {
            if constexpr (requires { r.block; r.sequence; }) {
                return r.block;
            } else {
                return 0;
            }
        },
        report);
}

uint32_t report_sequence(const protocol::AnyReport& report) noexcept {
    return std::visit(
        [](const auto& r) -> uint32_t {
            if constexpr (requires { r.sequence; }) {
                return r.sequence;
            } else {
                return 0;
            }
        },
        report);
}

std::optional<Refusal> check_type_block_fits(ReportId id, EffectType type, uint16_t block) {
    if (fits(id, type)) return std::nullopt;
    return Refusal::of(ErrorCode::invalid_parameter, std::string(report_key(id)),
                       block_words(block, type) + "; this report is for " + fitting_types(id));
}

std::optional<Refusal> check_type_block_values(const protocol::AnyReport& report, EffectType type) {
    const auto* periodic = std::get_if<protocol::SetPeriodicReport>(&report);
    if (periodic == nullptr || periodic->magnitude >= 0) return std::nullopt;
    if (type != EffectType::saw_up && type != EffectType::saw_down) return std::nullopt;
    // A saw upside down is the other saw (-saw_up(p) = saw_down(p)), which no phase gives:
    // the slope's sign is the type's, and an effect's type never changes.
    const bool up = type == EffectType::saw_up;
    Refusal why = Refusal::out_of_range("set_periodic.magnitude", periodic->magnitude, range::kLevel);
    why.rule = std::string("inverted, a ") + (up ? "saw_up is a saw_down" : "saw_down is a saw_up") +
               " and a type never changes: create a " + (up ? "saw_down" : "saw_up") + " instead";
    return why;
}

void apply_type_block(const protocol::AnyReport& report, Block& block) {
    EffectParams& p = block.shadow;
    Arrivals& a = block.arrived;
    std::visit(
        [&](const auto& r) {
            using R = std::decay_t<decltype(r)>;
            if constexpr (std::is_same_v<R, protocol::SetEnvelopeReport>) {
                p.envelope.impulse_level = r.impulse_level;
                p.envelope.settle_time_us = r.settle_time_us;
                p.envelope.fade_level = r.fade_level;
                p.envelope.fade_time_us = r.fade_time_us;
                a.envelope = true;
            } else if constexpr (std::is_same_v<R, protocol::SetConditionReport>) {
                if (r.axis_index >= kMaxAxes) return;  // decode bounds it; never index past the table
                ConditionBlock& c = p.conditions[r.axis_index];
                c.offset = r.center_offset;
                c.pos_coefficient = r.pos_coefficient;
                c.neg_coefficient = r.neg_coefficient;
                c.pos_saturation = r.pos_saturation;
                c.neg_saturation = r.neg_saturation;
                c.deadband = r.deadband;
                c.offset_mode = r.offset_mode;
                a.conditions = static_cast<uint8_t>(a.conditions | (1u << r.axis_index));
            } else if constexpr (std::is_same_v<R, protocol::SetPeriodicReport>) {
                const int32_t phase = r.phase == 36000 ? 0 : r.phase;  // 360° (a standard host's) is 0°
                p.periodic.magnitude = r.magnitude;
                p.periodic.offset = r.offset;
                p.periodic.phase = phase;
                if (is_periodic(block.type) && r.magnitude < 0) {
                    // PID's Magnitude is signed; a negative one is the wave upside down (evdev's
                    // negative periodic magnitude). A sine, square or triangle upside down is the
                    // same wave half a period on: -w(p) = w(p + 1/2). The offset stays. Saws were
                    // refused before (check_type_block_values).
                    p.periodic.magnitude = -r.magnitude;
                    p.periodic.phase = (phase + 18000) % 36000;
                }
                p.periodic.period_us = r.period_us;
                a.periodic = true;
            } else if constexpr (std::is_same_v<R, protocol::SetSweepReport>) {
                p.periodic.sweep_start_angle = r.start_angle;
                p.periodic.sweep_end_angle = r.end_angle;
                p.periodic.sweep_sense = r.sense;
                a.sweep = true;
            } else if constexpr (std::is_same_v<R, protocol::SetConstantForceReport>) {
                p.constant.magnitude = r.magnitude;
                a.constant = true;
            } else if constexpr (std::is_same_v<R, protocol::SetRampForceReport>) {
                p.ramp.start = r.start;
                p.ramp.end = r.end;
                a.ramp = true;
            } else if constexpr (std::is_same_v<R, protocol::SetCustomForceReport>) {
                p.custom.channels = r.channels;
                p.custom.sample_period_us = r.sample_period_us;
                p.custom.sample_count = r.sample_count;
                block.sample_count = r.sample_count;
                a.custom = true;
            } else if constexpr (std::is_same_v<R, protocol::SetTextureReport>) {
                p.texture = r.texture;
                a.texture = true;
            } else if constexpr (std::is_same_v<R, protocol::SetWallReport>) {
                p.wall = r.wall;
                a.wall = true;
            } else if constexpr (std::is_same_v<R, protocol::SetBarrierReport>) {
                p.barrier = r.barrier;
                a.barrier = true;
            } else if constexpr (std::is_same_v<R, protocol::SetDynamicReport>) {
                // Set Control Law carries the laws; this report's are placeholders.
                ControlLawBlock laws[kMaxAxes];
                std::copy(std::begin(p.dynamic.control_law), std::end(p.dynamic.control_law), laws);
                p.dynamic = r.dynamic;
                std::copy(std::begin(laws), std::end(laws), p.dynamic.control_law);
                a.dynamic = true;
            } else if constexpr (std::is_same_v<R, protocol::SetControlLawReport>) {
                if (r.axis_index >= kMaxAxes) return;
                p.dynamic.control_law[r.axis_index] = r.law;
                a.control_laws = static_cast<uint8_t>(a.control_laws | (1u << r.axis_index));
            }
        },
        report);
}

void apply_set_effect(const protocol::SetEffectReport& r, EffectParams& p, const runtime::Capabilities& device) {
    // A standard PID host (Linux's hid-pidff) writes evdev's values: duration 0 is evdev's
    // "infinite", iterations 0 is "not given" (once), an angle of 36000 is 360° (docs/protocol.md,
    // "Standard hosts").
    p.duration_us = r.duration_us == 0 ? kInfiniteUs : wire_time(r.duration_us);
    p.start_delay_us = r.start_delay_us;
    p.trigger_repeat_interval_us = r.trigger_repeat_interval_us;
    p.gain = r.gain;
    p.iterations = r.iterations == protocol::kLoopInfinite ? kInfiniteIterations
                   : r.iterations == 0                      ? 1
                                                            : int32_t{r.iterations};
    p.trigger.kind = r.trigger_kind;
    p.trigger.index = r.trigger_index;
    // A standard PID host names a reflex by Trigger Button alone (PID 1.0: the button that
    // starts the effect, 0 none) and leaves feel's trigger kind 0: a button.
    if (p.trigger.kind == TriggerKind::none && r.trigger_index != 0) p.trigger.kind = TriggerKind::button;
    p.axis_count = r.axis_count;
    std::copy(std::begin(r.axes), std::end(r.axes), p.axes);
    if (r.axis_count == 0) {
        p.axis_count = 0;
        const int device_axes = std::clamp(device.axis_count, 1, kMaxAxes);
        for (int k = 0; k < device_axes && r.axes_enable != 0; ++k) {
            if (((r.axes_enable >> static_cast<int>(device.axes[k].axis)) & 1u) != 0) p.axes[p.axis_count++] = device.axes[k].axis;
        }
        if (p.axis_count == 0) {  // no Axes Enable (check_axes_enable refused one naming none of the device's)
            p.axis_count = std::clamp(device.axis_count, 1, 2);
            for (int a = 0; a < p.axis_count; ++a) p.axes[a] = device.axes[a].axis;
        }
    }
    p.direction.kind = r.direction_kind;
    std::copy(std::begin(r.direction), std::end(r.direction), p.direction.value);
    if (p.direction.kind == DirectionKind::polar || p.direction.kind == DirectionKind::spherical) {
        for (int32_t& angle : p.direction.value) angle = angle == 36000 ? 0 : angle;
    }
    p.has_envelope = r.has_envelope;
}

std::optional<Refusal> check_axes_enable(const protocol::SetEffectReport& r, const runtime::Capabilities& device) {
    if (r.axes_enable == 0) return std::nullopt;
    if (r.axis_count >= 1) {
        uint8_t mask = 0;
        for (int i = 0; i < r.axis_count && i < kMaxAxes; ++i) {
            mask = static_cast<uint8_t>(mask | (1u << static_cast<int>(r.axes[i])));
        }
        if (r.axes_enable == mask) return std::nullopt;
        Refusal why = Refusal::of(ErrorCode::invalid_parameter, "set_effect.axes_enable",
                                  "must be 0 or name exactly the effect's axes (axes[0..axis_count))");
        why.value = r.axes_enable;
        return why;
    }
    const int device_axes = std::clamp(device.axis_count, 1, kMaxAxes);
    for (int k = 0; k < device_axes; ++k) {
        if (((r.axes_enable >> static_cast<int>(device.axes[k].axis)) & 1u) != 0) return std::nullopt;
    }
    Refusal why = Refusal::of(ErrorCode::invalid_parameter, "set_effect.axes_enable", "names no axis this device has");
    why.value = r.axes_enable;
    return why;
}

void ignore_direction_of_per_axis_conditions(EffectType type, uint8_t conditions_arrived, EffectParams& p) noexcept {
    // angle_spring is not here: its direction is the spring's angle.
    if (type != EffectType::spring && type != EffectType::damper && type != EffectType::inertia &&
        type != EffectType::friction) {
        return;
    }
    const int axes = p.axis_count >= 1 && p.axis_count <= kMaxAxes ? p.axis_count : 1;
    for (int i = 0; i < axes; ++i) {
        if ((conditions_arrived & (1u << i)) == 0) return;  // check_blocks_complete names the missing one
    }
    p.direction = Direction{};
}

std::optional<Refusal> check_conditions_within_axes(const protocol::SetEffectReport& r, EffectType type,
                                                    uint8_t conditions_arrived, const EffectParams& next) {
    if (r.axis_count == 0 || !is_condition_with_blocks(type)) return std::nullopt;  // a standard host's: ignored
    const int axes = next.axis_count >= 1 && next.axis_count <= kMaxAxes ? next.axis_count : 1;
    for (int i = axes; i < kMaxAxes; ++i) {
        if ((conditions_arrived & (1u << i)) == 0) continue;
        Refusal why = Refusal::out_of_range("set_condition.axis_index", i, {0, axes - 1});
        why.rule = "a Set Condition came for an axis the effect does not have (one per axis of the effect)";
        return why;
    }
    return std::nullopt;
}

std::optional<Refusal> check_blocks_complete(const Block& block, const EffectParams& next, uint16_t index) {
    const EffectType t = block.type;
    const Arrivals& a = block.arrived;
    const int axes = next.axis_count >= 1 && next.axis_count <= kMaxAxes ? next.axis_count : 1;
    if (t == EffectType::angle_spring) {
        if ((a.conditions & 1u) == 0) return missing(index, t, "set_condition", "Set Condition (axis 0)");
    } else if (is_condition_with_blocks(t)) {
        // One Set Condition (axis 0) and a direction on 2 or more axes: the condition with a
        // direction (§3.1), its block applied along it.
        if (is_directed_condition(next) && axes >= 2 && a.conditions == 1u) return std::nullopt;
        for (int i = 0; i < axes; ++i) {
            if ((a.conditions & (1u << i)) == 0) {
                return missing(index, t, "set_condition",
                               "Set Condition for axis " + std::to_string(i) +
                                   " (one per axis of the effect; or axis 0's alone, with a direction)");
            }
        }
    } else if (is_periodic(t) || is_sweep(t)) {
        if (!a.periodic) return missing(index, t, "set_periodic", "Set Periodic");
        if (is_sweep(t) && !a.sweep) return missing(index, t, "set_sweep", "Set Sweep");
    } else if (t == EffectType::constant || t == EffectType::vector_force || t == EffectType::smart_pop) {
        if (!a.constant) return missing(index, t, "set_constant_force", "Set Constant Force");
    } else if (t == EffectType::ramp) {
        if (!a.ramp) return missing(index, t, "set_ramp_force", "Set Ramp Force");
    } else if (t == EffectType::force_profile) {
        if (!a.custom) return missing(index, t, "set_custom_force", "Set Custom Force");
    } else if (t == EffectType::texture) {
        if (!a.texture) return missing(index, t, "set_texture", "Set Texture");
    } else if (t == EffectType::axis_wall || t == EffectType::angle_wall) {
        if (!a.wall) return missing(index, t, "set_wall", "Set Wall");
    } else if (t == EffectType::axis_barrier || t == EffectType::angle_barrier) {
        if (!a.barrier) return missing(index, t, "set_barrier", "Set Barrier");
    } else if (t == EffectType::dynamic_control_law) {
        for (int i = 0; i < axes; ++i) {
            if ((a.control_laws & (1u << i)) == 0) {
                return missing(index, t, "set_control_law",
                               "Set Control Law for axis " + std::to_string(i) + " (one per axis of the effect)");
            }
        }
    } else if (effect_class(t) == EffectClass::dynamic) {
        if (!a.dynamic) return missing(index, t, "set_dynamic", "Set Dynamic");
    }
    return std::nullopt;
}

uint32_t changed_fields(const EffectParams& from, const EffectParams& to) noexcept {
    namespace f = effect_field;
    uint32_t mask = 0;
    if (from.duration_us != to.duration_us) mask |= f::kDuration;
    if (from.start_delay_us != to.start_delay_us) mask |= f::kStartDelay;
    if (from.gain != to.gain) mask |= f::kGain;
    if (from.iterations != to.iterations) mask |= f::kIterations;
    if (from.axis_count != to.axis_count || !std::equal(std::begin(from.axes), std::end(from.axes), to.axes)) {
        mask |= f::kAxes;
    }
    if (!(from.direction == to.direction)) mask |= f::kDirection;
    if (!(from.trigger == to.trigger)) mask |= f::kTrigger;
    if (from.trigger_repeat_interval_us != to.trigger_repeat_interval_us) mask |= f::kTriggerRepeat;
    if (from.has_envelope != to.has_envelope || !(from.envelope == to.envelope)) mask |= f::kEnvelope;
    const bool same_blocks = std::equal(std::begin(from.conditions), std::end(from.conditions), to.conditions) &&
                             from.periodic == to.periodic && from.constant == to.constant &&
                             from.ramp == to.ramp && from.custom == to.custom && from.texture == to.texture &&
                             from.wall == to.wall && from.barrier == to.barrier && from.dynamic == to.dynamic;
    if (!same_blocks) mask |= f::kTypeSpecific;
    return mask;
}

int32_t iterations_of_loop_count(uint16_t loop_count) noexcept {
    if (loop_count == protocol::kLoopEffectOwn) return runtime::kEffectIterations;
    if (loop_count == protocol::kLoopInfinite) return kInfiniteIterations;
    return loop_count;
}

std::optional<runtime::DeviceControl> runtime_control(protocol::DeviceControlOp op) noexcept {
    using protocol::DeviceControlOp;
    switch (op) {
        case DeviceControlOp::enable_actuators: return runtime::DeviceControl::actuators_on;
        case DeviceControlOp::disable_actuators: return runtime::DeviceControl::actuators_off;
        case DeviceControlOp::stop_all_effects: return runtime::DeviceControl::stop_all;
        case DeviceControlOp::device_reset: return runtime::DeviceControl::reset;
        case DeviceControlOp::device_pause: return runtime::DeviceControl::pause;
        case DeviceControlOp::device_continue: return runtime::DeviceControl::resume;
    }
    return std::nullopt;
}

}  // namespace feel::peripheral::detail
