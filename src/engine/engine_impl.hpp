// The engine's private state, shared by the files that implement Engine's methods.
//
// engine.cpp holds the tick and the effect commands; other engine_*.cpp files may add
// methods that need the slots. Nothing outside src/engine includes this header.
#pragma once

#include <cmath>
#include <memory>

#include "conditions/condition.hpp"
#include "dynamics/dynamic.hpp"
#include "feel/engine.hpp"
#include "motion_estimator.hpp"
#include "sample_pool.hpp"

namespace feel {
namespace detail {

struct Slot {
    Slot() noexcept : condition{} {}  // the union's first state live; every other field as declared

    EffectParams params{};
    float direction[kMaxAxes] = {};  // force per unit value on each device axis
    // What the tick needs of params every tick, worked out once per command (prepare_slot):
    EffectClass cls = EffectClass::wave;
    bool reads_acceleration = false;  // inertia, or Dynamic Inertia
    float gain_factor = 0.0f;         // params.gain / kFullScale
    Waveform waveform = Waveform::sine;  // periodics and sweeps: waveform_of(params.type)
    bool scalar_wave = false;            // waves whose force is value · direction (is_scalar_wave)
    // Two flags of the clock and the commands below, kept here where they fill the padding
    // after the flags above (16 bytes a slot less: issue 14's RAM).
    bool began_playing = false;            // start_position is set
    PlayEnd last_end = PlayEnd::none;      // how the last play ended
    float direction_gain[kMaxAxes] = {}; // direction · gain_factor, for those
    detail::ConditionCurve curves[kMaxAxes] = {};  // params.conditions (condition.hpp)
    detail::ConditionLaw render_condition = nullptr;  // conditions: condition_renderer(params)
    // Friction and texture render after every other effect of the tick: their stiction holds
    // against what the others push with this tick (ConditionContext::others_force).
    bool renders_last = false;
    EffectState state = EffectState::free;
    uint16_t generation = 0;
    int64_t start_t_us = 0;
    float start_position[kMaxAxes] = {};   // sensed position when the effect began playing
    // The effect's memory between ticks: a condition's (bristles, contact ledger) or a
    // dynamic's (its simulated mass), never both, so they share the bytes. Which one is
    // live follows cls; reset_memory() starts the live one afresh.
    union {
        detail::ConditionState condition;
        detail::DynamicState dynamic;
    };
    int64_t next_interim_us = 0;           // when the next interim report is due

    // Commands and the parameter memory (engine_commands.cpp, pool_cost.cpp).
    int32_t iterations_override = 0;       // this play's count from start(id, n, solo); 0 = the effect's
    int32_t completed_iterations = 0;      // of the current or last play, set by the tick
    int64_t elapsed_us = 0;                // effect time of the current or last play, set by the tick
    uint32_t starts = 0;                   // times started since created
    int32_t pool_bytes = 0;                // parameter memory this effect holds (effect_pool_bytes)

    // Starts the memory of the slot's class afresh (cls must be set: prepare_slot). Both
    // states are trivially copyable, so assigning one makes it the union's live member.
    void reset_memory() noexcept {
        if (cls == EffectClass::dynamic) {
            dynamic = detail::DynamicState{};
        } else {
            condition = detail::ConditionState{};
        }
    }

    // The iteration count of the current play: Engine::start's override, else the effect's.
    // Read the effect's clock with it: detail::read_clock(params, play_iterations(), t).
    [[nodiscard]] int32_t play_iterations() const noexcept {
        return iterations_override != 0 ? iterations_override : params.iterations;
    }
};

// Works out a slot's per-tick constants (direction, class, gain) from its params: after
// every command that sets them, never in the tick.
void prepare_slot(Slot& s) noexcept;

// Checks every field of an EngineConfig; an invalid config makes an engine that refuses
// every create with this error.
[[nodiscard]] Error check_engine_config(const EngineConfig& c) noexcept;

// The parameter memory of an engine made with c (EngineConfig::pool_bytes, or when that is
// 0 the bytes of max_effects of the largest effect plus max_samples samples), in bytes.
[[nodiscard]] int64_t pool_capacity_bytes(const EngineConfig& c) noexcept;

// The device_full error of an effect that needs `needed` bytes where `free_bytes` are free:
// value = needed, allowed = 0..free_bytes, for a host that wants the numbers.
[[nodiscard]] Error pool_full_error(int32_t needed, int32_t free_bytes) noexcept;

}  // namespace detail

struct Engine::Impl {
    explicit Impl(const EngineConfig& c)
        : config(c),
          config_error(detail::check_engine_config(c)),
          slot_count(config_error ? 0 : c.max_effects),
          slots(new detail::Slot[static_cast<size_t>(slot_count > 0 ? slot_count : 1)]),
          last_slots(new LastSlot[static_cast<size_t>(slot_count > 0 ? slot_count : 1)]),
          samples(config_error ? 0 : c.max_samples, slot_count),
          report_capacity(config_error ? 1 : c.report_capacity),
          reports(new DynamicReport[static_cast<size_t>(report_capacity)]) {
        motion.configure(c.sensor_step);
        // Once, not per report (an invalid rate is refused by check_engine_config: no dynamic plays).
        interim_period_us = config_error ? 1000 : static_cast<int64_t>(1e6 / c.interim_report_hz);
        pool_total_bytes = config_error ? 0 : static_cast<int32_t>(detail::pool_capacity_bytes(c));
    }

    // Puts a slot at the beginning of a new play (start, a restarting update, a reflex): it
    // begins at the next tick that is not paused.
    void begin_play(detail::Slot& s, int32_t iterations_override) noexcept {
        s.state = EffectState::pending;
        s.began_playing = false;
        s.reset_memory();
        s.next_interim_us = 0;
        s.iterations_override = iterations_override;
        s.completed_iterations = 0;
        s.elapsed_us = 0;
        s.last_end = PlayEnd::none;
        ++s.starts;
    }

    // Frees a slot: its samples and bytes return to the pool, its handles go stale.
    void free_slot(detail::Slot& s, int32_t index) noexcept {
        samples.release(index);
        pool_used_bytes -= s.pool_bytes;
        s.pool_bytes = 0;
        s.state = EffectState::free;
        ++s.generation;
        while (slot_end > 0 && slots[slot_end - 1].state == EffectState::free) --slot_end;
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
    void push_report(const DynamicReport& r) noexcept {
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
        const bool interim_due = s.params.dynamic.interim_reporting && t_us >= s.next_interim_us;
        if (!interim_due && !r.finished) return;
        DynamicReport report;
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
            s.next_interim_us = (s.next_interim_us == 0 ? t_us : s.next_interim_us) + period_us;
            if (s.next_interim_us <= t_us) s.next_interim_us = t_us + period_us;
        }
    }

    detail::Slot* find(EffectId id) noexcept {
        if (id.index >= slot_count) return nullptr;
        detail::Slot& s = slots[id.index];
        return (s.state != EffectState::free && s.generation == id.generation) ? &s : nullptr;
    }

    EngineConfig config;
    Error config_error;
    int32_t slot_count;
    std::unique_ptr<detail::Slot[]> slots;
    // The tick's slots that render last (Slot::renders_last), gathered during its first pass.
    struct LastSlot {
        int32_t index = 0;
        int64_t tau_us = 0;
    };
    std::unique_ptr<LastSlot[]> last_slots;
    int32_t slot_end = 0;  // every slot from here on is free: the tick looks no further
    detail::SamplePool samples;
    int32_t device_gain = kFullScale;
    detail::MotionEstimator motion;
    int64_t interim_period_us = 1000;  // between interim reports (EngineConfig::interim_report_hz)
    int32_t report_capacity;
    std::unique_ptr<DynamicReport[]> reports;
    int32_t report_head = 0;
    int32_t report_count = 0;
    uint64_t reports_dropped = 0;
    bool have_previous = false;
    float applied_force[kMaxAxes] = {};  // the force commanded at the previous tick
    detail::AxisObservers observers;     // friction's stop guard: the handle on each axis
    int64_t previous_t_us = 0;

    // Device control and the parameter memory (engine_commands.cpp).
    int32_t pool_total_bytes = 0;
    int32_t pool_used_bytes = 0;
    bool paused = false;             // effect clocks frozen, output zero
    bool actuators_enabled = true;   // false: effects run, output zero
};

}  // namespace feel
