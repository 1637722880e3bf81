// The one validator of EffectParams.
//
// Design. Every consumer of an effect description (the sensation-file reader, the engine's
// create(), a future protocol decoder) calls validate_effect(), so the ranges and rules
// live here and nowhere else. It runs on the real-time side, so it never allocates or
// throws: the field path of an error ("conditions[1].deadband") is built in a fixed
// buffer, and rule sentences are string literals.
//
// The checks follow the order a person reads an effect: its type, its timing, its axes,
// its trigger, its envelope, then the block of its type and the direction rules of its
// class. The first problem found is returned; fixing it may reveal the next one.
//
// Only the fields the effect's type reads are checked: a spring does not care what its
// periodic block holds. The ranges are the primer's (§6.3, §6.6, §8) and are spelled as
// the named constants of units.hpp, so an error quotes exactly the range enforced.
//
// The plain fields are a table, not code (effect_field_rules.hpp): each block's fields are
// a list of FieldRule (the member's name, where it lives in the block, its width, and its
// range or list of choices), walked in order by one checker that builds the error's field
// path only when a field fails. On the Cortex-M4 build, where flash is counted
// (docs/firmware.md), one range check written out as code took about 40 bytes (the Range
// passed by value, the Error handed back through each caller); a table row takes 8. What
// is left as code is the rules between fields (directions, axes, the sample count) and
// their sentences.
//
// Direction rules (§6.5) decided here, and documented in docs/sensation-format.md:
//   - A wave on one axis may omit its direction (an "axis wave", §4.2.c); a wave on
//     several axes needs one (an "angle wave").
//   - polar names a compass angle in the x-y plane: it needs exactly the axes x and y.
//   - spherical names two angles in x-y-z space: it needs exactly the axes x, y and z.
//   - cartesian gives one component per axis, for the translational axes x, y, z;
//     moments gives one component per axis for the rotational axes rx, ry, rz (§6.5.d).
//     Either vector must not be zero (it would name no direction).
//   - spring, damper, inertia and friction on 2 or more axes may take a direction: then one
//     block (conditions[0]) acts along it (is_directed_condition); without, one per axis.
//   - Types whose block carries the angle (sweeps, angle_wall, angle_barrier, and the
//     directional dynamics recoil, impact, paddle) play in the x-y plane on the axes x
//     and y and take no separate direction: two sources of truth would disagree. Recoil
//     and impact also play on one axis (the sign of the intensity aims them, the angle is
//     0) and on x, y, z (a spherical direction aims them, the angle is 0); paddle is 2D.
#include "feel/effect_validation.hpp"

#include <cstddef>
#include <cstring>
#include <span>

#include "effect_field_rules.hpp"

namespace feel {
namespace {

// Named one by one, not `using namespace`: in a unity batch a whole namespace would clash
// with the engine's other k-names (effect_field::kGain).
using detail::field_rules::FieldRule;
using detail::field_rules::kChoice;
using detail::field_rules::kChoices;
using detail::field_rules::kRanges;
using detail::field_rules::kOffsetModeChoice;
using detail::field_rules::kBarrierRules;
using detail::field_rules::kBarrierSurfaceRules;
using detail::field_rules::kCenterDriftRules;
using detail::field_rules::kConditionRules;
using detail::field_rules::kConstantRules;
using detail::field_rules::kControlLawRules;
using detail::field_rules::kCustomRules;
using detail::field_rules::kEnvelopeRules;
using detail::field_rules::kImpactRules;
using detail::field_rules::kInertiaRules;
using detail::field_rules::kLiquidRules;
using detail::field_rules::kPaddleRules;
using detail::field_rules::kPeriodicRules;
using detail::field_rules::kRampRules;
using detail::field_rules::kRecoilRules;
using detail::field_rules::kSlingRules;
using detail::field_rules::kSweepRules;
using detail::field_rules::kTextureRules;
using detail::field_rules::kTimingRules;
using detail::field_rules::kWallRules;
using detail::field_rules::kWallSurfaceRules;

// A field path built in place, e.g. Path("conditions").index(1).add(".deadband").
// Its parts are C strings: on the Cortex-M4 at -Os a string_view made of a literal is an
// out-of-line call (strlen) at every call site.
class Path {
public:
    explicit Path(const char* base) noexcept { add(base); }

    Path& add(const char* s) noexcept {
        for (; *s != '\0'; ++s) {
            if (len_ + 1 < sizeof buf_) buf_[len_++] = *s;
        }
        buf_[len_] = '\0';
        return *this;
    }

    // An index is never negative and below 2^31 (an axis, a sample).
    Path& index(int64_t i) noexcept {
        char digits[12] = {};
        size_t n = sizeof digits - 2;
        digits[n] = ']';
        auto u = static_cast<uint32_t>(i);
        do {
            digits[--n] = static_cast<char>('0' + u % 10);
            u /= 10;
        } while (u != 0);
        add("[");
        return add(digits + n);
    }

    [[nodiscard]] const char* c_str() const noexcept { return buf_; }

private:
    char buf_[48] = {};
    size_t len_ = 0;
};

// Every check below returns true when it refuses the effect, having written why into `out`,
// the one Error validate_effect returns: on the Cortex-M4 an Error (88 bytes) handed back by
// value through each caller was copied at every level. The range goes by reference (16
// bytes by value at each call). The refusal is written in place, from the field's C string
// (the bytes Error::invalid and Error::out_of_range write): their string_view of a C string
// was an out-of-line strlen at each call site, and the Error they return a temporary copied
// into `out`.
[[nodiscard]] bool refuse_with(Error& out, const char* field, const char* rule, const Range* allowed,
                               int64_t value) noexcept {
    out = Error{};
    out.code = ErrorCode::invalid_parameter;
    for (size_t i = 0; i + 1 < sizeof out.field && field[i] != '\0'; ++i) out.field[i] = field[i];
    out.rule = rule;
    if (allowed != nullptr) {
        out.value = value;
        out.allowed = *allowed;
        out.has_range = true;
    }
    return true;
}

[[nodiscard]] bool refuse(Error& out, const char* field, const char* rule) noexcept {
    return refuse_with(out, field, rule, nullptr, 0);
}

[[nodiscard]] bool refuse(Error& out, const Path& field, const char* rule) noexcept {
    return refuse(out, field.c_str(), rule);
}

[[nodiscard]] bool in_range(const char* field, int64_t value, const Range& allowed, Error& out) noexcept {
    return !allowed.contains(value) && refuse_with(out, field, "is out of range", &allowed, value);
}

[[nodiscard]] bool in_range(const Path& field, int64_t value, const Range& allowed, Error& out) noexcept {
    return in_range(field.c_str(), value, allowed, out);
}

// --- the field table ------------------------------------------------------------------

// The fields of `block` in `rules`, in order; the first that fails is the error, its field
// named block[index].name (no index when index < 0; the bare name when block is empty).
[[nodiscard]] bool check_fields(const char* block, int index, const void* base,
                                 std::span<const FieldRule> rules, Error& out) noexcept {
    const auto* bytes = static_cast<const unsigned char*>(base);
    for (const FieldRule& r : rules) {
        int64_t value = 0;
        if (r.width == 8) {
            std::memcpy(&value, bytes + r.offset, 8);
        } else if (r.width == 4) {
            int32_t v32 = 0;
            std::memcpy(&v32, bytes + r.offset, 4);
            value = v32;
        } else {
            value = bytes[r.offset];
        }
        const bool choice = r.check >= kChoice;
        const Range allowed = choice ? Range{0, kChoices[r.check - kChoice].last} : kRanges[r.check];
        if (allowed.contains(value)) continue;
        Path field(block);
        if (index >= 0) field.index(index);
        if (*block != '\0') field.add(".");
        field.add(r.name);
        return choice ? refuse(out, field, kChoices[r.check - kChoice].rule) : in_range(field, value, allowed, out);
    }
    return false;
}

[[nodiscard]] bool check_fields(const char* block, const void* base, std::span<const FieldRule> rules, Error& out) noexcept {
    return check_fields(block, -1, base, rules, out);
}

// --- axes -------------------------------------------------------------------------------

[[nodiscard]] bool has_axis(const EffectParams& p, Axis a) noexcept {
    for (int i = 0; i < p.axis_count; ++i) {
        if (p.axes[i] == a) return true;
    }
    return false;
}

// Exactly the axes x and y, in either order (axes are known to be distinct).
[[nodiscard]] bool on_xy(const EffectParams& p) noexcept {
    return p.axis_count == 2 && has_axis(p, Axis::x) && has_axis(p, Axis::y);
}

[[nodiscard]] bool on_xyz(const EffectParams& p) noexcept {
    return p.axis_count == 3 && has_axis(p, Axis::x) && has_axis(p, Axis::y) && has_axis(p, Axis::z);
}

[[nodiscard]] bool is_rotational(Axis a) noexcept {
    return a == Axis::rx || a == Axis::ry || a == Axis::rz;
}

[[nodiscard]] bool all_axes(const EffectParams& p, bool rotational) noexcept {
    for (int i = 0; i < p.axis_count; ++i) {
        if (is_rotational(p.axes[i]) != rotational) return false;
    }
    return true;
}

[[nodiscard]] bool check_axes(const EffectParams& p, Error& out) noexcept {
    if (in_range("axes", p.axis_count, range::kAxisCount, out)) return true;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = static_cast<int>(p.axes[i]);
        if (in_range(Path("axes").index(i), a, Range{0, kMaxAxes - 1}, out)) return true;
        for (int j = 0; j < i; ++j) {
            if (p.axes[j] == p.axes[i]) {
                return refuse(out, Path("axes").index(i),
                                      "an axis may appear only once in an effect's axes");
            }
        }
    }
    return false;
}

// --- common fields ----------------------------------------------------------------------

[[nodiscard]] bool needs_finite_duration(EffectType t) noexcept {
    return t == EffectType::ramp || t == EffectType::smart_pop || is_sweep(t);
}

[[nodiscard]] bool check_timing(const EffectParams& p, Error& out) noexcept {
    if (p.duration_us == kInfiniteUs) {
        if (needs_finite_duration(p.type)) {
            return refuse(out, "duration_us",
                                  "ramp, smart_pop and the sweep waves need a finite duration: "
                                  "they are shaped over it");
        }
    } else if (in_range("duration_us", p.duration_us, range::kDurationUs, out)) {
        return true;
    }
    if (check_fields("", &p, kTimingRules, out)) return true;
    if (p.iterations != kInfiniteIterations) {
        if (in_range("iterations", p.iterations, range::kIterations, out)) return true;
    }
    return false;
}

[[nodiscard]] bool check_trigger(const EffectParams& p, Error& out) noexcept {
    switch (p.trigger.kind) {
        case TriggerKind::none:
            if (p.trigger_repeat_interval_us != 0) {
                return refuse(out, "trigger_repeat_interval_us",
                                      "a repeat interval needs a trigger button to repeat on");
            }
            return false;
        case TriggerKind::button:
            if (in_range("trigger_button", p.trigger.index, range::kTriggerButton, out)) return true;
            break;
        case TriggerKind::hat:
            if (in_range("trigger_button", p.trigger.index, range::kTriggerHat, out)) return true;
            break;
        default:
            return refuse(out, "trigger_button", "the trigger kind must be none, button or hat");
    }
    return in_range("trigger_repeat_interval_us", p.trigger_repeat_interval_us,
                    range::kRepeatIntervalUs, out);
}

[[nodiscard]] bool check_envelope(const EffectParams& p, Error& out) noexcept {
    if (!p.has_envelope) return false;
    if (!supports_envelope(p.type)) {
        return refuse(out, "envelope",
                              "only vector_force, constant, the periodic and sweep waves, "
                              "force_profile and ramp take an envelope (§6.4)");
    }
    return check_fields("envelope", &p.envelope, kEnvelopeRules, out);
}

// --- direction --------------------------------------------------------------------------

// A cartesian or moments vector: one component per axis, each in range, not all zero.
[[nodiscard]] bool check_vector(const EffectParams& p, const char* name, Error& out) noexcept {
    // Distinct axes of one kind are at most three; this guards value[3] all the same.
    if (p.axis_count > 3) {
        return refuse(out, Path("direction.").add(name),
                              "a cartesian or moments direction has at most 3 components, "
                              "one per axis");
    }
    bool any = false;
    for (int i = 0; i < p.axis_count; ++i) {
        const int32_t v = p.direction.value[i];
        if (in_range(Path("direction.").add(name).index(i), v, range::kCartesianComponent, out)) {
            return true;
        }
        any = any || v != 0;
    }
    if (!any) {
        return refuse(out, Path("direction.").add(name),
                              "the zero vector names no direction");
    }
    return false;
}

// The direction is well formed for the effect's axes (whether one is needed is the
// caller's rule).
[[nodiscard]] bool check_direction_form(const EffectParams& p, Error& out) noexcept {
    const Direction& d = p.direction;
    switch (d.kind) {
        case DirectionKind::none:
            return false;
        case DirectionKind::polar:
            if (!on_xy(p)) {
                return refuse(out, "direction.polar",
                                      "a polar direction is a compass angle in the x-y plane: "
                                      "the effect's axes must be x and y");
            }
            return in_range("direction.polar", d.value[0], range::kAngle, out);
        case DirectionKind::spherical:
            if (!on_xyz(p)) {
                return refuse(out, "direction.spherical",
                                      "a spherical direction needs the axes x, y and z (§6.5.c)");
            }
            if (in_range("direction.spherical[0]", d.value[0], range::kAngle, out)) return true;
            return in_range("direction.spherical[1]", d.value[1], range::kElevation, out);
        case DirectionKind::cartesian:
            if (!all_axes(p, false)) {
                return refuse(out, "direction.cartesian",
                                      "a cartesian direction is for the axes x, y, z; "
                                      "use moments for rx, ry, rz (§6.5.d)");
            }
            return check_vector(p, "cartesian", out);
        case DirectionKind::moments:
            if (!all_axes(p, true)) {
                return refuse(out, "direction.moments",
                                      "moments are for the rotational axes rx, ry, rz (§6.5.d)");
            }
            return check_vector(p, "moments", out);
    }
    return refuse(out, "direction", "the direction kind must be none, polar, cartesian, "
                                       "spherical or moments");
}

// A wave on one axis may omit its direction; on several axes it needs one.
[[nodiscard]] bool check_wave_direction(const EffectParams& p, Error& out) noexcept {
    if (p.direction.kind == DirectionKind::none && p.axis_count > 1) {
        return refuse(out, "direction",
                              "a wave on several axes needs a direction (polar, cartesian, "
                              "spherical or moments)");
    }
    return check_direction_form(p, out);
}

[[nodiscard]] bool no_direction(const EffectParams& p, const char* rule, Error& out) noexcept {
    return p.direction.kind != DirectionKind::none && refuse(out, "direction", rule);
}

[[nodiscard]] bool needs_xy(const EffectParams& p, const char* rule, Error& out) noexcept {
    return !on_xy(p) && refuse(out, "axes", rule);
}

[[nodiscard]] bool needs_one_axis(const EffectParams& p, const char* rule, Error& out) noexcept {
    return p.axis_count != 1 && refuse(out, "axes", rule);
}

// --- conditions (§6.6.a, g, h, j) ---------------------------------------------------------

// A relative offset (SpringAtCurrentLocation, §8.2) is measured from where the handle is
// when the effect starts: a position, so it means something only for springs.
[[nodiscard]] bool check_condition_block(const ConditionBlock& c, int i, EffectType type, Error& out) noexcept {
    constexpr FieldRule kOffsetMode[] = {{"offset_mode", offsetof(ConditionBlock, offset_mode), 1, kOffsetModeChoice}};
    if (check_fields("conditions", i, &c, kOffsetMode, out)) return true;
    if (c.offset_mode == OffsetMode::relative && type != EffectType::spring &&
        type != EffectType::angle_spring) {
        return refuse(out, Path("conditions").index(i).add(".offset_mode"),
                              "a relative offset is a position (the handle's at the start), so "
                              "only springs take it; damper, inertia and friction offsets are "
                              "absolute");
    }
    return check_fields("conditions", i, &c, kConditionRules, out);
}

// A spring, damper, inertia or friction with a direction (§3.1): one block, conditions[0],
// applied along the direction on 2 or more axes (DirectInput's single DICONDITION "in the
// specified direction"). The blocks past the first are not read, so they must be left at
// their defaults: a block given for an axis and silently ignored would be a lie.
[[nodiscard]] bool check_directed_condition(const EffectParams& p, Error& out) noexcept {
    if (p.axis_count < 2) {
        return refuse(out, "direction",
                              "a condition on one axis acts along that axis and takes no direction; a "
                              "direction applies one condition block along it on 2 or more axes");
    }
    if (check_direction_form(p, out)) return true;
    if (check_condition_block(p.conditions[0], 0, p.type, out)) return true;
    for (int i = 1; i < p.axis_count; ++i) {
        if (!(p.conditions[i] == ConditionBlock{})) {
            return refuse(out, Path("conditions").index(i),
                                  "a condition with a direction has one block, conditions[0], applied "
                                  "along the direction; leave the others at their defaults, or give "
                                  "one block per axis and no direction");
        }
    }
    return false;
}

// A wall or barrier: its fields before the angle (`head`), the angle, which only the
// angle types have (an axis type lies across its one axis), then its surface (`tail`).
[[nodiscard]] bool check_contact_block(const char* block, const void* base, std::span<const FieldRule> head,
                                        int32_t angle, bool angled, const char* axis_rule,
                                        std::span<const FieldRule> tail, Error& out) noexcept {
    if (check_fields(block, base, head, out)) return true;
    if (angled) {
        if (in_range(Path(block).add(".angle"), angle, range::kAngle, out)) return true;
    } else if (angle != 0) {
        return refuse(out, Path(block).add(".angle"), axis_rule);
    }
    return check_fields(block, base, tail, out);
}

[[nodiscard]] bool check_wall(const WallBlock& w, bool angled, Error& out) noexcept {
    return check_contact_block("wall", &w, kWallRules, w.angle, angled,
                               "an axis_wall lies across its one axis and has no angle; "
                               "use angle_wall for a wall at an angle",
                               kWallSurfaceRules, out);
}

[[nodiscard]] bool check_barrier(const BarrierBlock& b, bool angled, Error& out) noexcept {
    return check_contact_block("barrier", &b, kBarrierRules, b.angle, angled,
                               "an axis_barrier lies across its one axis and has no angle; "
                               "use angle_barrier for a barrier at an angle",
                               kBarrierSurfaceRules, out);
}

[[nodiscard]] bool check_condition(const EffectParams& p, Error& out) noexcept {
    switch (p.type) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::friction:
            if (is_directed_condition(p)) return check_directed_condition(p, out);
            for (int i = 0; i < p.axis_count; ++i) {
                if (check_condition_block(p.conditions[i], i, p.type, out)) return true;
            }
            return false;
        case EffectType::angle_spring:
            if (needs_xy(p, "an angle_spring acts in the x-y plane: its axes must be "
                            "x and y", out)) {
                return true;
            }
            if (p.direction.kind != DirectionKind::polar) {
                return refuse(out, "direction",
                                      "an angle_spring needs a polar direction: the angle of "
                                      "the spring");
            }
            if (check_direction_form(p, out)) return true;
            return check_condition_block(p.conditions[0], 0, p.type, out);
        case EffectType::texture:
            if (p.axis_count == 1) {
                if (no_direction(p, "a texture on one axis lies along that axis and "
                                    "takes no direction", out)) {
                    return true;
                }
            } else {
                if (p.direction.kind == DirectionKind::none) {
                    return refuse(out, "direction",
                                          "a texture on several axes needs a direction: the "
                                          "line its bumps lie along");
                }
                if (check_direction_form(p, out)) return true;
            }
            return check_fields("texture", &p.texture, kTextureRules, out);
        case EffectType::axis_wall:
        case EffectType::axis_barrier: {
            const bool wall = p.type == EffectType::axis_wall;
            if (needs_one_axis(p, "axis_wall and axis_barrier act on exactly one axis", out)) {
                return true;
            }
            if (no_direction(p, "axis_wall and axis_barrier lie across their one axis "
                                "and take no direction", out)) {
                return true;
            }
            return wall ? check_wall(p.wall, false, out) : check_barrier(p.barrier, false, out);
        }
        case EffectType::angle_wall:
        case EffectType::angle_barrier: {
            const bool wall = p.type == EffectType::angle_wall;
            if (needs_xy(p, "angle_wall and angle_barrier lie in the x-y plane: their "
                            "axes must be x and y", out)) {
                return true;
            }
            if (no_direction(p, "angle_wall and angle_barrier take their angle from "
                                "their block, not from a direction", out)) {
                return true;
            }
            return wall ? check_wall(p.wall, true, out) : check_barrier(p.barrier, true, out);
        }
        default:
            return false;
    }
}

// --- waves (§6.6.b, c, d, e, i) -------------------------------------------------------------

[[nodiscard]] bool check_periodic(const EffectParams& p, Error& out) noexcept {
    using Rules = std::span<const FieldRule>;
    return check_fields("periodic", &p.periodic, is_sweep(p.type) ? Rules(kSweepRules) : Rules(kPeriodicRules), out);
}

[[nodiscard]] bool check_force_profile(const EffectParams& p, std::span<const int16_t> samples, Error& out) noexcept {
    const CustomBlock& c = p.custom;
    if (check_fields("custom", &c, kCustomRules, out)) return true;
    if (c.sample_count % c.channels != 0) {
        return refuse(out, "custom.sample_count",
                              "the sample count must be a multiple of custom.channels: samples "
                              "are interleaved by channel (§6.6.d)");
    }
    if (samples.size() != static_cast<size_t>(c.sample_count)) {
        return refuse(out, "custom.samples",
                              "the number of samples passed must equal custom.sample_count");
    }
    for (size_t i = 0; i < samples.size(); ++i) {
        if (in_range(Path("custom.samples").index(static_cast<int64_t>(i)), samples[i],
                     range::kSample, out)) {
            return true;
        }
    }
    if (c.channels == 1) return check_wave_direction(p, out);
    if (c.channels != p.axis_count) {
        return refuse(out, "custom.channels",
                              "a profile with several channels drives one axis per channel: "
                              "custom.channels must equal the number of axes");
    }
    return no_direction(p, "a profile with several channels drives each axis with its own "
                           "channel and takes no direction", out);
}

[[nodiscard]] bool check_wave(const EffectParams& p, std::span<const int16_t> samples, Error& out) noexcept {
    const EffectType t = p.type;
    if (is_sweep(t)) {
        if (needs_xy(p, "a sweep turns its direction in the x-y plane: its axes must "
                        "be x and y", out)) {
            return true;
        }
        if (no_direction(p, "a sweep's direction is given by its sweep angles, not by "
                            "a direction", out)) {
            return true;
        }
        return check_periodic(p, out);
    }
    if (is_periodic(t)) {
        if (check_periodic(p, out)) return true;
        return check_wave_direction(p, out);
    }
    switch (t) {
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop:
            if (check_fields("constant", &p.constant, kConstantRules, out)) return true;
            return check_wave_direction(p, out);
        case EffectType::ramp:
            if (check_fields("ramp", &p.ramp, kRampRules, out)) return true;
            return check_wave_direction(p, out);
        case EffectType::force_profile:
            return check_force_profile(p, samples, out);
        default:
            return false;
    }
}

// --- dynamics (§6.6.f, §8.4) ----------------------------------------------------------------

// Recoil and impact aim their kick (§5.4, §5.10): in the x-y plane with the compass angle
// of their block; on one axis with the sign of their intensity (the angle must be 0); on
// the axes x, y and z with a spherical direction, as waves do (the angle must be 0).
[[nodiscard]] bool check_kick_aim(const EffectParams& p, const char* angle_field, int32_t angle, Error& out) noexcept {
    if (p.axis_count == 1) {
        if (no_direction(p, "a recoil or impact on one axis takes no direction: the "
                            "sign of its intensity is its direction", out)) {
            return true;
        }
        if (angle != 0) {
            return refuse(out, angle_field, "on one axis the sign of the intensity is the "
                                               "direction: the angle must be 0");
        }
        return false;
    }
    if (on_xyz(p)) {
        if (p.direction.kind != DirectionKind::spherical) {
            return refuse(out, "direction", "a recoil or impact on the axes x, y and z aims "
                                               "with a spherical direction (§6.5.c)");
        }
        if (angle != 0) {
            return refuse(out, angle_field, "on the axes x, y and z the spherical direction "
                                               "aims the kick: the angle must be 0");
        }
        return check_direction_form(p, out);
    }
    if (needs_xy(p, "a recoil or impact plays on one axis, on x and y (aimed by the "
                    "angle in its block) or on x, y and z (aimed by a spherical "
                    "direction)", out)) {
        return true;
    }
    return no_direction(p, "on x and y a recoil or impact aims with the angle in its block, "
                           "not with a direction", out);
}

[[nodiscard]] bool check_dynamic(const EffectParams& p, Error& out) noexcept {
    const bool kick = p.type == EffectType::dynamic_recoil || p.type == EffectType::dynamic_impact;
    if (!kick) {
        if (no_direction(p, "dynamics take no direction; paddle aims with the angle "
                            "in its block, recoil and impact with it on x and y", out)) {
            return true;
        }
    }
    const DynamicBlock& d = p.dynamic;
    switch (p.type) {
        case EffectType::dynamic_recoil:
        case EffectType::dynamic_impact: {
            // The angle's own range first, then how the kick is aimed, then every field.
            const bool recoil = p.type == EffectType::dynamic_recoil;
            using Rules = std::span<const FieldRule>;
            const Rules rules = recoil ? Rules(kRecoilRules) : Rules(kImpactRules);
            if (check_fields("dynamic", &d, rules.first(1), out)) return true;
            if (recoil ? check_kick_aim(p, "dynamic.blast_direction", d.blast_direction, out)
                       : check_kick_aim(p, "dynamic.impact_direction", d.impact_direction, out)) {
                return true;
            }
            return check_fields("dynamic", &d, rules, out);
        }
        case EffectType::dynamic_liquid: return check_fields("dynamic", &d, kLiquidRules, out);
        case EffectType::dynamic_inertia: return check_fields("dynamic", &d, kInertiaRules, out);
        case EffectType::dynamic_center_drift: return check_fields("dynamic", &d, kCenterDriftRules, out);
        case EffectType::dynamic_sling: return check_fields("dynamic", &d, kSlingRules, out);
        case EffectType::dynamic_paddle:
            if (needs_xy(p, "a paddle is a ball bouncing on the handle in the x-y plane "
                            "(2D only, not 1 or 3 axes): its axes must be x and y", out)) {
                return true;
            }
            return check_fields("dynamic", &d, kPaddleRules, out);
        case EffectType::dynamic_control_law:
            for (int i = 0; i < p.axis_count; ++i) {
                if (check_fields("dynamic.control_law", i, &d.control_law[i], kControlLawRules, out)) return true;
            }
            return false;
        default:
            return false;
    }
}

// The first refusal, in reading order, into `out`.
[[nodiscard]] bool check_effect(const EffectParams& p, std::span<const int16_t> samples, Error& out) noexcept {
    const int type = static_cast<int>(p.type);
    if (in_range("type", type, Range{0, kEffectTypeCount - 1}, out)) return true;
    if (check_timing(p, out) || check_axes(p, out) || check_trigger(p, out) || check_envelope(p, out)) {
        return true;
    }
    if (p.type != EffectType::force_profile && !samples.empty()) {
        return refuse(out, "custom.samples", "only force_profile effects carry samples");
    }
    switch (effect_class(p.type)) {
        case EffectClass::condition: return check_condition(p, out);
        case EffectClass::wave: return check_wave(p, samples, out);
        case EffectClass::dynamic: return check_dynamic(p, out);
    }
    return false;
}

}  // namespace

Error validate_effect(const EffectParams& p, std::span<const int16_t> samples) noexcept {
    Error out;
    (void)check_effect(p, samples, out);
    return out;
}

}  // namespace feel
