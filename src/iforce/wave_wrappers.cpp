// §8.3 Wave function wrappers: vector and constant forces, ramps and periodic waves, with
// or without an envelope and a trigger, built as §8.5's SineWave and ImpulseSquareWave
// fill DIEFFECT, DIENVELOPE and DIPERIODIC: on the axes x and y, in the polar direction
// given (rglDirection[0] = Angle), gain 10000.
//
// Ranges: §8.3's table. Where it is narrower than the engine (Magnitude 1..10000, Offset
// 0..10000, Start/End 0..10000, SettleTime/FadeTime 1..65e6) the primer wins. Where it is
// wider, the engine wins and the header says so: ramps and sweeps need a finite duration,
// and a trigger repeat interval of 0 means "no repeat" (§6.3; §8.5's samples pass it).
#include "feel/iforce.hpp"
#include "wrapper_args.hpp"

namespace feel::iforce {
namespace {

using detail::Args;
using detail::on_axes;

// A wave on x and y coming from compass angle `direction`.
EffectParams planar_wave(const Args& args, EffectType type, const char* direction_name, int32_t direction) {
    args.check(direction_name, direction, range::kAngle);
    EffectParams p = on_axes(type, {Axis::x, Axis::y});
    p.direction.kind = DirectionKind::polar;
    p.direction.value[0] = direction;
    return p;
}

void apply_trigger(const Args& args, EffectParams& p, Trigger trigger, int64_t repeat_us,
                   bool required = false) {
    args.trigger(trigger, repeat_us, required);
    p.trigger = trigger;
    p.trigger_repeat_interval_us = repeat_us;
}

void apply_envelope(const Args& args, EffectParams& p, int32_t impulse_level, int64_t settle_time_us,
                    int32_t fade_level, int64_t fade_time_us) {
    args.check("impulse_level", impulse_level, range::kLevel);
    args.check("settle_time_us", settle_time_us, detail::kEnvelopeTimeUs);
    args.check("fade_level", fade_level, range::kLevel);
    args.check("fade_time_us", fade_time_us, detail::kEnvelopeTimeUs);
    p.has_envelope = true;
    p.envelope = Envelope{impulse_level, settle_time_us, fade_level, fade_time_us};
}

EffectType periodic_type(const Args& args, Waveform waveform) {
    switch (waveform) {
        case Waveform::sine: return EffectType::sine;
        case Waveform::square: return EffectType::square;
        case Waveform::triangle: return EffectType::triangle;
        case Waveform::saw_up: return EffectType::saw_up;
        case Waveform::saw_down: return EffectType::saw_down;
    }
    args.fail("waveform", "must be sine, square, triangle, saw_up or saw_down");
}

EffectType sweep_type(const Args& args, Waveform waveform) {
    switch (waveform) {
        case Waveform::sine: return EffectType::sweep_sine;
        case Waveform::square: return EffectType::sweep_square;
        case Waveform::triangle: return EffectType::sweep_triangle;
        case Waveform::saw_up: return EffectType::sweep_saw_up;
        case Waveform::saw_down: return EffectType::sweep_saw_down;
    }
    args.fail("waveform", "must be sine, square, triangle, saw_up or saw_down");
}

// The constant-force family: magnitude, duration, direction.
EffectParams constant_wave(const Args& args, EffectType type, int32_t magnitude, int64_t duration_us,
                           bool allow_infinite, int32_t direction) {
    args.check("magnitude", magnitude, detail::kWaveMagnitude);
    args.duration("duration_us", duration_us, allow_infinite);
    EffectParams p = planar_wave(args, type, "direction", direction);
    p.duration_us = duration_us;
    p.constant.magnitude = magnitude;
    return p;
}

EffectParams ramp_wave(const Args& args, int32_t start, int32_t end, int64_t duration_us, int32_t direction) {
    args.check("start", start, detail::kRampLevel);
    args.check("end", end, detail::kRampLevel);
    args.duration("duration_us", duration_us, false);
    EffectParams p = planar_wave(args, EffectType::ramp, "direction", direction);
    p.duration_us = duration_us;
    p.ramp = RampBlock{start, end};
    return p;
}

// Periodic's first seven parameters (WaveForm .. Angle).
EffectParams periodic_wave(const Args& args, Waveform waveform, int32_t magnitude, int32_t offset,
                           int32_t phase, int64_t period_us, int64_t duration_us, int32_t angle) {
    const EffectType type = periodic_type(args, waveform);
    args.check("magnitude", magnitude, detail::kWaveMagnitude);
    args.check("offset", offset, detail::kWaveOffset);
    args.check("phase", phase, range::kAngle);
    args.check("period_us", period_us, range::kPeriodUs);
    args.duration("duration_us", duration_us, true);
    EffectParams p = planar_wave(args, type, "angle", angle);
    p.duration_us = duration_us;
    p.periodic.magnitude = magnitude;
    p.periodic.offset = offset;
    p.periodic.phase = phase;
    p.periodic.period_us = period_us;
    return p;
}

}  // namespace

EffectParams vector_force(int32_t magnitude, int64_t duration_us, int32_t direction) {
    const Args args("vector_force");
    return args.finish(constant_wave(args, EffectType::vector_force, magnitude, duration_us, true, direction));
}

EffectParams constant_force(int32_t magnitude, int64_t duration_us, int32_t direction) {
    const Args args("constant_force");
    return args.finish(constant_wave(args, EffectType::constant, magnitude, duration_us, false, direction));
}

EffectParams constant_force_trigger(int32_t magnitude, int64_t duration_us, int32_t direction,
                                    Trigger trigger, int64_t trigger_repeat_interval_us) {
    const Args args("constant_force_trigger");
    EffectParams p = constant_wave(args, EffectType::constant, magnitude, duration_us, false, direction);
    apply_trigger(args, p, trigger, trigger_repeat_interval_us, true);
    return args.finish(p);
}

EffectParams envelope_constant(int32_t magnitude, int64_t duration_us, int32_t direction,
                               int32_t impulse_level, int64_t settle_time_us, int32_t fade_level,
                               int64_t fade_time_us, Trigger trigger, int64_t trigger_repeat_interval_us) {
    const Args args("envelope_constant");
    EffectParams p = constant_wave(args, EffectType::constant, magnitude, duration_us, true, direction);
    apply_envelope(args, p, impulse_level, settle_time_us, fade_level, fade_time_us);
    apply_trigger(args, p, trigger, trigger_repeat_interval_us);
    return args.finish(p);
}

EffectParams ramp(int32_t start, int32_t end, int64_t duration_us, int32_t direction, Trigger trigger,
                  int64_t trigger_repeat_interval_us) {
    const Args args("ramp");
    EffectParams p = ramp_wave(args, start, end, duration_us, direction);
    apply_trigger(args, p, trigger, trigger_repeat_interval_us);
    return args.finish(p);
}

EffectParams ramp_envelope(int32_t start, int32_t end, int64_t duration_us, int32_t direction,
                           int32_t impulse_level, int64_t settle_time_us, int32_t fade_level,
                           int64_t fade_time_us, Trigger trigger, int64_t trigger_repeat_interval_us) {
    const Args args("ramp_envelope");
    EffectParams p = ramp_wave(args, start, end, duration_us, direction);
    apply_envelope(args, p, impulse_level, settle_time_us, fade_level, fade_time_us);
    apply_trigger(args, p, trigger, trigger_repeat_interval_us);
    return args.finish(p);
}

EffectParams periodic(Waveform waveform, int32_t magnitude, int32_t offset, int32_t phase, int64_t period_us,
                      int64_t duration_us, int32_t angle, Trigger trigger, int64_t trigger_repeat_interval_us) {
    const Args args("periodic");
    EffectParams p = periodic_wave(args, waveform, magnitude, offset, phase, period_us, duration_us, angle);
    apply_trigger(args, p, trigger, trigger_repeat_interval_us);
    return args.finish(p);
}

EffectParams envelope_periodic(Waveform waveform, int32_t magnitude, int32_t offset, int32_t phase,
                               int64_t period_us, int64_t duration_us, int32_t angle, int32_t impulse_level,
                               int64_t settle_time_us, int32_t fade_level, int64_t fade_time_us,
                               Trigger trigger, int64_t trigger_repeat_interval_us) {
    const Args args("envelope_periodic");
    EffectParams p = periodic_wave(args, waveform, magnitude, offset, phase, period_us, duration_us, angle);
    apply_envelope(args, p, impulse_level, settle_time_us, fade_level, fade_time_us);
    apply_trigger(args, p, trigger, trigger_repeat_interval_us);
    return args.finish(p);
}

EffectParams delayed_periodic(int64_t pause_us, Waveform waveform, int32_t magnitude, int32_t offset,
                              int32_t phase, int64_t period_us, int64_t duration_us, int32_t angle,
                              Trigger trigger, int64_t trigger_repeat_interval_us) {
    const Args args("delayed_periodic");
    args.check("pause_us", pause_us, range::kDelayUs);
    EffectParams p = periodic_wave(args, waveform, magnitude, offset, phase, period_us, duration_us, angle);
    p.start_delay_us = pause_us;
    apply_trigger(args, p, trigger, trigger_repeat_interval_us);
    return args.finish(p);
}

EffectParams sweep_periodic(int32_t start_angle, int32_t stop_angle, SweepSense sense, Waveform waveform,
                            int32_t magnitude, int32_t offset, int64_t period_us, int32_t phase,
                            int64_t duration_us) {
    const Args args("sweep_periodic");
    args.check("start_angle", start_angle, range::kAngle);
    args.check("stop_angle", stop_angle, range::kAngle);
    if (sense != SweepSense::clockwise && sense != SweepSense::counterclockwise) {
        args.fail("sense", "must be SweepSense::clockwise or SweepSense::counterclockwise");
    }
    const EffectType type = sweep_type(args, waveform);
    args.check("magnitude", magnitude, detail::kWaveMagnitude);
    args.check("offset", offset, detail::kWaveOffset);
    args.check("period_us", period_us, range::kPeriodUs);
    args.check("phase", phase, range::kAngle);
    args.duration("duration_us", duration_us, false);
    // A sweep turns its own direction (§6.6.i): it has no polar direction of its own.
    EffectParams p = on_axes(type, {Axis::x, Axis::y});
    p.duration_us = duration_us;
    p.periodic.magnitude = magnitude;
    p.periodic.offset = offset;
    p.periodic.period_us = period_us;
    p.periodic.phase = phase;
    p.periodic.sweep_start_angle = start_angle;
    p.periodic.sweep_end_angle = stop_angle;
    p.periodic.sweep_sense = sense;
    return args.finish(p);
}

}  // namespace feel::iforce
