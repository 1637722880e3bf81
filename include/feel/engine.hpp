// feel — the effect engine: a fixed pool of effect slots rendered once per tick.
//
// The engine is the part of feel that runs on the device's local processor (§2.2). It is
// built with -fno-exceptions -fno-rtti and allocates only in its constructor: every
// capacity (effect slots, force-profile sample memory) is fixed there, and a create that
// does not fit reports ErrorCode::device_full instead of growing.
//
// Time is an input. tick() takes the time and the sensor state and returns the force on
// each axis; effect math never reads a clock, so the same inputs give bit-identical
// outputs.
//
// Real-time safety: tick(), start(), stop(), set_gain(), status() never allocate, lock or
// throw. create() and destroy() do not allocate either, but copy sample data, so call them
// from the loop's command queue, not from an interrupt.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "feel/axis.hpp"
#include "feel/effect.hpp"
#include "feel/status.hpp"

namespace feel {

struct EngineConfig {
    int32_t axis_count = 2;         // 1..6: the device's axes are x, y, z, rx, ry, rz in order
    int32_t max_effects = 64;       // effect slots (the "memory pool" of §2.2), 1..65535
    int32_t max_samples = 1 << 16;  // force-profile sample memory, in samples

    // What the engine knows of the device, in normalized units (docs/conventions.md).
    // feel::sim::engine_config_for(profile) fills these from a device profile.
    float velocity_ref = 1e5f;        // > 0, position units/s that conditions read as 10000
    float acceleration_ref = 1e7f;    // > 0, position units/s² that inertia reads as 10000
    float sensor_step = 20000.0f / 4096.0f;  // > 0, position units per sensor count
    // The mechanism's own viscous damping b, as force units per (position unit/s): the
    // physical damping times half_travel / max_force. The passivity bound of walls uses it.
    float device_damping = 0.0f;      // >= 0
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

// What the engine is told each tick. Positions come from the device's quantized sensors.
struct TickInput {
    int64_t t_us = 0;                   // time of this tick, µs, non-decreasing
    float position[kMaxAxes] = {};      // normalized, ±10000 of each axis's travel
    uint32_t buttons = 0;               // bit i = button i+1 pressed
};

struct TickOutput {
    float force[kMaxAxes] = {};         // normalized ±10000, physical sign, clamped
    float velocity[kMaxAxes] = {};      // the engine's velocity estimate, normalized units/s
    float acceleration[kMaxAxes] = {};  // the engine's acceleration estimate, units/s²
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
    Error stop(EffectId id) noexcept;
    void stop_all() noexcept;
    [[nodiscard]] EffectState state(EffectId id) const noexcept;

    // Device gain, 0..10000, scales the summed force of every effect.
    Error set_gain(int32_t gain) noexcept;
    [[nodiscard]] int32_t gain() const noexcept;

    // Renders one tick. Never allocates, locks or throws; never outputs NaN or inf.
    void tick(const TickInput& in, TickOutput& out) noexcept;

    // Takes the oldest report of a dynamic (interim or final), if any. Real-time safe.
    [[nodiscard]] bool pop_report(DynamicReport& report) noexcept;
    // Reports lost because the queue was full since the engine was made.
    [[nodiscard]] uint64_t dropped_reports() const noexcept;

    [[nodiscard]] const EngineConfig& config() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace feel
