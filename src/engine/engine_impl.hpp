// The engine's private state, shared by the files that implement Engine's methods.
//
// engine.cpp holds the tick and the effect commands; other engine_*.cpp files may add
// methods that need the slots. Nothing outside src/engine includes this header.
#pragma once

#include <cmath>
#include <memory>

#include "conditions/condition.hpp"
#include "dynamics/dynamic.hpp"
#include "effect_clock.hpp"
#include "feel/engine.hpp"
#include "motion_estimator.hpp"
#include "record_pool.hpp"
#include "sample_pool.hpp"

namespace feel {
namespace detail {

// A dynamic's memory: its parameters' block (SlotParams::dynamic points here), and between
// ticks its simulated mass and its interim reports' schedule.
struct DynamicRecord {
    SlotDynamicBlock block{};
    DynamicState state{};
    int64_t next_interim_us = 0;  // when the next interim report is due
#if !defined(__OPTIMIZE_SIZE__)
    // A Dynamic Sling's: the next slot above its own that holds a created sling, or -1
    // (Engine::Impl::link_slings). The tick's pairing of slings (kPairSlings, x86) follows
    // this chain instead of testing every slot between two slings.
    int32_t next_sling = -1;
#endif
};

// A dynamic report as the engine's queue holds it (Engine::pop_report widens it to the
// host's DynamicReport): the kind and the axis count (1..kMaxAxes) in the bytes the host's
// record pads after its id, so a report takes 40 bytes instead of 48 on 2 axes (issue 14:
// RAM on a Cortex-M4F). Every value is the host record's, exactly.
struct QueuedReport {
    EffectId effect{};
    DynamicReport::Kind kind = DynamicReport::Kind::interim;
    int8_t axis_count = 0;
    int64_t t_us = 0;
    float position[kMaxAxes] = {};
    float velocity[kMaxAxes] = {};
    float handle_velocity[kMaxAxes] = {};
};

// How the tick renders a slot, worked out once by prepare_slot from its type, class and
// parameters, so that the tick tests one byte: a scalar wave (value · direction,
// is_scalar_wave) that is a periodic or not; any other wave; a condition; friction and
// texture, which render after every other effect of the tick (their stiction holds against
// what the others push with this tick: ConditionContext::others_force); a dynamic; a
// Dynamic Sling, rendered with the next playing one (kPairSlings; elsewhere a dynamic).
enum class SlotRoute : uint8_t { periodic, scalar_wave, wave, condition, renders_last, dynamic, sling };

struct Slot {
    SlotParams params{};  // the header and its type's block (slot_params.hpp)
    // The clock: the effect time of the current or last play, advanced by the tick's length
    // at every tick it runs (0 at its first: the same integer as that tick's time minus its
    // start, and pause, which freezes it, needs no start time to move). Next to params
    // (96 bytes on the board, a multiple of 8) so that the slot pads nothing before it.
    int64_t elapsed_us = 0;
#if FEEL_KEEPS_ITERATION_START
    // The current iteration's window in the same effect time: it began at
    // iteration_start_us (start delay + iteration · duration) and lasts iteration_span_us
    // (the duration, INT64_MAX when endless). Kept by the tick when it reads the clock the
    // long way (read_clock); 0 (no window) after every command that moves the clock or
    // changes its parameters (prepare_slot, begin_play). See clock().
    int64_t iteration_start_us = 0;
    uint64_t iteration_span_us = 0;
#endif
    // What the tick needs of params every tick, worked out once per command (prepare_slot).
    // Fields widest first, so that the slot pads little (issue 14's RAM).
    float direction[kMaxAxes] = {};       // force per unit value on each device axis
    float direction_gain[kMaxAxes] = {};  // direction · gain_factor, for scalar waves
    float start_position[kMaxAxes] = {};  // sensed position when the effect began playing
    float gain_factor = 0.0f;             // params.gain / kFullScale
    detail::ConditionLaw render_condition = nullptr;  // conditions: condition_renderer(params)
    // The effect's memory between ticks, if its type keeps any (memory_kind): its record in
    // the engine's pool of its kind (Engine::Impl::dynamic_pool, ::condition_pool), held
    // from create to destroy; null for the others. The live member follows cls.
    union {
        detail::ConditionState* condition_memory = nullptr;
        detail::DynamicRecord* dynamic_memory;
    };

    // The commands (engine_commands.cpp). The parameter memory an effect holds is not kept:
    // it is slot_pool_bytes(params) (pool_cost.cpp).
    int32_t completed_iterations = 0;      // of the current or last play, set by the tick
    uint32_t starts = 0;                   // times started since created
    int16_t iterations_override = 0;       // this play's count from start(id, n, solo); 0 = the effect's
    uint16_t generation = 0;

    EffectClass cls = EffectClass::wave;
    bool reads_acceleration = false;     // inertia, or Dynamic Inertia
    Waveform waveform = Waveform::sine;  // periodics and sweeps: waveform_of(params.type)
    SlotRoute route = SlotRoute::wave;   // how the tick renders it (prepare_slot)
    EffectState state = EffectState::free;
    bool began_playing = false;          // start_position is set
    PlayEnd last_end = PlayEnd::none;    // how the last play ended

    // The iteration count of the current play: Engine::start's override, else the effect's.
    // Read the effect's clock with it: detail::read_clock(params, play_iterations(), t).
    [[nodiscard]] int32_t play_iterations() const noexcept {
        return iterations_override != 0 ? iterations_override : params.iterations;
    }

    // The clock at effect time elapsed (≥ 0): detail::read_clock(params, play_iterations(),
    // elapsed, completed_iterations), the same reading.
    [[nodiscard, gnu::always_inline]] ClockReading clock(int64_t elapsed) const noexcept {
        ClockReading r;
        if (in_iteration_window(elapsed, r)) return r;
        return read_clock(params, play_iterations(), elapsed, completed_iterations);
    }

    // The reading at elapsed_us the long way, by the tick, which keeps the window it finds
    // (after in_iteration_window has not found it there).
    [[nodiscard, gnu::always_inline]] ClockReading advance_clock() noexcept {
        const ClockReading r = read_clock(params, play_iterations(), elapsed_us, completed_iterations);
#if FEEL_KEEPS_ITERATION_START
        if (r.phase == ClockPhase::playing) {
            iteration_start_us = elapsed_us - r.tau_us;
            iteration_span_us = params.duration_us == kInfiniteUs ? uint64_t{INT64_MAX}
                                                                  : static_cast<uint64_t>(params.duration_us);
        }
#endif
        return r;
    }

    // After a command that moves the clock (a new play) or changes its parameters.
    void forget_iteration_start() noexcept {
#if FEEL_KEEPS_ITERATION_START
        iteration_span_us = 0;
#endif
    }

    // Most ticks an effect stays in the iteration it was in: when elapsed −
    // iteration_start_us lies in [0, span) (one unsigned comparison), the iteration is the
    // one the last reading found (read_clock's floor(t / duration) is that iteration for
    // such a t), which was not finished and cannot be now (the count and the parameters
    // have not changed since, or the span would be 0), and τ is that difference: one
    // subtraction and one comparison instead of read_clock's five tests. Into r, if so.
    [[nodiscard, gnu::always_inline]] bool in_iteration_window([[maybe_unused]] int64_t elapsed,
                                                              [[maybe_unused]] ClockReading& r) const noexcept {
#if FEEL_KEEPS_ITERATION_START
        const int64_t tau = elapsed - iteration_start_us;
        if (static_cast<uint64_t>(tau) < iteration_span_us) {
            r = ClockReading{ClockPhase::playing, tau, completed_iterations};
            return true;
        }
#endif
        return false;
    }
};

// Whether an effect of this type keeps memory between ticks, in which pool: dynamics their
// simulated mass (DynamicRecord), friction and texture their bristles and walls and barriers
// their contact ledger (ConditionState). Waves, springs, dampers and inertia keep none.
enum class MemoryKind : uint8_t { none, dynamic, condition };
[[nodiscard]] constexpr MemoryKind memory_kind(EffectType t) noexcept {
    switch (t) {
        case EffectType::friction:
        case EffectType::texture:
        case EffectType::axis_wall:
        case EffectType::angle_wall:
        case EffectType::axis_barrier:
        case EffectType::angle_barrier: return MemoryKind::condition;
        default: return effect_class(t) == EffectClass::dynamic ? MemoryKind::dynamic : MemoryKind::none;
    }
}

// The capacities an EngineConfig asks for, its 0s resolved (EngineConfig::max_dynamics,
// max_stateful_conditions: 0 is one per effect slot).
[[nodiscard]] constexpr int32_t dynamics_capacity(const EngineConfig& c) noexcept {
    return c.max_dynamics == 0 ? c.max_effects : c.max_dynamics;
}
[[nodiscard]] constexpr int32_t stateful_conditions_capacity(const EngineConfig& c) noexcept {
    return c.max_stateful_conditions == 0 ? c.max_effects : c.max_stateful_conditions;
}

// Works out a slot's per-tick constants (direction, class, gain) from its params: after
// every command that sets them, never in the tick.
void prepare_slot(Slot& s) noexcept;

// Checks every field of an EngineConfig; an invalid config makes an engine that refuses
// every create with this error.
[[nodiscard]] Error check_engine_config(const EngineConfig& c) noexcept;

// The parameter memory of an engine made with c (EngineConfig::pool_bytes, or when that is
// 0 the bytes of max_effects of the largest effect plus max_samples samples), in bytes.
[[nodiscard]] int64_t pool_capacity_bytes(const EngineConfig& c) noexcept;

// The parameter memory a slot's effect holds: effect_pool_bytes of its parameters.
[[nodiscard]] int32_t slot_pool_bytes(const SlotParams& params) noexcept;

// The device_full error of an effect that needs `needed` bytes where `free_bytes` are free:
// value = needed, allowed = 0..free_bytes, for a host that wants the numbers.
[[nodiscard]] Error pool_full_error(int32_t needed, int32_t free_bytes) noexcept;

// The whole microseconds of one period at hz (1..1000, as check_engine_config admits):
// floor(1e6 / hz), in integers. hz is m · 2^e exactly (m its 24-bit significand), so this is
// (1e6 · 2^-e) / m. It equals the double quotient 1e6 / hz truncated: when the quotient is
// not whole it is at least 1/m > 2^-24 from every integer, and double's rounding of it moves
// it by at most 1e6 · 2^-53 < 2^-36, never across one (every float in 1..1000 checked too).
[[nodiscard]] int64_t period_us_of(float hz) noexcept;

}  // namespace detail

struct Engine::Impl {
    explicit Impl(const EngineConfig& c)
        : config(c),
          config_invalid(static_cast<bool>(detail::check_engine_config(c))),
          slot_count(config_invalid ? 0 : c.max_effects),
          // The arrays' counts as 16 bits: every capacity is at most 65535 (check_engine_config),
          // and a count the compiler knows is that small needs no test for an overflowing
          // size (issue 14's flash).
          slots(new detail::Slot[static_cast<uint16_t>(slot_count > 0 ? slot_count : 1)]()),
          dynamic_pool(config_invalid ? 0 : detail::dynamics_capacity(c)),
          condition_pool(config_invalid ? 0 : detail::stateful_conditions_capacity(c)),
          // Only friction and texture render last, and each holds a condition's memory.
          last_slots(new uint16_t[static_cast<uint16_t>(condition_pool.capacity() > 0 ? condition_pool.capacity() : 1)]),
          samples(config_invalid ? 0 : c.max_samples, slot_count),
          report_capacity(config_invalid ? 1 : c.report_capacity),
          reports(new detail::QueuedReport[static_cast<uint16_t>(report_capacity)]()) {
        motion.configure(c.sensor_step);
        // Once, not per report (an invalid rate is refused by check_engine_config: no dynamic plays).
        interim_period_us = config_invalid ? 1000 : detail::period_us_of(c.interim_report_hz);
        pool_total_bytes = config_invalid ? 0 : static_cast<int32_t>(detail::pool_capacity_bytes(c));
    }

    // Puts a slot at the beginning of a new play (start, a restarting update, a reflex): it
    // begins at the next tick that is not paused.
    void begin_play(detail::Slot& s, int32_t iterations_override) noexcept {
        s.state = EffectState::pending;
        s.began_playing = false;
        reset_memory(s);
        s.iterations_override = static_cast<int16_t>(iterations_override);  // validated: -1..255
        s.completed_iterations = 0;
        s.elapsed_us = 0;
        s.forget_iteration_start();
        s.last_end = PlayEnd::none;
        ++s.starts;
    }

    // Free records in the pool of a kind of memory (1 for none: there is nothing to take).
    [[nodiscard]] int32_t free_records(detail::MemoryKind kind) const noexcept {
        return kind == detail::MemoryKind::dynamic     ? dynamic_pool.free_count()
               : kind == detail::MemoryKind::condition ? condition_pool.free_count()
                                                       : 1;
    }

    // The device_full error of a create whose type's memory pool is full: the field names
    // the capacity, value = the effects of that kind with this one, allowed.max = capacity.
    [[nodiscard]] Error memory_full_error(detail::MemoryKind kind) const noexcept {
        const bool dynamic = kind == detail::MemoryKind::dynamic;
        Error e = Error::out_of_range(
            dynamic ? "resident dynamics (EngineConfig::max_dynamics)" : "stateful conditions (max_stateful_conditions)",
            int64_t{dynamic ? dynamic_pool.capacity() : condition_pool.capacity()} + 1,
            Range{0, dynamic ? dynamic_pool.capacity() : condition_pool.capacity()});
        e.code = ErrorCode::device_full;
        return e;
    }

    // Stores valid parameters in a slot holding its record (a dynamic's block into the record).
    static void store_params(detail::Slot& s, const EffectParams& p) noexcept {
        const bool dynamic = effect_class(p.type) == EffectClass::dynamic;
        if (dynamic) s.dynamic_memory->block = detail::slot_dynamic_block(p);
        s.params = detail::slot_params(p, dynamic ? &s.dynamic_memory->block : nullptr);
    }

    // Takes a record of the slot's kind for a slot being created (free_records said there is one).
    void acquire_memory(detail::Slot& s, detail::MemoryKind kind) noexcept {
        if (kind == detail::MemoryKind::dynamic) {
            s.dynamic_memory = dynamic_pool.acquire();
        } else {
            s.condition_memory = kind == detail::MemoryKind::condition ? condition_pool.acquire() : nullptr;
        }
    }

    // Starts the slot's memory afresh (cls must be set: prepare_slot); a dynamic's block stays.
    static void reset_memory(const detail::Slot& s) noexcept {
        if (s.cls == EffectClass::dynamic) {
            s.dynamic_memory->state = detail::DynamicState{};
            s.dynamic_memory->next_interim_us = 0;
        } else if (s.cls == EffectClass::condition && s.condition_memory != nullptr) {
            s.condition_memory->start_fresh(s.params.type);
        }
    }

    // prepare_slot, and a dynamic's per-tick form of its parameters (or a friction's laws)
    // marked stale.
    void prepare(detail::Slot& s) noexcept {
        acceleration_readers -= s.reads_acceleration ? 1 : 0;
        prepare_new(s);
        if (s.cls == EffectClass::dynamic) s.dynamic_memory->state.prepared = false;
        if (s.cls == EffectClass::condition && s.condition_memory != nullptr) {
            s.condition_memory->params_changed(s.params.type);
        }
    }

    // prepare_slot for a slot being created (its old constants were counted off when freed).
    void prepare_new(detail::Slot& s) noexcept {
        detail::prepare_slot(s);
        acceleration_readers += s.reads_acceleration ? 1 : 0;
    }

    // The tick's length in seconds (detail::tick_seconds_of), worked out again only when the
    // length changes, which at a fixed loop rate is never: a division a change, none a tick.
    float tick_seconds(int64_t dt_us) noexcept {
        if (dt_us != tick_length_us) {
            tick_length_us = dt_us;
            tick_length_s = detail::tick_seconds_of(dt_us);
        }
        return tick_length_s;
    }

    // Frees a slot: its samples, bytes and memory return to their pools, its handles go stale.
    void free_slot(detail::Slot& s, int32_t index) noexcept {
        samples.release(index);
        acceleration_readers -= s.reads_acceleration ? 1 : 0;
        if (s.cls == EffectClass::dynamic) {
            dynamic_pool.release(s.dynamic_memory);
        } else if (s.cls == EffectClass::condition && s.condition_memory != nullptr) {
            condition_pool.release(s.condition_memory);
        }
        s.condition_memory = nullptr;
        pool_used_bytes -= slot_pool_bytes(s.params);
        s.state = EffectState::free;
        ++s.generation;
        while (slot_end > 0 && slots[slot_end - 1].state == EffectState::free) --slot_end;
        if (s.params.type == EffectType::dynamic_sling) link_slings();
    }

    // The slings' chain (DynamicRecord::next_sling), linked again after a sling is created
    // or freed: each created sling's record names the next slot above it holding one.
    void link_slings() noexcept {
#if !defined(__OPTIMIZE_SIZE__)
        int32_t next = -1;
        for (int32_t j = slot_end - 1; j >= 0; --j) {
            detail::Slot& t = slots[j];
            if (t.state == EffectState::free || t.params.type != EffectType::dynamic_sling) continue;
            t.dynamic_memory->next_sling = next;
            next = j;
        }
#endif
    }

    // Stops a slot by command; a play that was under way ends as `stopped`.
    static void stop_play(detail::Slot& s) noexcept {
        if (s.state == EffectState::pending || s.state == EffectState::delayed ||
            s.state == EffectState::playing) {
            s.last_end = PlayEnd::stopped;
        }
        if (s.state != EffectState::free) s.state = EffectState::stopped;
    }

    // The report queue: a ring the tick writes and the host drains (single thread for now;
    // the device runtime puts a lock-free SPSC queue between them).
    void push_report(const detail::QueuedReport& r) noexcept {
        if (report_count == report_capacity) {
            ++reports_dropped;
            return;
        }
        reports[(report_head + report_count) % report_capacity] = r;
        ++report_count;
    }

    // Interim reports at the configured rate while interim_reporting is set, a final report
    // when the dynamic ends by itself, and the first playing dynamic's mass in the output.
    void report_dynamic(detail::Slot& s, uint16_t index, int64_t t_us, const detail::DynamicResult& r,
                        const float* handle_velocity, TickOutput& out) noexcept {
        if (!out.has_mass) {
            out.has_mass = true;
            for (int a = 0; a < kMaxAxes; ++a) {
                out.mass_position[a] = r.mass_position[a];
                out.mass_velocity[a] = r.mass_velocity[a];
            }
        }
        int64_t& next_interim_us = s.dynamic_memory->next_interim_us;
        const bool interim_due = s.params.dynamic->interim_reporting && t_us >= next_interim_us;
        if (!interim_due && !r.finished) return;
        detail::QueuedReport report;
        report.effect = EffectId{index, s.generation};
        report.kind = r.finished ? DynamicReport::Kind::final : DynamicReport::Kind::interim;
        report.t_us = t_us;
        report.axis_count = s.params.axis_count;
        for (int i = 0; i < s.params.axis_count; ++i) {
            const int a = axis_index(s.params.axes[i]);
            report.position[i] = r.mass_position[a];
            report.velocity[i] = r.mass_velocity[a];
            report.handle_velocity[i] = handle_velocity[a];
        }
        push_report(report);
        if (interim_due) {
            // The next report is due one period after this one was due, so the rate holds on
            // average even when the period is not a whole number of ticks.
            const int64_t period_us = interim_period_us;
            next_interim_us = (next_interim_us == 0 ? t_us : next_interim_us) + period_us;
            if (next_interim_us <= t_us) next_interim_us = t_us + period_us;
        }
    }

    detail::Slot* find(EffectId id) noexcept {
        if (id.index >= slot_count) return nullptr;
        detail::Slot& s = slots[id.index];
        return (s.state != EffectState::free && s.generation == id.generation) ? &s : nullptr;
    }

    EngineConfig config;
    // The config was refused: every create fails with check_engine_config(config), worked
    // out again when asked (the config never changes) rather than kept (88 bytes).
    bool config_invalid;
    int32_t slot_count;
    std::unique_ptr<detail::Slot[]> slots;
    // The effects' memory between ticks, by kind (record_pool.hpp; Slot::condition_memory,
    // Slot::dynamic_memory).
    detail::RecordPool<detail::DynamicRecord> dynamic_pool;
    detail::RecordPool<detail::ConditionState> condition_pool;
    // The tick's slots that render last (Slot::renders_last), gathered during its first pass:
    // their indices (max_effects is at most 65535). Their wave time is read again from their
    // clocks, not kept (2 bytes an entry where index and time took 16: issue 14's RAM).
    std::unique_ptr<uint16_t[]> last_slots;
    int32_t slot_end = 0;  // every slot from here on is free: the tick looks no further
    int32_t acceleration_readers = 0;  // created slots that read the acceleration (Slot::reads_acceleration)
    detail::SamplePool samples;
    int32_t device_gain = kFullScale;
    detail::MotionEstimator motion;
    int64_t interim_period_us = 1000;  // between interim reports (EngineConfig::interim_report_hz)
    int32_t report_capacity;
    std::unique_ptr<detail::QueuedReport[]> reports;
    int32_t report_head = 0;
    int32_t report_count = 0;
    uint64_t reports_dropped = 0;
    bool have_previous = false;
    float applied_force[kMaxAxes] = {};  // the force commanded at the previous tick
    detail::AxisObservers observers;     // friction's stop guard: the handle on each axis
    int64_t previous_t_us = 0;
    int64_t tick_length_us = 0;  // tick_seconds: the last tick's length, and in seconds
    float tick_length_s = 0.0f;

    // Device control and the parameter memory (engine_commands.cpp).
    int32_t pool_total_bytes = 0;
    int32_t pool_used_bytes = 0;
    bool paused = false;             // effect clocks frozen, output zero
    bool actuators_enabled = true;   // false: effects run, output zero
};

}  // namespace feel
