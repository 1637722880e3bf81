// Dynamic Sensations (§5): a simulated mass tethered to the handle.
//
// A dynamic sees the handle through DynamicContext (its sensed position and estimated
// velocity), keeps its simulated mass in DynamicState (in the effect's slot, persisting
// across ticks), adds the tether's reaction on the handle to force[] (±10000 units, physical
// sign, before effect and device gain), and tells the engine where its mass is and whether
// it has ended (DynamicResult). The engine turns that into interim and final reports.
// force[] is float, as the engine sums it; the balls work in float too (ball_tick.hpp), and
// render_dynamic adds each ball's own force to it once.
//
// Every named dynamic maps onto the control law (§8.4), except the sling and the paddle,
// which are true 2D models (§5.8, §5.9). One file per model; dynamic.cpp dispatches.
#pragma once

#include <cstdint>

#include "dynamics/ball_state.hpp"
#include "dynamics/control_law_state.hpp"
#include "feel/effect.hpp"
#include "slot_params.hpp"
#include "feel/engine.hpp"

namespace feel::detail {

struct DynamicState {
    DynamicState() noexcept : law{} {}  // the union's first member live; every other field as declared

    bool initialized = false;  // the first playing tick sets up the mass
    // The slot's parameters are worked into its per-tick form (ControlLawState::laws, a
    // sling's BallState::sling); prepare_slot clears it after every command that sets them.
    bool prepared = false;
    // Every axis's law is plain (PreparedTether::plain), set with prepared: the tick takes
    // the short way (control_law_dynamic.cpp).
    bool plain = false;
    // Bit i: axis i's mass as the last prediction left it is kept (ControlLawState's
    // ahead_stretch, ahead_velocity) and the catch-up's inputs are the prediction's, so the
    // catch-up takes it (control_law_dynamic.cpp). In the padding before inverse_step.
    uint8_t kept_ahead = 0;
    // 1/step of the tick length the laws are prepared for (PreparedTether::step_s), set with
    // them: a double division a tick less, in the padding before the union.
    float inverse_step = 0;
    // The simulated mass: a control law's or a ball's, never both (the type of a slot's
    // effect never changes), so they share the bytes (issue 14: RAM). The control law's is
    // live from construction; ball_tick assigns the ball's whole on a ball's first tick.
    union {
        ControlLawState law;    // control-law dynamics (recoil ... center drift, control law)
        BallState ball;         // sling and paddle
    };
};

struct DynamicContext {
    const SlotParams* params = nullptr;
    const EngineConfig* config = nullptr;
    const float* position = nullptr;        // [kMaxAxes] handle, sensed, position units
    const float* velocity = nullptr;        // [kMaxAxes] handle, estimated, position units/s
    // [kMaxAxes] handle, estimated, position units/s²: fitted in ticks where an inertia
    // condition or a Dynamic Inertia plays, else 0
    const float* acceleration = nullptr;
    const float* start_position = nullptr;  // [kMaxAxes] handle at the effect's first playing tick
    float dt_s = 0;                         // time since the previous tick, s (0 on the first)
    int64_t tau_us = 0;                     // time since the effect began playing
    DynamicState* state = nullptr;
};

struct DynamicResult {
    bool finished = false;               // ended by itself this tick (final report follows)
    float mass_position[kMaxAxes] = {};  // per DEVICE axis: mass minus handle, position units
    float mass_velocity[kMaxAxes] = {};  // per DEVICE axis: mass minus handle, position units/s
};

void render_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept;

// Two Dynamic Slings rendered together: the same forces, results and states, bit for bit,
// as render_dynamic on a and then on b, in about the time of one (their Verlet steps are
// latency chains that overlap when interleaved: sling_dynamic.cpp). The engine pairs the
// slings of a tick when kPairSlings; a build for size (the Cortex-M4F image, in order and
// without overlap) renders them one by one.
#if defined(__OPTIMIZE_SIZE__)
inline constexpr bool kPairSlings = false;
#else
inline constexpr bool kPairSlings = true;
#endif
void render_sling_pair(const DynamicContext& a, const DynamicContext& b, float force_a[kMaxAxes],
                       float force_b[kMaxAxes], DynamicResult& result_a, DynamicResult& result_b) noexcept;
// A sling whose ball rests on a slack string beside a handle sensed where it was last tick:
// its tick moves nothing and pulls nothing (sling_dynamic.cpp), so there is no chain to pair.
[[nodiscard]] bool sling_rests(const DynamicContext& c) noexcept;

// The models, one file each.
void control_law_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept;
void sling_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept;
void sling_pair_dynamic(const DynamicContext& a, const DynamicContext& b, float force_a[kMaxAxes],
                        float force_b[kMaxAxes], DynamicResult& result_a, DynamicResult& result_b) noexcept;
void paddle_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept;

}  // namespace feel::detail
