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

#include <charconv>
#include <initializer_list>
#include <string_view>

namespace feel {
namespace {

// A field path built in place, e.g. Path("conditions").index(1).add(".deadband").
class Path {
public:
    explicit Path(std::string_view base) noexcept { add(base); }

    Path& add(std::string_view s) noexcept {
        for (char c : s) {
            if (len_ + 1 < sizeof buf_) buf_[len_++] = c;
        }
        buf_[len_] = '\0';
        return *this;
    }

    Path& index(int64_t i) noexcept {
        char digits[24];
        const auto r = std::to_chars(digits, digits + sizeof digits, i);
        add("[");
        add(std::string_view(digits, static_cast<size_t>(r.ptr - digits)));
        return add("]");
    }

    [[nodiscard]] std::string_view view() const noexcept { return {buf_, len_}; }

private:
    char buf_[48] = {};
    size_t len_ = 0;
};

[[nodiscard]] Error in_range(std::string_view field, int64_t value, Range allowed) noexcept {
    return allowed.contains(value) ? Error{} : Error::out_of_range(field, value, allowed);
}

[[nodiscard]] Error in_range(const Path& field, int64_t value, Range allowed) noexcept {
    return in_range(field.view(), value, allowed);
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

[[nodiscard]] Error check_axes(const EffectParams& p) noexcept {
    if (Error e = in_range("axes", p.axis_count, range::kAxisCount)) return e;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = static_cast<int>(p.axes[i]);
        if (Error e = in_range(Path("axes").index(i), a, Range{0, kMaxAxes - 1})) return e;
        for (int j = 0; j < i; ++j) {
            if (p.axes[j] == p.axes[i]) {
                return Error::invalid(Path("axes").index(i).view(),
                                      "an axis may appear only once in an effect's axes");
            }
        }
    }
    return {};
}

// --- common fields ----------------------------------------------------------------------

[[nodiscard]] bool needs_finite_duration(EffectType t) noexcept {
    return t == EffectType::ramp || t == EffectType::smart_pop || is_sweep(t);
}

[[nodiscard]] Error check_timing(const EffectParams& p) noexcept {
    if (p.duration_us == kInfiniteUs) {
        if (needs_finite_duration(p.type)) {
            return Error::invalid("duration_us",
                                  "ramp, smart_pop and the sweep waves need a finite duration: "
                                  "they are shaped over it");
        }
    } else if (Error e = in_range("duration_us", p.duration_us, range::kDurationUs)) {
        return e;
    }
    if (Error e = in_range("start_delay_us", p.start_delay_us, range::kDelayUs)) return e;
    if (Error e = in_range("gain", p.gain, range::kGain)) return e;
    if (p.iterations != kInfiniteIterations) {
        if (Error e = in_range("iterations", p.iterations, range::kIterations)) return e;
    }
    return {};
}

[[nodiscard]] Error check_trigger(const EffectParams& p) noexcept {
    switch (p.trigger.kind) {
        case TriggerKind::none:
            if (p.trigger_repeat_interval_us != 0) {
                return Error::invalid("trigger_repeat_interval_us",
                                      "a repeat interval needs a trigger button to repeat on");
            }
            return {};
        case TriggerKind::button:
            if (Error e = in_range("trigger_button", p.trigger.index, range::kTriggerButton)) return e;
            break;
        case TriggerKind::hat:
            if (Error e = in_range("trigger_button", p.trigger.index, range::kTriggerHat)) return e;
            break;
        default:
            return Error::invalid("trigger_button", "the trigger kind must be none, button or hat");
    }
    return in_range("trigger_repeat_interval_us", p.trigger_repeat_interval_us,
                    range::kRepeatIntervalUs);
}

[[nodiscard]] Error check_envelope(const EffectParams& p) noexcept {
    if (!p.has_envelope) return {};
    if (!supports_envelope(p.type)) {
        return Error::invalid("envelope",
                              "only vector_force, constant, the periodic and sweep waves, "
                              "force_profile and ramp take an envelope (§6.4)");
    }
    const Envelope& e = p.envelope;
    if (Error r = in_range("envelope.impulse_level", e.impulse_level, range::kLevel)) return r;
    if (Error r = in_range("envelope.settle_time_us", e.settle_time_us, range::kDelayUs)) return r;
    if (Error r = in_range("envelope.fade_level", e.fade_level, range::kLevel)) return r;
    return in_range("envelope.fade_time_us", e.fade_time_us, range::kDelayUs);
}

// --- direction --------------------------------------------------------------------------

// A cartesian or moments vector: one component per axis, each in range, not all zero.
[[nodiscard]] Error check_vector(const EffectParams& p, std::string_view name) noexcept {
    // Distinct axes of one kind are at most three; this guards value[3] all the same.
    if (p.axis_count > 3) {
        return Error::invalid(Path("direction.").add(name).view(),
                              "a cartesian or moments direction has at most 3 components, "
                              "one per axis");
    }
    bool any = false;
    for (int i = 0; i < p.axis_count; ++i) {
        const int32_t v = p.direction.value[i];
        if (Error e = in_range(Path("direction.").add(name).index(i), v, range::kCartesianComponent)) {
            return e;
        }
        any = any || v != 0;
    }
    if (!any) {
        return Error::invalid(Path("direction.").add(name).view(),
                              "the zero vector names no direction");
    }
    return {};
}

// The direction is well formed for the effect's axes (whether one is needed is the
// caller's rule).
[[nodiscard]] Error check_direction_form(const EffectParams& p) noexcept {
    const Direction& d = p.direction;
    switch (d.kind) {
        case DirectionKind::none:
            return {};
        case DirectionKind::polar:
            if (!on_xy(p)) {
                return Error::invalid("direction.polar",
                                      "a polar direction is a compass angle in the x-y plane: "
                                      "the effect's axes must be x and y");
            }
            return in_range("direction.polar", d.value[0], range::kAngle);
        case DirectionKind::spherical:
            if (!on_xyz(p)) {
                return Error::invalid("direction.spherical",
                                      "a spherical direction needs the axes x, y and z (§6.5.c)");
            }
            if (Error e = in_range("direction.spherical[0]", d.value[0], range::kAngle)) return e;
            return in_range("direction.spherical[1]", d.value[1], range::kElevation);
        case DirectionKind::cartesian:
            if (!all_axes(p, false)) {
                return Error::invalid("direction.cartesian",
                                      "a cartesian direction is for the axes x, y, z; "
                                      "use moments for rx, ry, rz (§6.5.d)");
            }
            return check_vector(p, "cartesian");
        case DirectionKind::moments:
            if (!all_axes(p, true)) {
                return Error::invalid("direction.moments",
                                      "moments are for the rotational axes rx, ry, rz (§6.5.d)");
            }
            return check_vector(p, "moments");
    }
    return Error::invalid("direction", "the direction kind must be none, polar, cartesian, "
                                       "spherical or moments");
}

// A wave on one axis may omit its direction; on several axes it needs one.
[[nodiscard]] Error check_wave_direction(const EffectParams& p) noexcept {
    if (p.direction.kind == DirectionKind::none && p.axis_count > 1) {
        return Error::invalid("direction",
                              "a wave on several axes needs a direction (polar, cartesian, "
                              "spherical or moments)");
    }
    return check_direction_form(p);
}

[[nodiscard]] Error no_direction(const EffectParams& p, const char* rule) noexcept {
    return p.direction.kind == DirectionKind::none ? Error{} : Error::invalid("direction", rule);
}

[[nodiscard]] Error needs_xy(const EffectParams& p, const char* rule) noexcept {
    return on_xy(p) ? Error{} : Error::invalid("axes", rule);
}

[[nodiscard]] Error needs_one_axis(const EffectParams& p, const char* rule) noexcept {
    return p.axis_count == 1 ? Error{} : Error::invalid("axes", rule);
}

// --- conditions (§6.6.a, g, h, j) ---------------------------------------------------------

// A relative offset (SpringAtCurrentLocation, §8.2) is measured from where the handle is
// when the effect starts: a position, so it means something only for springs.
[[nodiscard]] Error check_condition_block(const ConditionBlock& c, int i, EffectType type) noexcept {
    auto at = [i](std::string_view f) { return Path("conditions").index(i).add(".").add(f); };
    if (c.offset_mode != OffsetMode::absolute && c.offset_mode != OffsetMode::relative) {
        return Error::invalid(at("offset_mode").view(), "the offset mode must be absolute or relative");
    }
    if (c.offset_mode == OffsetMode::relative && type != EffectType::spring &&
        type != EffectType::angle_spring) {
        return Error::invalid(at("offset_mode").view(),
                              "a relative offset is a position (the handle's at the start), so "
                              "only springs take it; damper, inertia and friction offsets are "
                              "absolute");
    }
    if (Error e = in_range(at("pos_coefficient"), c.pos_coefficient, range::kSignedLevel)) return e;
    if (Error e = in_range(at("neg_coefficient"), c.neg_coefficient, range::kSignedLevel)) return e;
    if (Error e = in_range(at("offset"), c.offset, range::kSignedLevel)) return e;
    if (Error e = in_range(at("pos_saturation"), c.pos_saturation, range::kLevel)) return e;
    if (Error e = in_range(at("neg_saturation"), c.neg_saturation, range::kLevel)) return e;
    return in_range(at("deadband"), c.deadband, range::kLevel);
}

// A spring, damper, inertia or friction with a direction (§3.1): one block, conditions[0],
// applied along the direction on 2 or more axes (DirectInput's single DICONDITION "in the
// specified direction"). The blocks past the first are not read, so they must be left at
// their defaults: a block given for an axis and silently ignored would be a lie.
[[nodiscard]] Error check_directed_condition(const EffectParams& p) noexcept {
    if (p.axis_count < 2) {
        return Error::invalid("direction",
                              "a condition on one axis acts along that axis and takes no direction; a "
                              "direction applies one condition block along it on 2 or more axes");
    }
    if (Error e = check_direction_form(p)) return e;
    if (Error e = check_condition_block(p.conditions[0], 0, p.type)) return e;
    for (int i = 1; i < p.axis_count; ++i) {
        if (!(p.conditions[i] == ConditionBlock{})) {
            return Error::invalid(Path("conditions").index(i).view(),
                                  "a condition with a direction has one block, conditions[0], applied "
                                  "along the direction; leave the others at their defaults, or give "
                                  "one block per axis and no direction");
        }
    }
    return {};
}

[[nodiscard]] Error check_texture(const TextureBlock& t) noexcept {
    if (Error e = in_range("texture.pos_roughness", t.pos_roughness, range::kPositiveLevel)) return e;
    if (Error e = in_range("texture.neg_roughness", t.neg_roughness, range::kPositiveLevel)) return e;
    if (Error e = in_range("texture.spacing", t.spacing, range::kPositiveLevel)) return e;
    return in_range("texture.density", t.density, range::kPositiveLevel);
}

[[nodiscard]] Error check_wall(const WallBlock& w, bool angled) noexcept {
    if (Error e = in_range("wall.hardness", w.hardness, range::kSignedLevel)) return e;
    if (w.sense != WallSense::positive && w.sense != WallSense::negative) {
        return Error::invalid("wall.sense", "the sense must be positive or negative");
    }
    if (Error e = in_range("wall.offset", w.offset, range::kSignedLevel)) return e;
    if (w.offset_mode != OffsetMode::absolute && w.offset_mode != OffsetMode::relative) {
        return Error::invalid("wall.offset_mode", "the offset mode must be absolute or relative");
    }
    if (angled) {
        if (Error e = in_range("wall.angle", w.angle, range::kAngle)) return e;
    } else if (w.angle != 0) {
        return Error::invalid("wall.angle",
                              "an axis_wall lies across its one axis and has no angle; "
                              "use angle_wall for a wall at an angle");
    }
    if (Error e = in_range("wall.surface_friction", w.surface_friction, range::kLevel)) return e;
    return in_range("wall.surface_texture", w.surface_texture, range::kLevel);
}

[[nodiscard]] Error check_barrier(const BarrierBlock& b, bool angled) noexcept {
    if (Error e = in_range("barrier.pos_hardness", b.pos_hardness, range::kSignedLevel)) return e;
    if (Error e = in_range("barrier.neg_hardness", b.neg_hardness, range::kSignedLevel)) return e;
    if (Error e = in_range("barrier.thickness", b.thickness, range::kPositiveLevel)) return e;
    if (Error e = in_range("barrier.offset", b.offset, range::kSignedLevel)) return e;
    if (b.offset_mode != OffsetMode::absolute && b.offset_mode != OffsetMode::relative) {
        return Error::invalid("barrier.offset_mode", "the offset mode must be absolute or relative");
    }
    if (angled) {
        if (Error e = in_range("barrier.angle", b.angle, range::kAngle)) return e;
    } else if (b.angle != 0) {
        return Error::invalid("barrier.angle",
                              "an axis_barrier lies across its one axis and has no angle; "
                              "use angle_barrier for a barrier at an angle");
    }
    if (Error e = in_range("barrier.surface_friction", b.surface_friction, range::kLevel)) return e;
    return in_range("barrier.surface_texture", b.surface_texture, range::kLevel);
}

[[nodiscard]] Error check_condition(const EffectParams& p) noexcept {
    switch (p.type) {
        case EffectType::spring:
        case EffectType::damper:
        case EffectType::inertia:
        case EffectType::friction:
            if (is_directed_condition(p)) return check_directed_condition(p);
            for (int i = 0; i < p.axis_count; ++i) {
                if (Error e = check_condition_block(p.conditions[i], i, p.type)) return e;
            }
            return {};
        case EffectType::angle_spring:
            if (Error e = needs_xy(p, "an angle_spring acts in the x-y plane: its axes must be "
                                      "x and y")) {
                return e;
            }
            if (p.direction.kind != DirectionKind::polar) {
                return Error::invalid("direction",
                                      "an angle_spring needs a polar direction: the angle of "
                                      "the spring");
            }
            if (Error e = check_direction_form(p)) return e;
            return check_condition_block(p.conditions[0], 0, p.type);
        case EffectType::texture:
            if (p.axis_count == 1) {
                if (Error e = no_direction(p, "a texture on one axis lies along that axis and "
                                              "takes no direction")) {
                    return e;
                }
            } else {
                if (p.direction.kind == DirectionKind::none) {
                    return Error::invalid("direction",
                                          "a texture on several axes needs a direction: the "
                                          "line its bumps lie along");
                }
                if (Error e = check_direction_form(p)) return e;
            }
            return check_texture(p.texture);
        case EffectType::axis_wall:
        case EffectType::axis_barrier: {
            const bool wall = p.type == EffectType::axis_wall;
            if (Error e = needs_one_axis(p, "axis_wall and axis_barrier act on exactly one axis")) {
                return e;
            }
            if (Error e = no_direction(p, "axis_wall and axis_barrier lie across their one axis "
                                          "and take no direction")) {
                return e;
            }
            return wall ? check_wall(p.wall, false) : check_barrier(p.barrier, false);
        }
        case EffectType::angle_wall:
        case EffectType::angle_barrier: {
            const bool wall = p.type == EffectType::angle_wall;
            if (Error e = needs_xy(p, "angle_wall and angle_barrier lie in the x-y plane: their "
                                      "axes must be x and y")) {
                return e;
            }
            if (Error e = no_direction(p, "angle_wall and angle_barrier take their angle from "
                                          "their block, not from a direction")) {
                return e;
            }
            return wall ? check_wall(p.wall, true) : check_barrier(p.barrier, true);
        }
        default:
            return {};
    }
}

// --- waves (§6.6.b, c, d, e, i) -------------------------------------------------------------

[[nodiscard]] Error check_periodic(const EffectParams& p) noexcept {
    const PeriodicBlock& w = p.periodic;
    const bool sweep = is_sweep(p.type);
    // §6.6.b: a periodic magnitude is 0..10000; §6.6.i: an advanced periodic one is signed.
    const Range magnitude = sweep ? range::kSignedLevel : range::kLevel;
    if (Error e = in_range("periodic.magnitude", w.magnitude, magnitude)) return e;
    if (Error e = in_range("periodic.offset", w.offset, range::kSignedLevel)) return e;
    if (Error e = in_range("periodic.period_us", w.period_us, range::kPeriodUs)) return e;
    if (Error e = in_range("periodic.phase", w.phase, range::kAngle)) return e;
    if (!sweep) return {};
    if (Error e = in_range("periodic.sweep_start_angle", w.sweep_start_angle, range::kAngle)) return e;
    if (Error e = in_range("periodic.sweep_end_angle", w.sweep_end_angle, range::kAngle)) return e;
    if (w.sweep_sense != SweepSense::clockwise && w.sweep_sense != SweepSense::counterclockwise) {
        return Error::invalid("periodic.sweep_sense",
                              "the sweep sense must be clockwise or counterclockwise");
    }
    return {};
}

[[nodiscard]] Error check_force_profile(const EffectParams& p, std::span<const int16_t> samples) noexcept {
    const CustomBlock& c = p.custom;
    if (Error e = in_range("custom.channels", c.channels, range::kChannels)) return e;
    if (Error e = in_range("custom.sample_period_us", c.sample_period_us, range::kPeriodUs)) return e;
    if (Error e = in_range("custom.sample_count", c.sample_count, range::kSampleCount)) return e;
    if (c.sample_count % c.channels != 0) {
        return Error::invalid("custom.sample_count",
                              "the sample count must be a multiple of custom.channels: samples "
                              "are interleaved by channel (§6.6.d)");
    }
    if (samples.size() != static_cast<size_t>(c.sample_count)) {
        return Error::invalid("custom.samples",
                              "the number of samples passed must equal custom.sample_count");
    }
    for (size_t i = 0; i < samples.size(); ++i) {
        if (Error e = in_range(Path("custom.samples").index(static_cast<int64_t>(i)), samples[i],
                               range::kSample)) {
            return e;
        }
    }
    if (c.channels == 1) return check_wave_direction(p);
    if (c.channels != p.axis_count) {
        return Error::invalid("custom.channels",
                              "a profile with several channels drives one axis per channel: "
                              "custom.channels must equal the number of axes");
    }
    return no_direction(p, "a profile with several channels drives each axis with its own "
                           "channel and takes no direction");
}

[[nodiscard]] Error check_wave(const EffectParams& p, std::span<const int16_t> samples) noexcept {
    const EffectType t = p.type;
    if (is_sweep(t)) {
        if (Error e = needs_xy(p, "a sweep turns its direction in the x-y plane: its axes must "
                                  "be x and y")) {
            return e;
        }
        if (Error e = no_direction(p, "a sweep's direction is given by its sweep angles, not by "
                                      "a direction")) {
            return e;
        }
        return check_periodic(p);
    }
    if (is_periodic(t)) {
        if (Error e = check_periodic(p)) return e;
        return check_wave_direction(p);
    }
    switch (t) {
        case EffectType::vector_force:
        case EffectType::constant:
        case EffectType::smart_pop:
            if (Error e = in_range("constant.magnitude", p.constant.magnitude, range::kSignedLevel)) {
                return e;
            }
            return check_wave_direction(p);
        case EffectType::ramp:
            if (Error e = in_range("ramp.start", p.ramp.start, range::kSignedLevel)) return e;
            if (Error e = in_range("ramp.end", p.ramp.end, range::kSignedLevel)) return e;
            return check_wave_direction(p);
        case EffectType::force_profile:
            return check_force_profile(p, samples);
        default:
            return {};
    }
}

// --- dynamics (§6.6.f, §8.4) ----------------------------------------------------------------

[[nodiscard]] Error check_control_law(const ControlLawBlock& c, int i) noexcept {
    auto at = [i](std::string_view f) {
        return Path("dynamic.control_law").index(i).add(".").add(f);
    };
    if (Error e = in_range(at("mass"), c.mass, range::kDynamicMass)) return e;
    if (Error e = in_range(at("k_pos"), c.k_pos, range::kDynamicStiffness)) return e;
    if (Error e = in_range(at("k_neg"), c.k_neg, range::kDynamicStiffness)) return e;
    if (Error e = in_range(at("b"), c.b, range::kLevel)) return e;
    if (Error e = in_range(at("vel_init"), c.vel_init, range::kSignedLevel)) return e;
    if (Error e = in_range(at("pos_init"), c.pos_init, range::kSignedLevel)) return e;
    if (Error e = in_range(at("half_cycles"), c.half_cycles, range::kHalfCycles)) return e;
    if (Error e = in_range(at("length"), c.length, range::kLevel)) return e;
    if (Error e = in_range(at("drag"), c.drag, range::kLevel)) return e;
    return in_range(at("gravity"), c.gravity, range::kSignedLevel);
}

// The first of several independent range checks that fails, in order.
struct Check {
    std::string_view field;
    int64_t value;
    Range allowed;
};

[[nodiscard]] Error first_failing(std::initializer_list<Check> checks) noexcept {
    for (const Check& c : checks) {
        if (Error e = in_range(c.field, c.value, c.allowed)) return e;
    }
    return {};
}

// Recoil and impact aim their kick (§5.4, §5.10): in the x-y plane with the compass angle
// of their block; on one axis with the sign of their intensity (the angle must be 0); on
// the axes x, y and z with a spherical direction, as waves do (the angle must be 0).
[[nodiscard]] Error check_kick_aim(const EffectParams& p, const char* angle_field, int32_t angle) noexcept {
    if (p.axis_count == 1) {
        if (Error e = no_direction(p, "a recoil or impact on one axis takes no direction: the "
                                      "sign of its intensity is its direction")) {
            return e;
        }
        if (angle != 0) {
            return Error::invalid(angle_field, "on one axis the sign of the intensity is the "
                                               "direction: the angle must be 0");
        }
        return {};
    }
    if (on_xyz(p)) {
        if (p.direction.kind != DirectionKind::spherical) {
            return Error::invalid("direction", "a recoil or impact on the axes x, y and z aims "
                                               "with a spherical direction (§6.5.c)");
        }
        if (angle != 0) {
            return Error::invalid(angle_field, "on the axes x, y and z the spherical direction "
                                               "aims the kick: the angle must be 0");
        }
        return check_direction_form(p);
    }
    if (Error e = needs_xy(p, "a recoil or impact plays on one axis, on x and y (aimed by the "
                              "angle in its block) or on x, y and z (aimed by a spherical "
                              "direction)")) {
        return e;
    }
    return no_direction(p, "on x and y a recoil or impact aims with the angle in its block, "
                           "not with a direction");
}

[[nodiscard]] Error check_dynamic(const EffectParams& p) noexcept {
    const bool kick = p.type == EffectType::dynamic_recoil || p.type == EffectType::dynamic_impact;
    if (!kick) {
        if (Error e = no_direction(p, "dynamics take no direction; paddle aims with the angle "
                                      "in its block, recoil and impact with it on x and y")) {
            return e;
        }
    }
    const DynamicBlock& d = p.dynamic;
    // §8.4: each wrapper parameter has the range of the control-law parameter it maps to.
    switch (p.type) {
        case EffectType::dynamic_recoil:
            if (Error e = in_range("dynamic.blast_direction", d.blast_direction, range::kAngle)) return e;
            if (Error e = check_kick_aim(p, "dynamic.blast_direction", d.blast_direction)) return e;
            return first_failing({{"dynamic.blast_direction", d.blast_direction, range::kAngle},
                                  {"dynamic.blast_intensity", d.blast_intensity, range::kSignedLevel},
                                  {"dynamic.dynamic_mass", d.dynamic_mass, range::kDynamicMass},
                                  {"dynamic.blast_resonance", d.blast_resonance, range::kDynamicStiffness},
                                  {"dynamic.blast_decay", d.blast_decay, range::kLevel}});
        case EffectType::dynamic_impact:
            if (Error e = in_range("dynamic.impact_direction", d.impact_direction, range::kAngle)) return e;
            if (Error e = check_kick_aim(p, "dynamic.impact_direction", d.impact_direction)) return e;
            return first_failing({{"dynamic.impact_direction", d.impact_direction, range::kAngle},
                                  {"dynamic.impact_intensity", d.impact_intensity, range::kSignedLevel},
                                  {"dynamic.dynamic_mass", d.dynamic_mass, range::kDynamicMass},
                                  {"dynamic.elasticity", d.elasticity, range::kDynamicStiffness},
                                  {"dynamic.collision_absorption", d.collision_absorption, range::kLevel}});
        case EffectType::dynamic_liquid:
            return first_failing({{"dynamic.density", d.density, range::kDynamicMass},
                                  {"dynamic.settle", d.settle, range::kDynamicStiffness},
                                  {"dynamic.viscosity", d.viscosity, range::kLevel}});
        case EffectType::dynamic_inertia:
            return first_failing({{"dynamic.inertia", d.inertia, range::kDynamicMass},
                                  {"dynamic.play", d.play, range::kLevel}});
        case EffectType::dynamic_center_drift:
            return first_failing({{"dynamic.stiffness", d.stiffness, range::kDynamicStiffness},
                                  {"dynamic.drift_resistance", d.drift_resistance, range::kLevel}});
        case EffectType::dynamic_sling:
            return first_failing({{"dynamic.ball_mass", d.ball_mass, range::kDynamicMass},
                                  {"dynamic.string_length", d.string_length, range::kLevel},
                                  {"dynamic.string_compliance", d.string_compliance, range::kDynamicStiffness},
                                  {"dynamic.ball_damping", d.ball_damping, range::kLevel}});
        case EffectType::dynamic_paddle:
            if (Error e = needs_xy(p, "a paddle is a ball bouncing on the handle in the x-y plane "
                                      "(2D only, not 1 or 3 axes): its axes must be x and y")) {
                return e;
            }
            return first_failing(
                {{"dynamic.ball_mass", d.ball_mass, range::kDynamicMass},
                 {"dynamic.initial_velocity", d.initial_velocity, range::kSignedLevel},
                 {"dynamic.initial_velocity_direction", d.initial_velocity_direction, range::kAngle},
                 {"dynamic.paddle_compliance", d.paddle_compliance, range::kDynamicStiffness},
                 {"dynamic.paddle_damping", d.paddle_damping, range::kLevel},
                 {"dynamic.gravity", d.gravity, range::kSignedLevel}});
        case EffectType::dynamic_control_law:
            for (int i = 0; i < p.axis_count; ++i) {
                if (Error e = check_control_law(d.control_law[i], i)) return e;
            }
            return {};
        default:
            return {};
    }
}

}  // namespace

Error validate_effect(const EffectParams& p, std::span<const int16_t> samples) noexcept {
    const int type = static_cast<int>(p.type);
    if (Error e = in_range("type", type, Range{0, kEffectTypeCount - 1})) return e;
    if (Error e = check_timing(p)) return e;
    if (Error e = check_axes(p)) return e;
    if (Error e = check_trigger(p)) return e;
    if (Error e = check_envelope(p)) return e;
    if (p.type != EffectType::force_profile && !samples.empty()) {
        return Error::invalid("custom.samples", "only force_profile effects carry samples");
    }
    switch (effect_class(p.type)) {
        case EffectClass::condition: return check_condition(p);
        case EffectClass::wave: return check_wave(p, samples);
        case EffectClass::dynamic: return check_dynamic(p);
    }
    return {};
}

}  // namespace feel
