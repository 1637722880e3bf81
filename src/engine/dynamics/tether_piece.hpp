// One piece of a law with regions to track (tether_tick.hpp says how it goes): the piece
// by its region's propagator, the tests of whether it may have crossed an edge, and the
// common case whole (one piece a step, nothing counted), inline for the callers that keep
// it off a call: advance_watched_tether and the watched laws' tick (control_law_dynamic.cpp).
//
// Real-time safe: no allocation, no exceptions.
#pragma once

#include <cmath>
#include <cstdint>

#include "dynamics/control_law_state.hpp"
#include "dynamics/tether_law.hpp"
#include "dynamics/tether_propagator.hpp"
#include "dynamics/tether_tick.hpp"

namespace feel::detail {

// Whether a piece that went from (s0, rate0) to (s1, rate1) in region r may have crossed
// an edge of it (tether_tick.hpp: only a piece that leaves, or turns while heading for
// an edge, can have).
inline bool may_have_crossed(TetherRegion r, float length, float s1, float rate0, float rate1) noexcept {
    switch (r) {
        case TetherRegion::above: return !(s1 > length) || (rate0 <= 0 && rate1 >= 0);
        case TetherRegion::below: return !(s1 < -length) || (rate0 >= 0 && rate1 <= 0);
        case TetherRegion::slack: break;
    }
    return !(s1 < length && s1 > -length) || !(rate0 * rate1 > 0);
}

// Whether a stretched region's motion from local (y, v) (y measured from the region's edge)
// stays clear of the edge however long it runs: with a constant force f the energy about
// the equilibrium y_eq = f/k, ½·k·(y − y_eq)² + ½·m·v², never grows (damping only takes),
// so y never leaves y_eq ± R, R² = (y − y_eq)² + m·v²/k. Clear when that whole interval is
// on the region's side (`outward` +1 above, −1 below).
inline bool stays_clear(float outward, float k, float m, float f, float y, float v) noexcept {
    const float equilibrium = f / k;
    if (!(equilibrium * outward > 0)) return false;
    const float offset = y - equilibrium;
    return offset * offset + m * v * v / k < equilibrium * equilibrium;
}

// Whether a piece of the play that starts at s0 with rate v0 and ends within the play,
// at s1, its velocity having turned (or started at rest), stayed clear of both edges. In
// the play the mass is free, ÿ = −a·ẏ + f/m with a >= 0 and f constant: its velocity can
// turn only against f, and while it heads on its way (the sign of v0) drag and f both
// slow it, so it goes on at most |v0|·h before it turns; after the turn it heads back
// monotonically to s1. So the extremum lies within |v0|·h of s0, on v0's side, and the
// piece crossed no edge when that point is inside the play (with a margin of 2^-10 of
// the bound and 2^-20 of the play for the propagator's rounding, which is far finer).
// The exact piece (tether_law.cpp) would search both edges for a crossing there is not.
inline bool turns_within_play(float length, float s0, float v0, float s1, float h) noexcept {
    const float reach = std::fabs(v0) * h * (1.0f + 0x1p-10f) + length * 0x1p-20f;
    const float extremum = v0 >= 0 ? s0 + reach : s0 - reach;
    return std::fabs(extremum) < length && std::fabs(s1) < length;
}

// How a piece of a piecewise law went (try_piece).
enum class PieceOutcome : uint8_t {
    at_rest,    // at rest in the play with nothing pushing it: no piece moves the mass
    clear,      // the piece ended in its region and touched no edge
    may_cross,  // an edge may lie within the piece: the exact piece must redo it
};

// One piece of a piecewise law from (s, rate): its region, the region's origin, and the
// piece's end (y, v) about that origin by the region's propagator.
struct WatchedPiece {
    TetherRegion region = TetherRegion::slack;
    float origin = 0;
    float y = 0, v = 0;
};

[[gnu::always_inline]] inline PieceOutcome try_piece(const PreparedTether& t, float s, float rate, float slack_force,
                                                     float taut_force, float piece, WatchedPiece& w) noexcept {
    const TetherRegion r = tether_region(t.length, s, rate, taut_force);
    // At rest in the play with nothing pushing it: the free propagator maps (y, 0) to (y, 0)
    // exactly, so no piece moves the mass. The exact piece would be asked every time (a
    // piece that starts at rest may have turned), which is most of what a still handle costs.
    if (r == TetherRegion::slack && rate == 0 && slack_force == 0) return PieceOutcome::at_rest;
    const float origin = r == TetherRegion::above ? t.length : (r == TetherRegion::below ? -t.length : 0.0f);
    const TetherPropagator& p = r == TetherRegion::above ? t.above : (r == TetherRegion::below ? t.below : t.slack);
    float y = s - origin;
    float v = rate;
    propagate(p, r == TetherRegion::slack ? slack_force : taut_force, y, v);
    w = {r, origin, y, v};
    if (may_have_crossed(r, t.length, y + origin, rate, v) &&
        !(r == TetherRegion::slack ? turns_within_play(t.length, s, rate, y, piece)
                             : stays_clear(r == TetherRegion::above ? 1.0f : -1.0f, r == TetherRegion::above ? t.k_pos : t.k_neg,
                                           t.mass, taut_force, s - origin, rate))) {
        return PieceOutcome::may_cross;
    }
    return PieceOutcome::clear;
}

// The forces on a mass moving with the handle along `line`, apart from the spring
// (tether_law.cpp's segment): taut, the tether damper reads against damper_velocity;
// slack, no tether.
struct LineForces {
    float slack = 0, taut = 0;
};

[[gnu::always_inline]] inline LineForces line_forces(const PreparedTether& t, float gravity, HandleLine line) noexcept {
    const float slack = t.mass * gravity - t.drag * line.velocity;
    return {slack, slack - t.b * (line.velocity - line.damper_velocity)};
}

// The momentum balance M·Δv = J + M·g·h − d·Δx (Δx the mass's own displacement): the
// tether's impulse over a step that went from (s0, rate0) to (s, rate).
[[gnu::always_inline]] inline float tether_impulse(const PreparedTether& t, float gravity, float u, float s0,
                                                   float rate0, float s, float rate) noexcept {
    const float h = t.step_s;
    return t.mass * (rate - rate0) - t.mass * gravity * h + t.drag * ((s - s0) + u * h);
}

#if !defined(__OPTIMIZE_SIZE__)
// The common case of advance_watched_tether, a law with regions in one piece that counts
// nothing (t.piecewise, t.pieces == 1, t.half_cycles == 0: the busy mix's control laws and
// inertias with play): its piece with no call on its way, so that nothing is spilled
// around calls it almost never makes. Returns false, with `state` untouched, when the
// piece may have crossed an edge: the general case then redoes it from the start (the
// same operations, so the same bits). Not in a build for size (the Cortex-M4F image, whose
// flash is the tighter budget).
[[gnu::always_inline]] inline bool advance_one_watched_piece(const PreparedTether& t, float gravity,
                                                             TetherAxisState& state, HandleLine line,
                                                             float& impulse) noexcept {
    const float u = line.velocity;
    const LineForces forces = line_forces(t, gravity, line);
    const float s0 = state.stretch;
    const float rate0 = state.velocity - u;
    WatchedPiece w;
    // One piece: its length is the step's (step_s / 1 exactly).
    const PieceOutcome outcome = try_piece(t, s0, rate0, forces.slack, forces.taut, t.step_s, w);
    if (outcome == PieceOutcome::may_cross) return false;
    impulse = 0.0f;
    if (outcome == PieceOutcome::at_rest) {
        state.velocity = rate0 + u;
        return true;
    }
    const float s = w.y + w.origin;
    state.stretch = s;
    state.velocity = w.v + u;
    if (w.region != TetherRegion::slack) impulse = tether_impulse(t, gravity, u, s0, rate0, s, w.v);
    return true;
}
#endif

}  // namespace feel::detail
