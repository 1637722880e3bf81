// One axis of the control law advanced in float, tick by tick (tether_law.hpp has the model).
//
// Between events the tethered mass is linear in each region of the law (stretched beyond
// +length on k_pos, beyond −length on k_neg, slack within the play), so a piece of a step
// is one application of that region's propagator (tether_propagator.hpp): a handful of
// float multiply-adds, the propagators worked out once per command and tick length. The
// step keeps tether_law's pieces (ω·h ≤ 1, so a half cycle spans at least π pieces and
// the half-cycle count sees every swing).
//
// The events are the law's nonlinearity. Within a piece the stretch has at most one
// extremum (ω·h ≤ 1), so a piece that ends in the region it started in, with a velocity
// that did not turn while heading for an edge, cannot have touched that edge: the motion
// was monotone toward it, or it turned away from it. Every other piece of a piecewise law
// (it ends beyond an edge, or it turned while heading for one, or it started at rest) is
// redone from its start by the exact piece of tether_law.cpp (float too), which
// locates the crossing and switches region there. That happens about twice per swing
// through an edge; a law with one region (no play, k_pos = k_neg) never needs it.
//
// Real-time safe: no allocation, no exceptions.
#pragma once

#include "dynamics/control_law_state.hpp"
#include "dynamics/tether_law.hpp"
#include "dynamics/tether_propagator.hpp"

namespace feel::detail {

// The handle over a step as the stretch sees it: moving at `velocity`, its damper reading
// `damper_velocity` (tether_law.hpp's HandlePath, without the position: the state is
// relative to the handle already).
struct HandleLine {
    float velocity = 0;         // position units/s
    float damper_velocity = 0;  // position units/s
};

// The law of one axis in its per-tick form; pieces not yet prepared (step_s = 0).
[[nodiscard]] PreparedTether prepare_tether(const TetherLaw& law) noexcept;

// The pieces and the propagators of every region for steps of step_s seconds (> 0).
void prepare_pieces(PreparedTether& t, float step_s) noexcept;

// The prepared law as tether_law.hpp's, with the given gravity (the law's own, or the handle's frame:
// control_law_dynamic.cpp), for the exact piece and the instantaneous reaction.
[[nodiscard]] TetherLaw exact_law(const PreparedTether& t, float gravity) noexcept;

// Advances one axis by h = t.step_s seconds (prepare_pieces first) under `gravity` against
// the handle line, counting half cycles as advance_tether_piece does when the law ends
// after some (t.half_cycles > 0; else state.half_cycles and state.side are left as they
// are). state.stretch is relative to the handle at the start of the step and comes back
// relative to it at the end. Returns the impulse the tether gave the mass, force units·s
// (the handle felt its opposite). The general case, out of line: a law with regions to
// track or half cycles to count.
float advance_watched_tether(const PreparedTether& t, float gravity, TetherAxisState& state, HandleLine line,
                             float hysteresis) noexcept;

// The same for any law. Most laws have one region and count nothing (recoil, impact,
// liquid, center drift): their step is one propagator, inline, with none of the general
// case's region bookkeeping (pieces is 1 for them: prepare_pieces).
[[gnu::always_inline]] inline float advance_prepared_tether(const PreparedTether& t, float gravity, TetherAxisState& state,
                                                             HandleLine line, float hysteresis) noexcept {
#if defined(__OPTIMIZE_SIZE__)
    // A build for size (the Cortex-M4F image) has one copy of the step: the general case
    // takes a law with one region through the same operations in the same order.
    return advance_watched_tether(t, gravity, state, line, hysteresis);
#else
    if (t.piecewise || t.half_cycles > 0) return advance_watched_tether(t, gravity, state, line, hysteresis);
    const float u = line.velocity;
    // The force on a mass moving with the handle, apart from the spring (tether_law.cpp's
    // segment); the tether is always taut, its damper reading against damper_velocity.
    const float taut_force = t.mass * gravity - t.drag * u - t.b * (u - line.damper_velocity);
    const float s0 = state.stretch;
    const float rate0 = state.velocity - u;
    float s = s0;
    float rate = rate0;
    for (int32_t i = 0; i < t.pieces; ++i) propagate(t.above, taut_force, s, rate);
    state.stretch = s;
    state.velocity = rate + u;
    // The momentum balance M·Δv = J + M·g·h − d·Δx (Δx the mass's own displacement).
    const float h = t.step_s;
    return t.mass * (rate - rate0) - t.mass * gravity * h + t.drag * ((s - s0) + u * h);
#endif
}

// The prediction's impulse as a linear form of the state for a law with one region that
// counts nothing (weighted_change_form of its one propagator): prepared with the pieces,
// except in a build for size, which works it out here by the same operations (the same bits).
[[gnu::always_inline]] inline WeightedChangeForm prediction_form(const PreparedTether& t) noexcept {
#if defined(__OPTIMIZE_SIZE__)
    return weighted_change_form(t.above, t.mass, t.drag);
#else
    return t.prediction_form;
#endif
}

// The impulse advance_prepared_tether would return for a copy of the state, where only the
// impulse is wanted (the prediction: control_law_dynamic.cpp). For a law with one region
// that counts nothing (one piece: prepare_pieces) the piece's map is affine, so the impulse
// is a linear form of the state (weighted_change), computed without the predicted state;
// other laws advance the copy.
[[gnu::always_inline]] inline float predicted_impulse(const PreparedTether& t, float gravity,
                                                       const TetherAxisState& state, HandleLine line,
                                                       float hysteresis) noexcept {
    if (t.piecewise || t.half_cycles > 0) {
        TetherAxisState ahead = state;
        return advance_watched_tether(t, gravity, ahead, line, hysteresis);
    }
    const float u = line.velocity;
    const float taut_force = t.mass * gravity - t.drag * u - t.b * (u - line.damper_velocity);
    const float h = t.step_s;
    const float change = weighted_change(prediction_form(t), taut_force, state.stretch, state.velocity - u);
    return change - t.mass * gravity * h + t.drag * (u * h);
}

}  // namespace feel::detail
