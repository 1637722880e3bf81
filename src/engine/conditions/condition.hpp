// Spatial Conditions (§3): forces that are functions of the handle's motion.
//
// A condition sees the handle through ConditionContext: the sensed position, the
// estimated velocity and acceleration, the position when the effect started, and its own
// state in the effect's slot. It adds its force to force[] (±10000 units, before effect and
// device gain). Walls with clipping also write the position the device reports.
//
// One file per condition family; condition.cpp dispatches on the type.
#pragma once

#include <cstdint>

#include "feel/effect.hpp"
#include "slot_params.hpp"
#include "feel/engine.hpp"
#include "conditions/contact_state.hpp"
#include "conditions/friction_state.hpp"

namespace feel::detail {

// A condition's memory between ticks: friction's and texture's bristles, or a wall's or
// barrier's contact ledger. A condition keeps one or the other (its type never changes), so
// they share their bytes (issue 14: RAM on a Cortex-M4F); start_fresh makes the one of its
// type the live member.
struct ConditionState {
    ConditionState() noexcept : friction{} {}
    union {
        FrictionState friction;  // friction, texture
        ContactState contact;    // axis_wall, angle_wall, axis_barrier, angle_barrier
    };

    // The memory of a condition of type t starting afresh (zeroed, as at create and start).
    void start_fresh(EffectType t) noexcept {
        if (t == EffectType::friction || t == EffectType::texture) {
            friction = FrictionState{};
        } else {
            contact = ContactState{};
        }
    }

    // The effect's parameters changed (an update) and the memory of its type t is kept: a
    // friction's lean way checks its blocks' laws again.
    void params_changed(EffectType t) noexcept {
        if (kFrictionLeanWay && t == EffectType::friction) friction.laws_current = false;
    }
};

struct ConditionContext {
    const SlotParams* params = nullptr;
    const EngineConfig* config = nullptr;
    const float* position = nullptr;        // [kMaxAxes] sensed, normalized ±10000
    const float* velocity = nullptr;        // [kMaxAxes] estimated, position units/s
    const float* acceleration = nullptr;    // [kMaxAxes] estimated, position units/s²
    const float* start_position = nullptr;  // [kMaxAxes] sensed position at the effect's first tick
    const float* direction = nullptr;       // [kMaxAxes] the effect's direction factors (direction.hpp)
    float dt_s = 0;                         // time since the previous tick, s (0 on the first)
    // Time since the effect began playing. Not set for friction and texture, which render
    // last and read no clock (nor curves: Engine::tick's second pass).
    int64_t tau_us = 0;
    ConditionState* state = nullptr;        // this effect's state, persists across ticks
    float* reported_position = nullptr;     // [kMaxAxes] clipping walls overwrite their axis
    const ConditionCurve* curves = nullptr; // [kMaxAxes] the blocks as curves (params->curved)
    float velocity_scale = 0.0f;            // kFullScale / velocity_ref: velocity to the ±10000 scale
    float acceleration_scale = 0.0f;        // kFullScale / acceleration_ref
    int axes = kMaxAxes;                    // the device's axes: forces beyond them are 0
    const float* applied_force = nullptr;   // [kMaxAxes] the engine's force of the previous tick (friction's stop guard)
    // [kMaxAxes] friction and texture (rendered last): this tick's force of the effects
    // rendered before them, device gain included, what their stiction holds against; null
    // when unknown.
    const float* others_force = nullptr;
    float device_gain = 1.0f;               // the device gain as a fraction (0..1)
    // The engine's observers of the handle, one per device axis, advanced this tick (friction's
    // stop guard, stop_guard.hpp); null off the device's axes (a condition with a direction)
    // or when the engine keeps none.
    const AxisObservers* observers = nullptr;
};

// The axes a condition reads and pushes on: the device's c.axes (the engine reads no force
// beyond them, and an effect names no axis beyond them, so its direction is 0 there). A
// build for at most 2 axes (the board's, FEEL_MAX_AXES=2) runs both lanes whatever the
// device, a count known when compiling, as the engine's own sums do (engine.cpp,
// two_lanes): on a 1-axis device the second lane's direction is 0, so it adds ±0, which
// changes no sum that starts from +0 (such a sum is never −0), and pushes on no axis the
// engine reads.
[[nodiscard]] inline int condition_lanes(const ConditionContext& c) noexcept { return kMaxAxes == 2 ? 2 : c.axes; }

// u · v over the device's axes (condition_lanes).
[[nodiscard]] inline float along(const ConditionContext& c, const float* u, const float* v) noexcept {
    // The common device, unrolled: the loop's operations.
    if (kMaxAxes == 2 || c.axes == 2) return (0.0f + u[0] * v[0]) + u[1] * v[1];
    float sum = 0.0f;
    for (int a = 0; a < c.axes; ++a) sum += u[a] * v[a];
    return sum;
}

// force += value·u on the device's axes (condition_lanes).
inline void add_force_along(const ConditionContext& c, const float* u, float value, float force[kMaxAxes]) noexcept {
    if (kMaxAxes == 2 || c.axes == 2) {  // the common device, unrolled, as along
        force[0] += value * u[0];
        force[1] += value * u[1];
        return;
    }
    for (int a = 0; a < c.axes; ++a) force[a] += value * u[a];
}

// The curve of a block: the single-precision constants condition_response needs.
[[nodiscard]] ConditionCurve curve_of(const ConditionBlock& b) noexcept;

// The families, one file each, all single precision (issue 14; docs/tick-cost.md, "Where
// double remains", for the few double constants left).
void spring_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept;   // spring, angle_spring
void damper_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept;
void inertia_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept;
void friction_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept;
void texture_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept;
void wall_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept;     // axis_wall, angle_wall
void barrier_condition(const ConditionContext& c, float force[kMaxAxes]) noexcept;  // axis_barrier, angle_barrier

// A condition law: it adds its force into force[kMaxAxes].
using ConditionLaw = void (*)(const ConditionContext&, float*);

// The function that renders a condition of these params, chosen once per command so that
// the tick calls it directly: it adds the condition's force (±10000 units, before effect and
// device gain) into force[].
[[nodiscard]] ConditionLaw condition_renderer(const SlotParams& params) noexcept;

// A spring, damper, inertia or friction with a direction (is_directed_condition): `law`, the
// family's function, rendered on the line of the direction and applied along it.
void directed_condition(const ConditionContext& c, ConditionLaw law, float force[kMaxAxes]) noexcept;

}  // namespace feel::detail
