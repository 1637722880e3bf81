// Closed-loop rendering: the engine and the simulated device run together, tick by tick.
//
// Each tick does what the device's local loop does (§2.2): read the sensors, let the
// engine compute the force from the time and the sensed state, send the force to the
// motors, and let the world move. Here the world is SimDevice, so the loop is
//
//     in.t_us = t(n);  device.sense(in);  engine.tick(in, out);  record;  device.step(out.force, dt)
//
// The row recorded for tick n holds the handle's true state at t(n) (not the quantized
// sensor reading the engine saw) and the force the engine commanded at t(n). That force
// then acts on the handle until t(n+1).
//
// Time is integer µs and computed from the tick index, t(n) = round(n·1e6 / rate), never
// accumulated, so the last tick of a long render is as exact as the first. The physics
// step dt is the difference of two such times, so the device's clock and the engine's
// clock never drift apart.
//
// The engine is sized to hold the whole sensation: rendering answers "what does this
// sensation feel like", not "does it fit a particular device's memory".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "feel/engine.hpp"
#include "feel/render/render.hpp"
#include "feel/runtime/reflexes.hpp"
#include "feel/sim/input_schedule.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::render {
namespace {

std::string format_number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

// The rate, as whole Hz; throws unless it is a whole number within the limits.
int64_t checked_rate(double rate_hz) {
    const bool whole = std::isfinite(rate_hz) && std::floor(rate_hz) == rate_hz;
    if (!whole || rate_hz < kMinRateHz || rate_hz > kMaxRateHz) {
        throw std::invalid_argument("--rate = " + format_number(rate_hz) +
                                    " Hz is out of range (allowed a whole number of Hz, " +
                                    format_number(kMinRateHz) + ".." +
                                    format_number(kMaxRateHz) + ")");
    }
    return static_cast<int64_t>(rate_hz);
}

// The render length in seconds: the option, or the sensation's own length when it is 0.
double checked_duration(const format::Sensation& sensation, double duration_s) {
    const std::string allowed = "allowed 0 < duration <= " + format_number(kMaxDurationS) +
                                " s, or 0 for the sensation's own length";
    if (!std::isfinite(duration_s) || duration_s < 0 || duration_s > kMaxDurationS) {
        throw std::invalid_argument("--duration = " + format_number(duration_s) +
                                    " s is out of range (" + allowed + ")");
    }
    if (duration_s > 0) return duration_s;
    const double own = default_duration_s(sensation);
    if (own > kMaxDurationS) {
        throw std::invalid_argument("sensation \"" + sensation.name + "\" lasts " +
                                    format_number(own) +
                                    " s with its tail, longer than the longest render: pass "
                                    "--duration (" + allowed + ")");
    }
    return own;
}

// Tick n's time, µs, rounded to the nearest µs.
int64_t tick_time_us(int64_t n, int64_t rate) noexcept {
    return (n * 1'000'000 + rate / 2) / rate;
}

std::string effect_label(const format::Sensation& sensation, size_t index,
                         const EffectParams& params) {
    return "sensation \"" + sensation.name + "\": effect " + std::to_string(index) + " (" +
           std::string(effect_type_name(params.type)) + ")";
}

[[noreturn]] void throw_refused(const format::Sensation& sensation, size_t index,
                                const EffectParams& params, const char* what,
                                const Error& error) {
    throw std::runtime_error(effect_label(sensation, index, params) + ": the engine " + what +
                             " it (" + std::string(error_code_name(error.code)) +
                             "): " + error.message());
}

EngineConfig engine_config_for(const format::Sensation& sensation, const sim::DeviceProfile& profile) {
    EngineConfig config = sim::engine_config_for(profile);
    size_t samples = 0;
    for (const format::EffectSpec& e : sensation.effects) samples += e.samples.size();
    constexpr size_t kMaxSlots = 65535;
    config.max_effects = static_cast<int32_t>(
        std::clamp<size_t>(sensation.effects.size(), static_cast<size_t>(config.max_effects),
                           kMaxSlots));
    config.max_samples = static_cast<int32_t>(std::clamp<size_t>(
        samples, static_cast<size_t>(config.max_samples), static_cast<size_t>(INT32_MAX)));
    // A render shows what a sensation feels like, so it sizes the parameter memory to fit
    // (0: every slot and sample); the device's own byte budget is the runtime's concern.
    config.pool_bytes = 0;
    return config;
}

sim::TargetMotion parse_motion(const std::string& spec, double duration_s, int32_t axis_count) {
    try {
        return sim::TargetMotion::parse(spec, duration_s, axis_count);
    } catch (const std::invalid_argument& e) {
        const std::string message = e.what();
        if (message.find("--motion") != std::string::npos) throw;
        throw std::invalid_argument("--motion \"" + spec + "\": " + message);
    }
}

bool is_surface(EffectType type) noexcept {
    return type == EffectType::axis_wall || type == EffectType::angle_wall || type == EffectType::axis_barrier ||
           type == EffectType::angle_barrier;
}

// The mark of a wall or barrier effect, its `at` the block's offset (a relative wall adds
// the handle's position along u when it begins playing: place_relative()).
SurfaceMark surface_mark(const format::Sensation& sensation, size_t index) {
    const EffectParams& p = sensation.effects[index].params;
    SurfaceMark m;
    m.effect = sensation.compound ? sensation.name + " effect " + std::to_string(index) : sensation.name;
    m.barrier = p.type == EffectType::axis_barrier || p.type == EffectType::angle_barrier;
    const bool angled = p.type == EffectType::angle_wall || p.type == EffectType::angle_barrier;
    m.axis = angled ? -1 : axis_index(p.axes[0]);
    if (m.barrier) {
        m.angle = angled ? p.barrier.angle : 0;
        m.at = p.barrier.offset;
        m.thickness = p.barrier.thickness;
    } else {
        m.angle = angled ? p.wall.angle : 0;
        m.at = p.wall.offset;
        m.solid_above = p.wall.sense == WallSense::positive;
        m.clipping = p.wall.clipping;
        m.relative = p.wall.offset_mode == OffsetMode::relative;
    }
    return m;
}

// A relative wall's surface: offset + start·u, start the sensed position the engine saw
// on the effect's first playing tick.
void place_relative(SurfaceMark& m, const float start[kMaxAxes]) {
    if (m.axis >= 0) {
        m.at += start[m.axis];
        return;
    }
    const double a = m.angle * std::numbers::pi / 18000.0;
    m.at += std::sin(a) * start[0] + std::cos(a) * start[1];
}

}  // namespace

sim::InputSchedule input_schedule(const std::vector<Press>& presses, const sim::DeviceProfile& profile) {
    sim::InputSchedule schedule(profile);
    for (const Press& p : presses) {
        try {
            if (p.control.kind == TriggerKind::hat) {
                schedule.push_hat(p.press_us, p.control.index).center_hat(p.release_us, p.control.index);
            } else {
                schedule.press(p.press_us, p.control.index).release(p.release_us, p.control.index);
            }
        } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--press on device " + std::string(profile.name) + ": " + e.what());
        }
    }
    return schedule;
}

Trace render(const format::Sensation& sensation, const RenderOptions& options) {
    if (options.profile == nullptr) {
        throw std::invalid_argument("--device: no device profile given (render needs one)");
    }
    const sim::DeviceProfile& profile = *options.profile;
    const int64_t rate = checked_rate(options.rate_hz);
    const double duration_s = checked_duration(sensation, options.duration_s);
    const double exact_ticks = duration_s * static_cast<double>(rate);
    if (exact_ticks > static_cast<double>(kMaxTicks)) {
        throw std::invalid_argument(
            "--duration * --rate = " + format_number(exact_ticks) + " ticks is too many (allowed " +
            "at most " + std::to_string(kMaxTicks) + "; lower --rate or --duration)");
    }
    const int64_t ticks = std::max<int64_t>(1, std::llround(exact_ticks));

    sim::SimDevice device(profile, options.grip,
                          parse_motion(options.motion, duration_s, profile.axis_count));

    Engine engine(engine_config_for(sensation, profile));
    std::vector<EffectId> ids;
    ids.reserve(sensation.effects.size());
    for (size_t i = 0; i < sensation.effects.size(); ++i) {
        const format::EffectSpec& spec = sensation.effects[i];
        const CreateResult created = engine.create(spec.params, spec.samples);
        if (created.error) throw_refused(sensation, i, spec.params, "refused", created.error);
        ids.push_back(created.id);
    }
    // Effects with a trigger are reflexes: armed, started by their presses (§1.2.c).
    runtime::ReflexTable reflexes(static_cast<int32_t>(std::max<size_t>(1, ids.size())));
    if (const Error error = reflexes.assign_all(engine, ids)) {
        throw std::runtime_error("sensation \"" + sensation.name + "\": its triggers cannot be armed (" +
                                 std::string(error_code_name(error.code)) + "): " + error.message());
    }
    sim::InputSchedule inputs = input_schedule(options.presses, profile);
    // The device starts with nothing pressed (InputSchedule's script does), so a press at
    // t = 0 is a press edge at tick 0, not a button already held when the table first looks.
    reflexes.on_tick(0, 0, 0, engine);
    for (size_t i = 0; i < ids.size(); ++i) {
        if (sensation.effects[i].params.trigger.kind != TriggerKind::none) continue;
        if (const Error error = engine.start(ids[i])) {
            throw_refused(sensation, i, sensation.effects[i].params, "could not start", error);
        }
    }

    Trace trace;
    trace.axis_count = profile.axis_count;
    trace.rate_hz = static_cast<double>(rate);
    trace.rows.resize(static_cast<size_t>(ticks));
    trace.has_hand = options.grip != sim::Grip::none;
    for (const format::EffectSpec& e : sensation.effects) {
        if (effect_class(e.params.type) == EffectClass::dynamic) trace.has_dynamics = true;
    }
    // Relative walls wait for their first playing tick to know where they are.
    struct Unplaced {
        SurfaceMark mark;
        EffectId id;
    };
    std::vector<Unplaced> unplaced;
    for (size_t i = 0; i < sensation.effects.size(); ++i) {
        if (!is_surface(sensation.effects[i].params.type)) continue;
        SurfaceMark mark = surface_mark(sensation, i);
        if (mark.relative) unplaced.push_back({std::move(mark), ids[i]});
        else trace.surfaces.push_back(std::move(mark));
    }
    for (int64_t n = 0; n < ticks; ++n) {
        TickInput in;
        in.t_us = tick_time_us(n, rate);
        (void)inputs.apply(device, in.t_us);
        device.sense(in);
        const uint64_t fired_before = reflexes.fired();
        reflexes.on_tick(in, engine);
        for (uint64_t k = fired_before; k < reflexes.fired(); ++k) trace.reflex_starts_us.push_back(in.t_us);
        TickOutput out;
        engine.tick(in, out);
        for (auto u = unplaced.begin(); u != unplaced.end();) {
            if (engine.status(u->id).state != EffectState::playing) {
                ++u;
                continue;
            }
            place_relative(u->mark, in.position);
            trace.surfaces.push_back(std::move(u->mark));
            u = unplaced.erase(u);
        }
        const sim::TargetMotion::Sample target = device.motion().at(static_cast<double>(in.t_us) * 1e-6);

        TraceRow& row = trace.rows[static_cast<size_t>(n)];
        row.t_us = in.t_us;
        row.saturated = out.saturated;
        for (int a = 0; a < profile.axis_count; ++a) {
            row.position[a] = static_cast<float>(device.position(a));
            row.velocity[a] = static_cast<float>(device.velocity(a));
            row.force[a] = out.force[a];
            row.reported[a] = out.reported_position[a];
            row.target[a] = static_cast<float>(target.position[a]);
            row.mass_relative[a] = out.mass_position[a];
            row.mass_velocity[a] = out.mass_velocity[a];
            row.mass_absolute[a] = out.has_mass ? in.position[a] + out.mass_position[a] : 0.0f;
        }
        row.has_mass = out.has_mass;
        DynamicReport report;
        while (engine.pop_report(report)) {
            if (report.kind == DynamicReport::Kind::final) trace.final_reports.push_back(report);
            else ++trace.interim_reports;
        }
        const double dt_s = static_cast<double>(tick_time_us(n + 1, rate) - in.t_us) * 1e-6;
        device.step(out.force, dt_s);
    }
    return trace;
}

}  // namespace feel::render
