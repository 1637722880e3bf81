// The float, per-tick step of one control-law axis; tether_tick.hpp says how it goes.
#include "dynamics/tether_tick.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/tether_step.hpp"

namespace feel::detail {

namespace {

using Region = TetherRegion;

// Whether a piece that went from (s0, rate0) to (s1, rate1) in region r may have crossed
// an edge of it (tether_tick.hpp: only a piece that leaves, or turns while heading for
// an edge, can have).
bool may_have_crossed(Region r, float length, float s1, float rate0, float rate1) noexcept {
    switch (r) {
        case Region::above: return !(s1 > length) || (rate0 <= 0 && rate1 >= 0);
        case Region::below: return !(s1 < -length) || (rate0 >= 0 && rate1 <= 0);
        case Region::slack: break;
    }
    return !(s1 < length && s1 > -length) || !(rate0 * rate1 > 0);
}

// Whether a stretched region's motion from local (y, v) (y measured from the region's edge)
// stays clear of the edge however long it runs: with a constant force f the energy about
// the equilibrium y_eq = f/k, ½·k·(y − y_eq)² + ½·m·v², never grows (damping only takes),
// so y never leaves y_eq ± R, R² = (y − y_eq)² + m·v²/k. Clear when that whole interval is
// on the region's side (`outward` +1 above, −1 below).
bool stays_clear(float outward, float k, float m, float f, float y, float v) noexcept {
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
bool turns_within_play(float length, float s0, float v0, float s1, float h) noexcept {
    const float reach = std::fabs(v0) * h * (1.0f + 0x1p-10f) + length * 0x1p-20f;
    const float extremum = v0 >= 0 ? s0 + reach : s0 - reach;
    return std::fabs(extremum) < length && std::fabs(s1) < length;
}

float rest_stretch_of(const PreparedTether& t, float gravity) noexcept {
    const float weight = t.mass * gravity;
    if (weight > 0) return t.length + weight / t.k_pos;
    if (weight < 0) return -t.length + weight / t.k_neg;
    return 0.0f;
}

// Out of line: only a law that ends after some half cycles counts them, and inlined the
// compiler worked the side out on every piece of every law before testing whether to count.
[[gnu::noinline]] void count_half_cycle(TetherAxisState& state, float stretch, float rest, float hysteresis) noexcept {
    const float e = stretch - rest;
    const int8_t side = e > hysteresis ? 1 : (e < -hysteresis ? -1 : 0);
    if (side == 0 || side == state.side) return;
    if (state.side != 0) ++state.half_cycles;
    state.side = side;
}

}  // namespace

PreparedTether prepare_tether(const TetherLaw& law) noexcept {
    PreparedTether t;
    t.mass = law.mass;
    t.k_pos = law.k_pos;
    t.k_neg = law.k_neg;
    t.b = law.b;
    t.drag = law.drag;
    t.gravity = law.gravity;
    t.length = law.length;
    t.pos_init = law.pos_init;
    t.vel_init = law.vel_init;
    t.half_cycles = law.half_cycles;
    t.handle_frame = law.handle_frame;
    t.piecewise = t.length > 0 || t.k_pos != t.k_neg;
    t.plain = !t.piecewise && t.half_cycles == 0 && !t.handle_frame;
    return t;
}

TetherLaw exact_law(const PreparedTether& t, float gravity) noexcept {
    TetherLaw law;
    law.mass = t.mass;
    law.k_pos = t.k_pos;
    law.k_neg = t.k_neg;
    law.b = t.b;
    law.drag = t.drag;
    law.gravity = gravity;
    law.length = t.length;
    law.pos_init = t.pos_init;
    law.vel_init = t.vel_init;
    law.half_cycles = t.half_cycles;
    law.handle_frame = t.handle_frame;
    return law;
}

void prepare_pieces(PreparedTether& t, float step_s) noexcept {
    const float m = t.mass, drag = t.drag, taut = t.b + t.drag;
    // Pieces with ω·h ≤ 1 are needed to see every edge and every half cycle; a law with one
    // region that counts none is exact in one piece of any length.
    const bool watched = t.piecewise || t.half_cycles > 0;
    t.pieces = watched ? tether_substeps<float>({m, std::max(t.k_pos, t.k_neg), 0.0f, 0.0f}, step_s, kMaxTetherSubsteps)
                       : 1;
    const float piece = step_s / static_cast<float>(t.pieces);
    t.below = tether_propagator({m, t.k_neg, taut, 0.0f}, piece);
    t.above = tether_propagator({m, t.k_pos, taut, 0.0f}, piece);
    t.slack = tether_propagator({m, 0.0f, drag, 0.0f}, piece);
    t.step_s = step_s;
#if !defined(__OPTIMIZE_SIZE__)
    t.prediction_form = weighted_change_form(t.above, m, drag);
    t.weight = m * t.gravity;
    t.weight_impulse = t.weight * step_s;
#endif
}

namespace {

// How a piece of a piecewise law went (try_piece).
enum class PieceOutcome : uint8_t {
    at_rest,    // at rest in the play with nothing pushing it: no piece moves the mass
    clear,      // the piece ended in its region and touched no edge
    may_cross,  // an edge may lie within the piece: the exact piece must redo it
};

// One piece of a piecewise law from (s, rate): its region, the region's origin, and the
// piece's end (y, v) about that origin by the region's propagator.
struct WatchedPiece {
    Region region = Region::slack;
    float origin = 0;
    float y = 0, v = 0;
};

[[gnu::always_inline]] inline PieceOutcome try_piece(const PreparedTether& t, float s, float rate, float slack_force,
                                                     float taut_force, float piece, WatchedPiece& w) noexcept {
    const Region r = tether_region(t.length, s, rate, taut_force);
    // At rest in the play with nothing pushing it: the free propagator maps (y, 0) to (y, 0)
    // exactly, so no piece moves the mass. The exact piece would be asked every time (a
    // piece that starts at rest may have turned), which is most of what a still handle costs.
    if (r == Region::slack && rate == 0 && slack_force == 0) return PieceOutcome::at_rest;
    const float origin = r == Region::above ? t.length : (r == Region::below ? -t.length : 0.0f);
    const TetherPropagator& p = r == Region::above ? t.above : (r == Region::below ? t.below : t.slack);
    float y = s - origin;
    float v = rate;
    propagate(p, r == Region::slack ? slack_force : taut_force, y, v);
    w = {r, origin, y, v};
    if (may_have_crossed(r, t.length, y + origin, rate, v) &&
        !(r == Region::slack ? turns_within_play(t.length, s, rate, y, piece)
                             : stays_clear(r == Region::above ? 1.0f : -1.0f, r == Region::above ? t.k_pos : t.k_neg,
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

// advance_watched_tether's general case: any number of pieces, half cycles counted, edges
// crossed by the exact piece.
[[gnu::noinline]] float advance_pieces(const PreparedTether& t, float gravity, TetherAxisState& state, HandleLine line,
                                       float hysteresis) noexcept {
    const float u = line.velocity;
    const LineForces forces = line_forces(t, gravity, line);
    // Half cycles are counted only for a law that ends after some (its count is what ends
    // it): the rest stretch they are counted about takes two divisions.
    const bool counting = t.half_cycles > 0;
    const float rest = counting ? rest_stretch_of(t, gravity) : 0.0f;
    const float s0 = state.stretch;
    const float rate0 = state.velocity - u;
    const float piece = t.step_s / static_cast<float>(t.pieces);
    float s = s0;
    float rate = rate0;
    bool taut = !t.piecewise;  // whether any piece met the tether (else its impulse is exactly 0)
    if (!t.piecewise) {
        // One region (no play, k_pos = k_neg): the tether is always taut, both sides are the
        // same propagator about the same origin (0). A law that counts no half cycles comes
        // here only in a build for size (advance_prepared_tether), in one piece.
        for (int32_t i = 0; i < t.pieces; ++i) {
            propagate(t.above, forces.taut, s, rate);
            if (counting) count_half_cycle(state, s, rest, hysteresis);
        }
    } else {
        for (int32_t i = 0; i < t.pieces; ++i) {
            WatchedPiece w;
            const PieceOutcome outcome = try_piece(t, s, rate, forces.slack, forces.taut, piece, w);
            if (outcome == PieceOutcome::at_rest) {
                // Neither does any later piece move it.
                if (counting) count_half_cycle(state, s, rest, hysteresis);
                break;
            }
            if (outcome == PieceOutcome::may_cross) {
                // The exact piece finds the edge (rare).
                const TetherLaw law = exact_law(t, gravity);
                const HandlePath path{0.0f, u, line.damper_velocity};
                taut = advance_tether_piece(law, state, s, rate, path, piece, hysteresis, {w.y, w.v}) || taut;
                continue;
            }
            s = w.y + w.origin;
            rate = w.v;
            taut = taut || w.region != Region::slack;
            if (counting) count_half_cycle(state, s, rest, hysteresis);
        }
    }
    state.stretch = s;
    state.velocity = rate + u;
    // A step spent wholly in the play gave the mass no tether impulse: exactly 0, not the
    // rounding the balance leaves when gravity (or the handle's frame) moves it.
    if (!taut) return 0.0f;
    return tether_impulse(t, gravity, u, s0, rate0, s, rate);
}

}  // namespace

// Flattened: the piece's tests (tether_region, may_have_crossed, ...) inline, which GCC
// otherwise called out of line here, spilling around each call.
[[gnu::flatten]] float advance_watched_tether(const PreparedTether& t, float gravity, TetherAxisState& state,
                                              HandleLine line, float hysteresis) noexcept {
#if !defined(__OPTIMIZE_SIZE__)
    // The common case, a law with regions in one piece that counts nothing (the busy mix's
    // control laws and inertias with play): its piece with no call on its way, so that
    // nothing is spilled around calls it almost never makes. A piece that may have crossed
    // is redone by the general case from the start (the same operations, so the same bits);
    // not in a build for size (the Cortex-M4F image, whose flash is the tighter budget).
    if (t.piecewise && t.pieces == 1 && t.half_cycles == 0) {
        const float u = line.velocity;
        const LineForces forces = line_forces(t, gravity, line);
        const float s0 = state.stretch;
        const float rate0 = state.velocity - u;
        WatchedPiece w;
        // One piece: its length is the step's (step_s / 1 exactly).
        const PieceOutcome outcome = try_piece(t, s0, rate0, forces.slack, forces.taut, t.step_s, w);
        if (outcome == PieceOutcome::at_rest) {
            state.velocity = rate0 + u;
            return 0.0f;
        }
        if (outcome == PieceOutcome::clear) {
            const float s = w.y + w.origin;
            state.stretch = s;
            state.velocity = w.v + u;
            if (w.region == Region::slack) return 0.0f;
            return tether_impulse(t, gravity, u, s0, rate0, s, w.v);
        }
    }
#endif
    return advance_pieces(t, gravity, state, line, hysteresis);
}

}  // namespace feel::detail
