// The engine tick, the way a device's local processor runs it (§2.2):
//
//   for each effect slot that is playing:
//       read its clock        (start delay, iterations: effect_clock.cpp)
//       render its force      (waves/: a function of the wave time τ only)
//       scale by its gain and add it to the axes it acts on
//   scale the sum by the device gain, clamp each axis to the device maximum
//
// Slots live in one array sized at construction; handles carry a generation so a handle
// to a freed slot is refused instead of reaching its successor. Nothing here reads a clock,
// allocates or throws: time arrives in TickInput. While the device is paused the loop
// above is skipped and every running effect's start time moves with the clock, so effect
// time stands still; with the actuators off it runs and only the output is zeroed
// (engine_commands.cpp has the other commands and the parameter memory).
#include "feel/engine.hpp"

#include "engine_impl.hpp"

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "conditions/condition.hpp"
#include "conditions/contact_surface.hpp"
#include "direction.hpp"
#include "dynamics/dynamic.hpp"
#include "effect_clock.hpp"
#include "engine_support.hpp"
#include "feel/effect_validation.hpp"
#include "motion_estimator.hpp"
#include "sample_pool.hpp"
#include "time_division.hpp"
#include "waves/wave.hpp"

namespace feel {
namespace {

using detail::ClockPhase;
using detail::Slot;

// A periodic or sweep wave (sine .. sweep_saw_down, contiguous in EffectType): a vibration
// meant to be felt, which friction's stiction lets through (the tick's `vibration`).
constexpr bool oscillates(EffectType t) noexcept {
    return t >= EffectType::sine && t <= EffectType::sweep_saw_down;
}
static_assert(oscillates(EffectType::saw_down) && oscillates(EffectType::sweep_sine) &&
              !oscillates(EffectType::force_profile) && !oscillates(EffectType::smart_pop));

// The first slot above slot i (a sling) holding a Dynamic Sling that plays this tick, or -1,
// with its clock: the tick loop's own test (its state, its clock after this tick's dt_us),
// made ahead of the loop reaching it so that two slings can render together
// (detail::render_sling_pair). It visits the slings only, along their chain
// (DynamicRecord::next_sling: every created sling above i, in slot order).
int32_t next_playing_sling([[maybe_unused]] const Slot* slots, [[maybe_unused]] int32_t i,
                           [[maybe_unused]] int64_t dt_us, [[maybe_unused]] detail::ClockReading& clock) noexcept {
#if !defined(__OPTIMIZE_SIZE__)  // kPairSlings: the chain is x86's
    for (int32_t j = slots[i].dynamic_memory->next_sling; j >= 0; j = slots[j].dynamic_memory->next_sling) {
        const Slot& t = slots[j];
        if (t.state == EffectState::stopped) continue;  // a sling in the chain is never free
        const int64_t elapsed_us = t.state == EffectState::pending ? 0 : t.elapsed_us + dt_us;
        clock = t.clock(elapsed_us);
        if (clock.phase == ClockPhase::playing) return j;
    }
#endif
    return -1;
}

// Two playing slings render together (detail::render_sling_pair): the first renders both,
// and the second's force and result wait here until the tick's loop reaches its slot, so
// the forces are summed in slot order as ever.
struct SlingPairing {
    int32_t waiting = -1;  // the slot whose force and result wait, or -1
    float force[kMaxAxes] = {};
    detail::DynamicResult result;
};

// The sling in slot i (context c) into force and result: what waits for it, or it and the
// next playing sling together, or it alone. Out of line, so that the tick's loop over every
// slot keeps its registers (inline, this cost the loop about 10 instructions a slot).
[[gnu::noinline]] void render_sling(SlingPairing& pairing, Slot* slots, int32_t i, int64_t dt_us,
                                    const detail::DynamicContext& c, float force[kMaxAxes],
                                    detail::DynamicResult& result) noexcept {
    if (i == pairing.waiting) {
        for (int a = 0; a < kMaxAxes; ++a) force[a] = pairing.force[a];
        result = pairing.result;
        return;
    }
    detail::ClockReading clock;
    const int32_t other = detail::sling_rests(c) ? -1 : next_playing_sling(slots, i, dt_us, clock);
    if (other < 0) {
        detail::render_dynamic(c, force, result);
        return;
    }
    Slot& t = slots[other];
    // A sling reads no start position; the loop sets t's when it reaches t.
    const detail::DynamicContext second{&t.params,
                                        c.config,
                                        c.position,
                                        c.velocity,
                                        c.acceleration,
                                        t.began_playing ? t.start_position : c.position,
                                        c.dt_s,
                                        clock.tau_us,
                                        &t.dynamic_memory->state};
    for (float& f : pairing.force) f = 0.0f;
    pairing.result = {};
    detail::render_sling_pair(c, second, force, pairing.force, result, pairing.result);
    pairing.waiting = other;
}

}  // namespace

namespace {

// check_engine_config's fields as tables, in the order they are checked (the first that
// fails is the error): on the Cortex-M4 build, where flash is counted (docs/firmware.md),
// each check written out as code built its own 88-byte Error (976 bytes for the function);
// a row is 12 or 8 bytes.
struct ConfigCountRule {
    const char* name;
    uint16_t offset;  // of an int32_t in EngineConfig
    int32_t max;      // kUpToMaxEffects: the device's max_effects
    int32_t min;
};
constexpr int32_t kUpToMaxEffects = -1;

struct ConfigScaleRule {
    const char* name;
    uint16_t offset;  // of a float in EngineConfig
    bool zero_allowed;
};

constexpr ConfigCountRule kConfigCounts[] = {
    {"axis_count", offsetof(EngineConfig, axis_count), kMaxAxes, 1},
    {"max_effects", offsetof(EngineConfig, max_effects), 65535, 1},
    {"max_samples", offsetof(EngineConfig, max_samples), 1 << 24, 0},
    {"pool_bytes", offsetof(EngineConfig, pool_bytes), 1 << 30, 0},
    {"max_dynamics", offsetof(EngineConfig, max_dynamics), kUpToMaxEffects, 0},
    {"max_stateful_conditions", offsetof(EngineConfig, max_stateful_conditions), kUpToMaxEffects, 0},
    {"report_capacity", offsetof(EngineConfig, report_capacity), 65535, 1},  // after the scales
};

constexpr ConfigScaleRule kConfigScales[] = {
    {"velocity_ref", offsetof(EngineConfig, velocity_ref), false},
    {"acceleration_ref", offsetof(EngineConfig, acceleration_ref), false},
    {"sensor_step", offsetof(EngineConfig, sensor_step), false},
    {"device_damping", offsetof(EngineConfig, device_damping), true},
    {"device_mass", offsetof(EngineConfig, device_mass), true},
    {"wall_stiffness", offsetof(EngineConfig, wall_stiffness), false},
    {"dynamic_mass_ref", offsetof(EngineConfig, dynamic_mass_ref), false},
    {"dynamic_stiffness_ref", offsetof(EngineConfig, dynamic_stiffness_ref), false},
    {"dynamic_damping_ref", offsetof(EngineConfig, dynamic_damping_ref), false},
    {"gravity_ref", offsetof(EngineConfig, gravity_ref), false},
};

// The counts in rules[first, last) into `out`; whether one failed.
bool refuse_config_counts(const EngineConfig& c, int first, int last, Error& out) noexcept {
    for (int i = first; i < last; ++i) {
        const ConfigCountRule& r = kConfigCounts[i];
        int32_t value = 0;
        std::memcpy(&value, reinterpret_cast<const unsigned char*>(&c) + r.offset, sizeof value);
        const Range allowed{r.min, r.max == kUpToMaxEffects ? c.max_effects : r.max};
        if (!allowed.contains(value)) {
            out = Error::out_of_range(r.name, value, allowed);
            return true;
        }
    }
    return false;
}

}  // namespace

Error detail::check_engine_config(const EngineConfig& c) noexcept {
    Error out;
    constexpr int kReportCapacity = 6;  // kConfigCounts' last row, checked after the scales
    if (refuse_config_counts(c, 0, kReportCapacity, out)) return out;
    for (const ConfigScaleRule& r : kConfigScales) {
        float v = 0.0f;
        std::memcpy(&v, reinterpret_cast<const unsigned char*>(&c) + r.offset, sizeof v);
        if (!(r.zero_allowed ? v >= 0 : v > 0) || !std::isfinite(v)) {
            return Error::invalid(r.name, r.zero_allowed ? "must be a finite number >= 0"
                                                         : "must be a finite number > 0");
        }
    }
    if (!(c.interim_report_hz >= 1.0f && c.interim_report_hz <= 1000.0f))
        return Error::invalid("interim_report_hz", "must be between 1 and 1000 Hz");
    if (refuse_config_counts(c, kReportCapacity, kReportCapacity + 1, out)) return out;
    return detail::check_supported_types(c);
}

int64_t detail::period_us_of(float hz) noexcept {
    const auto bits = std::bit_cast<uint32_t>(hz);
    const int exponent = static_cast<int>(bits >> 23) - 150;    // hz = significand · 2^exponent
    const int64_t significand = (bits & 0x7fffffu) | 0x800000u;  // hz is normal (1..1000)
    // 1..1000 Hz: the exponent is -23..-14, so the dividend stays below 2^43; the significand
    // is 24 bits, so the board divides it without a 64-bit division (time_division.hpp).
    return time_quotient(int64_t{1'000'000} << -exponent, static_cast<int32_t>(significand));
}

void detail::prepare_slot(Slot& s) noexcept {
    s.forget_iteration_start();
    direction_factors(s.params, s.direction);
    s.cls = effect_class(s.params.type);
    if (is_periodic(s.params.type) || is_sweep(s.params.type)) s.waveform = waveform_of(s.params.type);
    s.reads_acceleration = s.params.type == EffectType::inertia || s.params.type == EffectType::dynamic_inertia;
    s.gain_factor = static_cast<float>(s.params.gain) * (1.0f / static_cast<float>(kFullScale));
    s.render_condition = s.cls == EffectClass::condition ? condition_renderer(s.params) : nullptr;
    const EffectType type = s.params.type;
    if (s.cls == EffectClass::wave) {
        s.route = !is_scalar_wave(s.params) ? detail::SlotRoute::wave
                  : oscillates(type)        ? detail::SlotRoute::periodic
                                            : detail::SlotRoute::scalar_wave;
    } else if (s.cls == EffectClass::condition) {
        s.route = type == EffectType::friction || type == EffectType::texture ? detail::SlotRoute::renders_last
                                                                              : detail::SlotRoute::condition;
    } else {
        s.route = detail::kPairSlings && type == EffectType::dynamic_sling ? detail::SlotRoute::sling
                                                                          : detail::SlotRoute::dynamic;
    }
    for (int a = 0; a < kMaxAxes; ++a) s.direction_gain[a] = s.direction[a] * s.gain_factor;
    detail::element_direction(s.params, s.direction);  // walls and barriers: u across the surface
}

namespace {

float finite_or_zero(float v) noexcept { return std::isfinite(v) ? v : 0.0f; }

// Whether the tick adds the axes' forces in two unrolled lanes: on a device of 2 axes, and on
// every device of a build for at most 2 (FEEL_MAX_AXES=2, the board's), where the loop over
// the axes is then never compiled. On a 1-axis device the second lane adds into sum[1] and
// vibration[1], which nothing reads (the output and the others' force take the device's axes
// only): the forces on its axis are the loop's. (others[1], which a friction or texture along
// a direction reads, keeps its loop.)
constexpr bool two_lanes(int axes) noexcept { return kMaxAxes == 2 || axes == 2; }

// Between the loads of a renderer's force on the two axes of the common device: the
// renderers store each axis by itself, and x86's vectorizer would read both with one 8-byte
// load, which cannot take its data from two 4-byte stores still in the store queue and waits
// for them to reach the cache (a store-forwarding stall). A profile of the 40-effect mix put a
// third of the tick's own time on that load. The empty statement keeps the loads apart (the
// compiler may not move a load across it); it emits no instruction.
inline void separate_loads() noexcept { asm("" ::: "memory"); }

// Whether the tick calls a scalar periodic wave itself (x86) or through scalar_wave_value
// (the board's build for size, where the second call site is flash): the same call.
#if !defined(__OPTIMIZE_SIZE__)
constexpr bool kCallsPeriodicDirectly = true;
#else
constexpr bool kCallsPeriodicDirectly = false;
#endif

// What a condition's and a dynamic's context (alike in these fields) share with every other
// of the tick: set once a tick, not per effect.
template <class Context>
void set_shared_motion(Context& c, const EngineConfig& config, const float* position, const float* velocity,
                       const float* acceleration, float dt_s) noexcept {
    c.config = &config;
    c.position = position;
    c.velocity = velocity;
    c.acceleration = acceleration;
    c.dt_s = dt_s;
}

// Gains are in units of 1/kFullScale: a multiplication by this, not a division per effect.
constexpr float kPerFullScale = 1.0f / static_cast<float>(kFullScale);

}  // namespace


Engine::Engine(const EngineConfig& config) : impl_(std::make_unique<Impl>(config)) {}
Engine::~Engine() = default;

const EngineConfig& Engine::config() const noexcept { return impl_->config; }

CreateResult Engine::create(const EffectParams& params, std::span<const int16_t> samples) noexcept {
    Impl& m = *impl_;
    if (m.config_invalid) return {{}, detail::check_engine_config(m.config)};
    if (Error e = validate_effect(params, samples)) return {{}, e};
    for (int i = 0; i < params.axis_count; ++i) {
        if (axis_index(params.axes[i]) >= m.config.axis_count) {
            char field[16] = "axes[0]";
            field[5] = static_cast<char>('0' + i);
            return {{}, Error::invalid(field, "names an axis this device does not have")};
        }
    }
    if (Error e = detail::check_supported(m.config, params.type)) return {{}, e};

    int32_t index = -1;
    for (int32_t i = 0; i < m.slot_count; ++i) {
        if (m.slots[i].state == EffectState::free) {
            index = i;
            break;
        }
    }
    if (index < 0) return {{}, Error::of(ErrorCode::device_full, "", "every effect slot is in use")};
    const int32_t bytes = effect_pool_bytes(params);
    if (bytes > m.pool_total_bytes - m.pool_used_bytes) {
        return {{}, detail::pool_full_error(bytes, m.pool_total_bytes - m.pool_used_bytes)};
    }
    const detail::MemoryKind memory = detail::memory_kind(params.type);
    if (m.free_records(memory) == 0) return {{}, m.memory_full_error(memory)};
    const bool is_profile = params.type == EffectType::force_profile;
    if (is_profile && !m.samples.allocate(index, samples.data(), static_cast<int32_t>(samples.size()))) {
        return {{}, Error::of(ErrorCode::device_full, "custom.samples", "not enough free sample memory")};
    }

    Slot& s = m.slots[index];
    m.acquire_memory(s, memory);
    Impl::store_params(s, params);
    s.state = EffectState::stopped;
    s.began_playing = false;
    s.iterations_override = 0;
    s.completed_iterations = 0;
    s.elapsed_us = 0;
    s.starts = 0;
    s.last_end = PlayEnd::none;
    m.pool_used_bytes += bytes;
    m.prepare_new(s);
    m.reset_memory(s);
    if (index >= m.slot_end) m.slot_end = index + 1;
    if (params.type == EffectType::dynamic_sling) m.link_slings();
    return {EffectId{static_cast<uint16_t>(index), s.generation}, {}};
}

Error Engine::destroy(EffectId id) noexcept {
    Slot* s = impl_->find(id);
    if (!s) return Error::of(ErrorCode::invalid_handle, "", "no such effect");
    impl_->free_slot(*s, id.index);
    return {};
}

Error Engine::start(EffectId id) noexcept {
    Slot* s = impl_->find(id);
    if (!s) return Error::of(ErrorCode::invalid_handle, "", "no such effect");
    impl_->begin_play(*s, 0);
    return {};
}

Error Engine::stop(EffectId id) noexcept {
    Slot* s = impl_->find(id);
    if (!s) return Error::of(ErrorCode::invalid_handle, "", "no such effect");
    Impl::stop_play(*s);
    return {};
}

void Engine::stop_all() noexcept {
    for (int32_t i = 0; i < impl_->slot_count; ++i) Impl::stop_play(impl_->slots[i]);
}

EffectState Engine::state(EffectId id) const noexcept {
    const Slot* s = impl_->find(id);
    return s ? s->state : EffectState::free;
}

Error Engine::set_gain(int32_t gain) noexcept {
    if (!range::kGain.contains(gain)) return Error::out_of_range("gain", gain, range::kGain);
    impl_->device_gain = gain;
    return {};
}

int32_t Engine::gain() const noexcept { return impl_->device_gain; }

void Engine::tick(const TickInput& in, TickOutput& out) noexcept {
    Impl& m = *impl_;
    const int axes = m.config_invalid ? 0 : m.config.axis_count;

    // The handle's motion as the conditions see it: sensed position, estimated velocity
    // and acceleration. The reported position starts as the sensed one; clipping walls
    // may hold it at their surface.
    const int64_t dt_us = m.have_previous ? in.t_us - m.previous_t_us : 0;
    const float dt_s = m.tick_seconds(dt_us);
    // The acceleration costs as much as the velocity and only inertia and Dynamic Inertia
    // (control_law_dynamic.cpp) read it: fitted only in ticks where one plays. Without one
    // created (most ticks) the slots are not looked at.
    bool inertia_plays = false;
    for (int32_t i = 0; i < (m.acceleration_readers > 0 ? m.slot_end : 0) && !inertia_plays; ++i) {
        const Slot& s = m.slots[i];
        inertia_plays = s.reads_acceleration && s.state != EffectState::free && s.state != EffectState::stopped;
    }
    m.motion.update(in.t_us, in.position, axes, inertia_plays);
    float velocity[kMaxAxes] = {};
    float acceleration[kMaxAxes] = {};
    for (int a = 0; a < kMaxAxes; ++a) {
        velocity[a] = a < axes ? finite_or_zero(m.motion.velocity(a)) : 0.0f;
        acceleration[a] = a < axes && inertia_plays ? finite_or_zero(m.motion.acceleration(a)) : 0.0f;
        out.velocity[a] = velocity[a];
        out.acceleration[a] = acceleration[a];
        out.reported_position[a] = a < axes ? in.position[a] : 0.0f;
        out.mass_position[a] = 0.0f;
        out.mass_velocity[a] = 0.0f;
    }
    out.has_mass = false;
    m.previous_t_us = in.t_us;
    m.have_previous = true;

    // Single precision (issue 14): forces are within ±10000 per effect and a sum of a few
    // hundred effects keeps float's 7 digits far beyond a unit.
    float sum[kMaxAxes] = {};
    // What the periodic and sweep waves add to sum: a vibration, not a push. Friction's
    // stiction balances the others' push (friction_model.hpp, hold_with_others) but not
    // this part, so a rumble played with a friction is felt by a hand holding the handle
    // still (docs/conditions.md, "Stiction balances the engine's push").
    float vibration[kMaxAxes] = {};
    int32_t playing = 0;
    // Pause freezes every effect's clock (§2.2 device control): the loop below, which
    // advances each running effect's time by the tick's length, is skipped, so its elapsed
    // time stands still and it resumes exactly where it was. Pending effects wait for the
    // first running tick. Nothing renders, so conditions and dynamics keep their state too.
    const int32_t slot_end = m.paused ? 0 : m.slot_end;
    // What every condition sees alike this tick; the loop fills in each one's own part.
    detail::ConditionContext condition;
    set_shared_motion(condition, m.config, in.position, velocity, acceleration, dt_s);
    condition.reported_position = out.reported_position;
    condition.axes = axes;
    condition.velocity_scale = static_cast<float>(kFullScale) / m.config.velocity_ref;
    condition.acceleration_scale = static_cast<float>(kFullScale) / m.config.acceleration_ref;
    condition.applied_force = m.applied_force;  // friction's stop guard: last tick's force
    condition.device_gain = static_cast<float>(m.device_gain) * kPerFullScale;
    // What every dynamic sees alike this tick, likewise.
    detail::DynamicContext dynamic;
    set_shared_motion(dynamic, m.config, in.position, velocity, acceleration, dt_s);
    int32_t last_count = 0;
    SlingPairing pairing;
    Slot* const slots = m.slots.get();  // once: the loop's stores could alias the member
    for (int32_t i = 0; i < slot_end; ++i) {
        Slot& s = slots[i];
        detail::ClockReading clock;
        if (s.state == EffectState::playing && s.in_iteration_window(s.elapsed_us + dt_us, clock)) {
            // Most slots, most ticks (x86): still in the iteration the last tick played, so
            // still playing, its start position set (Slot::in_iteration_window).
            s.elapsed_us += dt_us;
        } else {
            if (s.state == EffectState::free || s.state == EffectState::stopped) continue;
            s.elapsed_us = s.state == EffectState::pending ? 0 : s.elapsed_us + dt_us;
            clock = s.advance_clock();
            if (clock.phase == ClockPhase::finished) {
                s.state = EffectState::stopped;
                s.last_end = PlayEnd::finished;
                s.completed_iterations = s.play_iterations();
                continue;
            }
            s.completed_iterations = clock.iteration;
            if (clock.phase == ClockPhase::delayed) {
                s.state = EffectState::delayed;
                continue;
            }
            s.state = EffectState::playing;
            if (!s.began_playing) {
                for (int a = 0; a < kMaxAxes; ++a) s.start_position[a] = in.position[a];
                s.began_playing = true;
            }
        }
        ++playing;

        const detail::SlotRoute route = s.route;
        if (route <= detail::SlotRoute::scalar_wave) {
            // Most waves: one value along a fixed direction, gain included (prepare_slot).
            // A scalar wave that oscillates is a periodic (sweeps are not scalar): on x86 the
            // tick calls it without scalar_wave_value's dispatch on the type, which would
            // take the same call (its default).
            const bool periodic = route == detail::SlotRoute::periodic;
            float value = 0.0f;
            if (kCallsPeriodicDirectly && periodic) {
                value = detail::periodic_wave(s.params, s.waveform, clock.tau_us);
            } else {
                const detail::WaveInput wave{&s.params, s.direction,
                                             s.params.type == EffectType::force_profile ? m.samples.data(i) : nullptr,
                                             clock.tau_us, s.waveform, axes};
                value = detail::scalar_wave_value(wave);
            }
            if (two_lanes(axes)) {  // the common device, unrolled
                sum[0] += value * s.direction_gain[0];
                sum[1] += value * s.direction_gain[1];
            } else {
                for (int a = 0; a < axes; ++a) sum[a] += value * s.direction_gain[a];
            }
            if (periodic) {
                if (two_lanes(axes)) {
                    vibration[0] += value * s.direction_gain[0];
                    vibration[1] += value * s.direction_gain[1];
                } else {
                    for (int a = 0; a < axes; ++a) vibration[a] += value * s.direction_gain[a];
                }
            }
            continue;
        }
        if (route == detail::SlotRoute::renders_last) {
            m.last_slots[last_count++] = static_cast<uint16_t>(i);
            continue;
        }
        float force[kMaxAxes] = {};
        if (route >= detail::SlotRoute::dynamic) {
            // A dynamic adds its force in float (the paddle's contact, which steps in double,
            // rounds its push once: docs/tick-cost.md, "Where double remains").
            dynamic.params = &s.params;
            dynamic.start_position = s.start_position;
            dynamic.tau_us = clock.tau_us;
            dynamic.state = &s.dynamic_memory->state;
            detail::DynamicResult result;
            if (detail::kPairSlings && route == detail::SlotRoute::sling) {
                render_sling(pairing, slots, i, dt_us, dynamic, force, result);
            } else {
                detail::render_dynamic(dynamic, force, result);
            }
            m.report_dynamic(s, static_cast<uint16_t>(i), in.t_us, result, velocity, out);
            if (result.finished) {
                s.state = EffectState::stopped;
                s.last_end = PlayEnd::finished;
                --playing;
                continue;  // its last force is not applied: the event is over
            }
        } else if (route == detail::SlotRoute::condition) {
            condition.params = &s.params;
            condition.start_position = s.start_position;
            condition.direction = s.direction;
            condition.tau_us = clock.tau_us;
            condition.state = s.condition_memory;
            condition.curves = s.params.curved.curves;
            s.render_condition(condition, force);
        } else {
            const detail::WaveInput wave{&s.params, s.direction,
                                         s.params.type == EffectType::force_profile ? m.samples.data(i) : nullptr,
                                         clock.tau_us, s.waveform, axes};
            detail::render_wave(wave, force);
            if (oscillates(s.params.type)) {
                if (two_lanes(axes)) {  // the common device, unrolled
                    vibration[0] += force[0] * s.gain_factor;
                    vibration[1] += force[1] * s.gain_factor;
                } else {
                    for (int a = 0; a < axes; ++a) vibration[a] += force[a] * s.gain_factor;
                }
            }
        }
        if (two_lanes(axes)) {  // the common device, unrolled
            const float f0 = force[0];
            separate_loads();
            sum[0] += f0 * s.gain_factor;
            sum[1] += force[1] * s.gain_factor;
        } else {
            for (int a = 0; a < axes; ++a) sum[a] += force[a] * s.gain_factor;
        }
    }

    const float device_gain = static_cast<float>(m.device_gain) * kPerFullScale;
    if (last_count > 0) {
        // Friction and texture, once the others' force of this tick is known: each sees the
        // sum of everything rendered before it, at the motors' scale.
        float others[kMaxAxes] = {};
        for (int a = 0; a < axes; ++a) others[a] = (sum[a] - vibration[a]) * device_gain;
        condition.others_force = others;
        // Friction's stop guard watches the handle through one observer per axis, shared by
        // every friction (stop_guard.hpp, AxisObservers).
        detail::observe_axes(m.observers, m.config, dt_s, in.t_us, in.t_us - dt_us, in.position, velocity,
                             m.applied_force, axes);
        condition.observers = &m.observers;
        for (int32_t k = 0; k < last_count; ++k) {
            Slot& s = slots[m.last_slots[k]];
            condition.params = &s.params;
            condition.start_position = s.start_position;
            condition.direction = s.direction;
            // (No tau_us and no curves: friction and texture read neither, so the clock is
            // not read again here; the context keeps the last condition's.)
            condition.state = s.condition_memory;
            float force[kMaxAxes] = {};
            s.render_condition(condition, force);
            if (axes == 2) {  // the common device, unrolled (others[1] is read on 2 axes only)
                const float f0 = force[0];
                separate_loads();
                const float f1 = force[1];
                sum[0] += f0 * s.gain_factor;
                sum[1] += f1 * s.gain_factor;
                others[0] += f0 * s.gain_factor * device_gain;
                others[1] += f1 * s.gain_factor * device_gain;
            } else {
                for (int a = 0; a < axes; ++a) {
                    sum[a] += force[a] * s.gain_factor;
                    others[a] += force[a] * s.gain_factor * device_gain;
                }
            }
        }
    }

    // Paused or actuators off: the motors get nothing (sum is zero while paused anyway).
    const bool output_on = m.actuators_enabled && !m.paused;
    constexpr float kLimit = static_cast<float>(kFullScale);
    out.saturated = false;
    for (int a = 0; a < kMaxAxes; ++a) {
        float f = a < axes && output_on ? sum[a] * device_gain : 0.0f;
        if (!std::isfinite(f)) f = 0.0f;  // never pass NaN or inf to a motor
        if (f > kLimit || f < -kLimit) {
            f = f > 0 ? kLimit : -kLimit;
            out.saturated = true;
        }
        out.force[a] = f;
        m.applied_force[a] = f;
    }
    out.playing_effects = playing;
}

bool Engine::pop_report(DynamicReport& report) noexcept {
    Impl& m = *impl_;
    if (m.report_count == 0) return false;
    const detail::QueuedReport& queued = m.reports[m.report_head];
    report = DynamicReport{};
    report.effect = queued.effect;
    report.kind = queued.kind;
    report.t_us = queued.t_us;
    report.axis_count = queued.axis_count;
    for (int i = 0; i < kMaxAxes; ++i) {
        report.position[i] = queued.position[i];
        report.velocity[i] = queued.velocity[i];
        report.handle_velocity[i] = queued.handle_velocity[i];
    }
    m.report_head = (m.report_head + 1) % m.report_capacity;
    --m.report_count;
    return true;
}

uint64_t Engine::dropped_reports() const noexcept { return impl_->reports_dropped; }

}  // namespace feel
