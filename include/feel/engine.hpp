// feel — the effect engine: a fixed pool of effect slots rendered once per tick.
//
// The engine is the part of feel that runs on the device's local processor (§2.2). It is
// built with -fno-exceptions -fno-rtti and allocates only in its constructor: every
// capacity (effect slots, parameter bytes, force-profile sample memory) is fixed there, and
// a create that does not fit reports ErrorCode::device_full instead of growing.
//
// Time is an input. tick() takes the time and the sensor state and returns the force on
// each axis; effect math never reads a clock, so the same inputs give bit-identical
// outputs.
//
// Real-time safety: every method but the constructor and destructor is noexcept and never
// allocates or locks. tick(), start(), stop(), stop_all(), status(), set_gain(), pause(),
// resume(), set_actuators_enabled() and pool() take constant or O(slots) time. create(),
// update() and destroy() may copy or compact sample data (O(sample memory)), and reset()
// frees every slot, so call them from the loop's command queue, not from an interrupt.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include <string_view>

#include "feel/axis.hpp"
#include "feel/effect.hpp"
#include "feel/effect_type.hpp"
#include "feel/status.hpp"

namespace feel {

// A set of effect types as a bit mask: bit effect_type_bit(t) for each type t in the set.
[[nodiscard]] constexpr uint64_t effect_type_bit(EffectType t) noexcept {
    return uint64_t{1} << static_cast<unsigned>(t);
}
inline constexpr uint64_t kAllEffectTypes = (uint64_t{1} << kEffectTypeCount) - 1;

struct EngineConfig {
    int32_t axis_count = 2;         // 1..6: the device's axes are x, y, z, rx, ry, rz in order
    int32_t max_effects = 64;       // effect slots (the "memory pool" of §2.2), 1..65535
    int32_t max_samples = 1 << 16;  // force-profile sample memory, in samples
    // Parameter memory, in bytes, 0..2^30 (§2.2): every resident effect costs the bytes of
    // the blocks it holds (effect_pool_bytes() below, docs/runtime.md), force-profile
    // samples 2 each. 0 sizes it to hold max_effects of the largest effect plus max_samples
    // samples, so only the slots and the sample memory limit creation.
    int32_t pool_bytes = 0;
    // The effects' memory between ticks, held from create to destroy (§2.2's "memory pool"
    // as RAM): how many Dynamic Sensations (a simulated mass each) and how many conditions
    // with memory (friction and texture: bristles; walls and barriers: a contact ledger) can
    // be resident at once, 0..max_effects. 0 is one per effect slot (every host profile);
    // a small device sets fewer (firmware/: 4 and 8 of 32 slots) and create() refuses the
    // one over with ErrorCode::device_full naming the capacity (docs/firmware.md, "RAM").
    int32_t max_dynamics = 0;
    int32_t max_stateful_conditions = 0;

    // What the engine knows of the device, in normalized units (docs/conventions.md).
    // feel::sim::engine_config_for(profile) fills these from a device profile.
    float velocity_ref = 1e5f;        // > 0, position units/s that conditions read as 10000
    float acceleration_ref = 1e7f;    // > 0, position units/s² that inertia reads as 10000
    float sensor_step = 20000.0f / 4096.0f;  // > 0, position units per sensor count
    // The mechanism's own viscous damping b, as force units per (position unit/s): the
    // physical damping times half_travel / max_force. The passivity bound of walls uses it.
    float device_damping = 0.0f;      // >= 0
    // The mechanism's moving mass m, force units per (position unit/s²): the physical mass
    // times half_travel / max_force. Friction uses it to tell a free handle coming to rest
    // from a held one (docs/conditions.md, "Friction"). 0: unknown.
    float device_mass = 0.0f;         // >= 0
    // Time-domain passivity observer and controller on walls and barriers (§3.7): lets
    // walls stiffer than the naive bound 2(b - B)/T stay stable. On by default.
    bool passivity_control = true;

    // Dynamic Sensations (§5): what the Dynamic Struct's integers mean on this device, in
    // normalized units (force units, position units, seconds). docs/dynamics.md explains
    // the mapping; feel::sim::engine_config_for(profile) sets them per profile. The
    // defaults are the joystick's. Velocities (VelInit, intensities) use velocity_ref.
    // > 0: mass of "mass 10000", force units per (position unit/s²). The profiles use
    // 10000/acceleration_ref, the mass full force accelerates at a brisk hand's acceleration
    // (the inertia condition's scale; 0.445 kg at the joystick's grip).
    float dynamic_mass_ref = 0.005f;
    // > 0: tether stiffness of "k 10000", force units per position unit. The profiles use
    // twice the naive passivity bound 2b/T (docs/dynamics.md: why that is stable).
    float dynamic_stiffness_ref = 22.47f;
    // > 0: damping of "b 10000" or "drag 10000", force units per (position unit/s). The
    // profiles use 2·sqrt(dynamic_stiffness_ref · dynamic_mass_ref): b 10000 critically
    // damps mass 10000 on tether 10000 against a held handle.
    float dynamic_damping_ref = 0.6704f;
    // > 0: acceleration of "gravity 10000", position units/s². The profiles use
    // 10000/dynamic_mass_ref, so mass 10000 at gravity 10000 weighs full force (on the
    // joystick and the 3-axis device that is about 1 g).
    float gravity_ref = 2.0e6f;
    // Interim reports of dynamics with interim_reporting set (§5.2): their rate, and the
    // capacity of the report queue the host drains with Engine::pop_report().
    float interim_report_hz = 60.0f;       // 1..1000
    int32_t report_capacity = 256;         // 1..65535; reports beyond it are dropped and counted
    // The stiffness of a wall or barrier of hardness 10000 (§3.7, §3.8), in force units per
    // position unit (a spring coefficient of 10000 is 1). > 0 and finite. A hardness h
    // renders h/10000 of it. engine_config_for() sets it per profile to a multiple of the
    // profile's naive passivity bound 2b/T; the default is the joystick's (docs/stability.md).
    float wall_stiffness = 56.18f;

    // The effect types the device plays (EnumEffects, §6.2; an I-FORCE 1.x-class device has
    // no Dynamics, §5.1): effect_type_bit(t) set for each. create() refuses any other type
    // with ErrorCode::not_supported. Bits beyond the kEffectTypeCount types are invalid.
    // feel::sim::engine_config_for(profile) takes it from the profile. Default: all 33.
    uint64_t supported_types = kAllEffectTypes;
    // The device's class, named in not_supported errors, e.g. "I-FORCE 1.x"; empty for none.
    // Must outlive the engine (the profiles' names are static).
    std::string_view device_class = {};
};

// A handle to an effect slot. The generation makes a handle to a freed slot stale.
struct EffectId {
    uint16_t index = 0xFFFF;
    uint16_t generation = 0;
    [[nodiscard]] bool valid() const noexcept { return index != 0xFFFF; }
    friend bool operator==(EffectId, EffectId) = default;
};

struct CreateResult {
    EffectId id{};
    Error error{};
};

enum class EffectState : uint8_t {
    free,      // the slot holds nothing (stale handle)
    stopped,   // created, not playing (never started, stopped, or finished)
    pending,   // started; begins at the next tick
    delayed,   // playing, inside its start delay
    playing,   // playing, producing force
};

// How an effect's last play ended.
enum class PlayEnd : uint8_t {
    none,      // never started, or its current play has not ended
    stopped,   // stopped by a command: stop, stop_all, a solo start of another effect
    finished,  // ran to its end by itself: all iterations done, or a dynamic that ended
};

// What Engine::status() tells of one effect (DirectInput's GetEffectStatus, and more).
struct EffectStatus {
    EffectState state = EffectState::free;
    // The iteration count of the current or last play: 1..255 or kInfiniteIterations (the
    // effect's own, or the count Engine::start was given); 0 if it was never started.
    int32_t iterations = 0;
    // Iterations of the current or last play that ran to their end, 0..iterations. While
    // playing it is also the 0-based index of the iteration that plays.
    int32_t completed_iterations = 0;
    // Effect time since the current or last play began, µs, >= 0: it excludes the time the
    // device was paused. 0 while pending. An endless effect's reading grows without bound.
    int64_t elapsed_us = 0;
    uint32_t starts = 0;              // times started since it was created (wraps at 2^32)
    PlayEnd last_end = PlayEnd::none;
};

// Which fields of EffectParams Engine::update() changes (DirectInput's DIEP_* flags). Fields
// outside the mask keep their values; the effect's type never changes.
namespace effect_field {
inline constexpr uint32_t kDuration = 1u << 0;       // duration_us
inline constexpr uint32_t kStartDelay = 1u << 1;     // start_delay_us
inline constexpr uint32_t kGain = 1u << 2;           // gain
inline constexpr uint32_t kIterations = 1u << 3;     // iterations
inline constexpr uint32_t kAxes = 1u << 4;           // axis_count and axes
inline constexpr uint32_t kDirection = 1u << 5;      // direction
inline constexpr uint32_t kTrigger = 1u << 6;        // trigger (button or hat)
inline constexpr uint32_t kTriggerRepeat = 1u << 7;  // trigger_repeat_interval_us
inline constexpr uint32_t kEnvelope = 1u << 8;       // has_envelope and envelope
// The blocks of the effect's type (conditions, periodic, constant, ramp, custom, texture,
// wall, barrier, dynamic); a force profile's samples come with it.
inline constexpr uint32_t kTypeSpecific = 1u << 9;
inline constexpr uint32_t kAll = (1u << 10) - 1;
}  // namespace effect_field

// The parameter memory (§2.2), from Engine::pool().
struct PoolInfo {
    int32_t total_bytes = 0;    // parameter memory, bytes (EngineConfig::pool_bytes or derived)
    int32_t free_bytes = 0;     // bytes no resident effect holds
    int32_t max_effects = 0;    // effect slots: the most effects resident (and playing) at once
    int32_t free_effects = 0;   // slots free
    // Of those, how many dynamics and conditions with memory can be resident at once
    // (EngineConfig::max_dynamics, max_stateful_conditions, 0 resolved) and are still free.
    int32_t max_dynamics = 0;
    int32_t free_dynamics = 0;
    int32_t max_stateful_conditions = 0;
    int32_t free_stateful_conditions = 0;
    int32_t total_samples = 0;  // force-profile sample storage, samples (EngineConfig::max_samples)
    int32_t free_samples = 0;
};

// The cost table of the parameter memory, in bytes. The sizes of the I-FORCE protocol's
// parameter blocks where it has one (as the Linux iforce driver allocates them: effect
// 14, envelope 14, periodic 12, magnitude 2, condition 8 per axis); the blocks it lacks
// count 2 bytes per 16-bit field. docs/runtime.md explains each.
namespace pool_cost {
inline constexpr int32_t kEffect = 14;            // every effect: the Effect Structure (§6.3)
inline constexpr int32_t kEnvelope = 14;          // has_envelope (§6.3 Envelope Struct)
inline constexpr int32_t kConstant = 2;           // constant, vector_force, smart_pop (§6.6.c)
inline constexpr int32_t kPeriodic = 12;          // sine .. saw_down (§6.6.b)
inline constexpr int32_t kAdvancedPeriodic = 16;  // sweeps: periodic + angles and sense (§6.6.i)
inline constexpr int32_t kRamp = 4;               // start, end (§6.6.e)
inline constexpr int32_t kCustom = 8;             // channels, sample period, count, where (§6.6.d)
inline constexpr int32_t kSample = 2;             // each force-profile sample
inline constexpr int32_t kCondition = 8;          // per condition block: per axis, angle_spring 1
inline constexpr int32_t kTexture = 8;            // §6.6.j
inline constexpr int32_t kWall = 12;              // §6.6.h
inline constexpr int32_t kBarrier = 14;           // §6.6.g
inline constexpr int32_t kDynamicAxis = 20;       // per axis: the control law (§6.6.f, §8.4)
}  // namespace pool_cost

// The bytes of parameter memory an effect costs (the table above). Assumes params passed
// validate_effect(). Real-time safe.
[[nodiscard]] int32_t effect_pool_bytes(const EffectParams& params) noexcept;

// What the engine is told each tick. Positions come from the device's quantized sensors.
struct TickInput {
    int64_t t_us = 0;                   // time of this tick, µs, non-decreasing
    float position[kMaxAxes] = {};      // normalized, ±10000 of each axis's travel
    uint32_t buttons = 0;               // bit i = button i+1 pressed
    uint32_t hats = 0;                  // bit h-1 = hat switch h (1..4) pushed off center
    // The dead-man switch (§2.2): true while a hand properly engages the handle. A device
    // without such a switch reports true. The engine ignores it; the runtime's
    // SafetyMonitor (feel/runtime/safety.hpp) cuts every force while it is false.
    bool handle_held = true;
};

struct TickOutput {
    float force[kMaxAxes] = {};         // normalized ±10000, physical sign, clamped
    float velocity[kMaxAxes] = {};      // the engine's velocity estimate, normalized units/s
    // The engine's acceleration estimate, units/s²: fitted only in ticks where an inertia
    // condition plays (it costs as much as the velocity), else 0.
    float acceleration[kMaxAxes] = {};
    // The position the device reports to the host: the sensed position, except where a
    // wall with clipping on holds it at the wall surface while the handle penetrates (§3.7).
    float reported_position[kMaxAxes] = {};
    int32_t playing_effects = 0;        // effects producing force this tick
    bool saturated = false;             // the sum was clamped on some axis this tick
    // The simulated mass of the first playing dynamic (lowest slot), relative to the
    // handle: what interim reporting would send, every tick. has_mass is false when no
    // dynamic plays.
    bool has_mass = false;
    float mass_position[kMaxAxes] = {};  // position units, mass minus handle
    float mass_velocity[kMaxAxes] = {};  // position units/s, mass minus handle
};

// A report of a dynamic's simulated mass to the host (§5.2, §6.6.f).
struct DynamicReport {
    enum class Kind : uint8_t {
        interim,  // while it plays, at EngineConfig::interim_report_hz, if interim_reporting
        final,    // once, when it ends by itself: a paddle ball leaving, half_cycles done
    };
    EffectId effect{};
    Kind kind = Kind::interim;
    int64_t t_us = 0;                    // the tick that produced it
    int32_t axis_count = 0;              // the effect's axes, in its order
    float position[kMaxAxes] = {};       // mass minus handle, position units, per effect axis
    float velocity[kMaxAxes] = {};       // mass minus handle, position units/s
    // The handle's own velocity at that tick (the engine's estimate), per effect axis: add
    // it to `velocity` for the mass's velocity in the fixed frame, e.g. where a paddle ball
    // flies off to.
    float handle_velocity[kMaxAxes] = {};  // position units/s
};

// What the engine played at its last tick, for the device's own filters: Intelligent
// Disturbance Filtering (§1.2.d, feel/runtime/idf.hpp) removes from the reported position
// the displacement these known forces cause. Plain fixed-size data, no heap.
enum class DisturbanceClass : uint8_t {
    periodic,  // vibrations: periodic and sweep waves, force profiles that loop
    impulse,   // jolts: constant, vector_force, smart_pop, ramp and one-shot force profiles
               // whose single play lasts at most kImpulseMaxUs
    other,     // known forces that are neither, e.g. an endless constant push
};
inline constexpr int kDisturbanceClassCount = 3;
// The longest single play of a jolt, µs: a gun's recoil or an asteroid's hit (§1.2.d) lasts
// tens of milliseconds; a push longer than a quarter second is a steady force, not a jolt.
inline constexpr int64_t kImpulseMaxUs = 250'000;
inline constexpr int kMaxActivityEffects = 32;

struct EffectActivity {
    EffectId id{};
    EffectType type = EffectType::constant;
    DisturbanceClass kind = DisturbanceClass::other;
    // periodic: the period of the vibration, µs (a periodic or sweep's period, a looping
    // force profile's loop length), 1..65e6; 0 for the other classes.
    int64_t period_us = 0;
    // Its force at the last tick on each device axis, normalized ±10000 units, physical
    // sign, after the effect's and the device's gain, before the engine's clamp.
    float force[kMaxAxes] = {};
};

struct EngineActivity {
    int64_t t_us = 0;      // the tick described: the last tick() (0 before the first)
    int32_t count = 0;     // entries of effects[] in use, 0..kMaxActivityEffects
    int32_t omitted = 0;   // playing waves beyond kMaxActivityEffects, left out of effects[]
    EffectActivity effects[kMaxActivityEffects] = {};  // playing waves, in slot order
    // Per class, the summed force of every playing wave of that class on each device axis,
    // omitted ones included: normalized units, after gains, before the clamp.
    float class_force[kDisturbanceClassCount][kMaxAxes] = {};
};

class Engine {
public:
    explicit Engine(const EngineConfig& config);
    ~Engine();
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // Validates and stores an effect in a free slot (download). Force profiles pass
    // their interleaved samples, which are copied into the engine's sample memory.
    [[nodiscard]] CreateResult create(const EffectParams& params,
                                      std::span<const int16_t> samples = {}) noexcept;
    Error destroy(EffectId id) noexcept;

    // Starts the effect at the next tick, from its beginning. Restarting a playing effect
    // restarts it.
    Error start(EffectId id) noexcept;
    // The same, playing `iterations` times (1..255 or kInfiniteIterations) instead of the
    // effect's own count, for this play only. solo stops every other effect first
    // (DirectInput's DIES_SOLO). A bad count changes nothing.
    Error start(EffectId id, int32_t iterations, bool solo) noexcept;
    Error stop(EffectId id) noexcept;
    void stop_all() noexcept;
    [[nodiscard]] EffectState state(EffectId id) const noexcept;
    // State and progress of one effect; state free for a stale handle.
    [[nodiscard]] EffectStatus status(EffectId id) const noexcept;
    // Copies the effect's parameters into `out` (what update() merges into). The device keeps
    // only what the effect reads: the other types' blocks, an envelope without has_envelope,
    // a trigger's index without a trigger, the condition blocks beyond the effect's axes, a
    // dynamic block's fields of the other dynamics (and a control law's beyond the effect's
    // axes) and the direction values its kind does not read come back as their defaults.
    Error params(EffectId id, EffectParams& out) const noexcept;

    // Changes the fields of `field_mask` (effect_field::k*) to those of `params`. The merged
    // parameters are checked (validate_effect, the device's axes, the pool) before anything
    // changes: on any error the effect is exactly as it was. The type cannot change
    // (params.type must be the effect's when kTypeSpecific is set). A force profile updating
    // kTypeSpecific passes its new samples. Without restart a playing effect keeps its
    // clock (time since it began) and its state, and plays on with the new parameters; a
    // stopped one stays stopped. With restart it (re)starts from its beginning, as start(id)
    // (DirectInput's DIEP_START).
    Error update(EffectId id, const EffectParams& params, uint32_t field_mask, bool restart,
                 std::span<const int16_t> samples = {}) noexcept;

    // Device gain, 0..10000, scales the summed force of every effect.
    Error set_gain(int32_t gain) noexcept;
    [[nodiscard]] int32_t gain() const noexcept;

    // Device control (DirectInput's DISFFC_*).
    // pause: every effect's clock stops where it is and the output is zero; resume lets
    // them go on from there. Effects started while paused begin at the first tick after
    // resume. Reflexes do not fire while paused (feel/runtime/reflexes.hpp).
    void pause() noexcept;
    void resume() noexcept;
    [[nodiscard]] bool paused() const noexcept;
    // Actuators off: effects play on (clocks run), but the output force is zero.
    void set_actuators_enabled(bool enabled) noexcept;
    [[nodiscard]] bool actuators_enabled() const noexcept;
    // The power-on state: every effect freed (handles go stale), device gain 10000, not
    // paused, actuators on, the dynamics report queue emptied.
    void reset() noexcept;

    // The parameter memory: bytes in all and free, effect slots in all and free.
    [[nodiscard]] PoolInfo pool() const noexcept;

    // Renders one tick. Never allocates, locks or throws; never outputs NaN or inf.
    void tick(const TickInput& in, TickOutput& out) noexcept;

    // Takes the oldest report of a dynamic (interim or final), if any. Real-time safe.
    [[nodiscard]] bool pop_report(DynamicReport& report) noexcept;
    // Reports lost because the queue was full since the engine was made.
    [[nodiscard]] uint64_t dropped_reports() const noexcept;

    // What the last tick played: each playing wave's disturbance class, period and force
    // (EngineActivity). Call it after tick(); real-time safe (no allocation, lock or throw).
    // Conditions are left out: their forces answer the handle's motion, so a filter sees
    // them as part of the mechanism. Dynamics are left out too: their force is not kept
    // between ticks.
    void activity(EngineActivity& out) const noexcept;

    [[nodiscard]] const EngineConfig& config() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace feel
