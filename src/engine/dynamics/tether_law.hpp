// The control law of one axis (§5.10, §8.4): a mass tethered to the handle, in physical
// (normalized) units, and its exact piecewise integration.
//
//                 length (free play, no tether force within ±length)
//               |<------>|
//   handle p ---[ spring k± ]---[ damper b ]--- mass M ~~~ drag d to the fixed frame
//                                               <-- gravity g on the mass, any sign
//
// The stretch s = x − p is the mass's position relative to the handle. Outside the play
// the tether pulls the mass back with −k±·(s ∓ length) − b·ṡ (k_pos for s > +length, k_neg
// for s < −length); within it the tether is slack and pulls neither way. Drag −d·ẋ acts
// on the mass's absolute velocity, gravity M·g on the mass. The handle feels the reaction
// of the tether and nothing else: +k±·(s ∓ length) + b·ṡ.
//
// Each region is a linear spring-damper, solved exactly by tether_step. A step is cut into
// pieces with ω·h ≤ 1 (ω = √(max k±/M)). Each tick applies each region's exact solution as
// a float propagator (tether_tick.hpp); in a piece where an edge may lie, tether_crossing
// finds the moment the stretch reaches an edge of the play (or 0, when k_pos ≠ k_neg and
// there is no play), the piece is split there, the stretch is set exactly onto the edge
// and the next region carries on. Rather than chase a mass that grazes an edge endlessly (a Zeno sequence of
// crossings), a piece takes at most kMaxRegionSwitches switches and finishes the rest of
// its time in the region it is in.
#pragma once

#include <cstdint>

#include "dynamics/control_law_state.hpp"
#include "dynamics/tether_step.hpp"
#include "feel/effect.hpp"
#include "slot_params.hpp"
#include "feel/engine.hpp"

namespace feel::detail {

// One axis of the control law in normalized physical units (dynamic_units.hpp).
struct TetherLaw {
    float mass = 1;        // > 0, force units per (position unit/s²)
    float k_pos = 1;       // > 0, force units per position unit, stretch beyond +length
    float k_neg = 1;       // > 0, the same beyond −length
    float b = 0;           // >= 0, tether damping on the relative velocity, force/(units/s)
    float drag = 0;        // >= 0, ambient damping on the absolute velocity, force/(units/s)
    float gravity = 0;     // position units/s², either sign: the force M·g on the mass
    float length = 0;      // >= 0, position units: the half-width of the free play
    float pos_init = 0;    // position units, the mass's start relative to the handle
    float vel_init = 0;    // position units/s, relative to the handle
    int32_t half_cycles = 0;  // 0 = never ends; else ends after this many half oscillations
    // The mass is simulated in the handle's frame, driven by the handle's estimated
    // acceleration rather than by its sensed position and estimated velocity: Dynamic
    // Inertia (control_law_dynamic.cpp says why).
    bool handle_frame = false;
};

// A handle moving at constant velocity over an interval: p(t) = position + velocity·t. The
// tether's damper acts on the mass's velocity relative to damper_velocity, normally the
// same; control_law_dynamic.cpp explains when it is not.
struct HandlePath {
    float position = 0;         // position units
    float velocity = 0;         // position units/s
    float damper_velocity = 0;  // position units/s
};

// At most this many pieces per step: enough for ω·h ≤ 1 at 100 Hz on every profile
// (docs/dynamics.md); a longer step is still exact piecewise, only edges may be missed.
inline constexpr int32_t kMaxTetherSubsteps = 128;
// At most this many edge crossings handled per piece.
inline constexpr int32_t kMaxRegionSwitches = 8;

// The three regions of the law.
enum class TetherRegion : uint8_t {
    below,  // s < −length: the tether is stretched negatively, k_neg
    slack,  // |s| < length: free play
    above,  // s > +length: stretched positively, k_pos
};

// The region a stretch s is in. On
// an edge, the side the motion leaves to decides (the sign of ṡ, else of the force at
// rest), so that a mass set onto an edge by a crossing goes on into the region it was
// heading for. Without play (length 0), the sign of the stretch.
template <typename T>
[[nodiscard]] TetherRegion tether_region(T length, T s, T rate, T rest_force) noexcept {
    if (length > 0) {
        if (s > length) return TetherRegion::above;
        if (s < -length) return TetherRegion::below;
        if (s > -length && s < length) return TetherRegion::slack;
        const T out = s > 0 ? T(1) : T(-1);  // on +edge, outward is +
        const T leaving = rate != 0 ? rate : rest_force;
        if (leaving * out > 0) return s > 0 ? TetherRegion::above : TetherRegion::below;
        return TetherRegion::slack;
    }
    if (s > 0) return TetherRegion::above;
    if (s < 0) return TetherRegion::below;
    if (rate != 0) return rate > 0 ? TetherRegion::above : TetherRegion::below;
    return rest_force >= 0 ? TetherRegion::above : TetherRegion::below;
}

// The stretch where the mass rests against a held handle: 0 without gravity, else the
// sag M·g/k± beyond the play on the side gravity pulls to.
[[nodiscard]] float rest_stretch(const TetherLaw& law) noexcept;

// The tether's pull on the handle (force units, + toward +axis) at stretch s, rate ṡ.
[[nodiscard]] float tether_reaction(const TetherLaw& law, float stretch, float stretch_rate) noexcept;

// The side (−1, 0, +1) a stretch is on relative to the rest stretch, beyond ±hysteresis.
[[nodiscard]] int8_t stretch_side(const TetherLaw& law, float stretch, float hysteresis) noexcept;

// Advances the stretch (s, ṡ) of one axis exactly by one piece of h seconds (ω·h ≤ 1,
// h >= 0) against the handle path (its position unused: s is relative to the handle),
// switching regions at the edges it finds (tether_crossing) and, for a law that ends
// after some (law.half_cycles > 0; else state is left as it is), counting half cycles:
// each time the stretch goes from beyond +hysteresis of the rest stretch to beyond
// −hysteresis, or back, checked at every edge crossing and at the piece's end. Float, as
// the tick; tether_tick.cpp calls it for the pieces in which an edge may lie. `end` is the
// piece's end in the region it starts in (the region's local coordinate: s − length
// above, s + length below, s in the slack), which the caller's propagator has already
// computed: the exact step to it is not evaluated again. Returns whether any part of the
// piece was spent beyond the play (the tether taut).
bool advance_tether_piece(const TetherLaw& law, TetherAxisState& state, float& s, float& rate,
                          const HandlePath& path, float h, float hysteresis, MassStateF end) noexcept;

// The §8.4 mapping: fills laws[i] for each axis i of the effect from its dynamic type and
// Dynamic Struct, scaled by the config. Returns the effect's axis count. The effect must
// be a control-law dynamic (recoil, impact, liquid, inertia, center drift, control law)
// that validate_effect() accepted.
int32_t tether_laws(const SlotParams& params, const EngineConfig& config, TetherLaw laws[kMaxAxes]) noexcept;

}  // namespace feel::detail
