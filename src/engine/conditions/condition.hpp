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
#include "feel/engine.hpp"
#include "conditions/contact_state.hpp"
#include "conditions/friction_state.hpp"

namespace feel::detail {

struct ConditionState {
    FrictionState friction{};
    ContactState contact{};
};

struct ConditionContext {
    const EffectParams* params = nullptr;
    const EngineConfig* config = nullptr;
    const float* position = nullptr;        // [kMaxAxes] sensed, normalized ±10000
    const float* velocity = nullptr;        // [kMaxAxes] estimated, position units/s
    const float* acceleration = nullptr;    // [kMaxAxes] estimated, position units/s²
    const float* start_position = nullptr;  // [kMaxAxes] sensed position at the effect's first tick
    const float* direction = nullptr;       // [kMaxAxes] the effect's direction factors (direction.hpp)
    double dt_s = 0;                        // time since the previous tick, s (0 on the first)
    int64_t tau_us = 0;                     // time since the effect began playing
    ConditionState* state = nullptr;        // this effect's state, persists across ticks
    float* reported_position = nullptr;     // [kMaxAxes] clipping walls overwrite their axis
    const float* applied_force = nullptr;   // [kMaxAxes] the engine's force of the previous tick (friction's stop guard)
    float device_gain = 1.0f;               // the device gain as a fraction (0..1)
};

void render_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;

// The families, one file each.
void spring_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;   // spring, angle_spring
void damper_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;
void inertia_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;
void friction_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;
void texture_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;
void wall_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;     // axis_wall, angle_wall
void barrier_condition(const ConditionContext& c, double force[kMaxAxes]) noexcept;  // axis_barrier, angle_barrier

// A spring, damper, inertia or friction with a direction (is_directed_condition): `law`, the
// family's function, rendered on the line of the direction and applied along it.
void directed_condition(const ConditionContext& c, void (*law)(const ConditionContext&, double*),
                        double force[kMaxAxes]) noexcept;

}  // namespace feel::detail
