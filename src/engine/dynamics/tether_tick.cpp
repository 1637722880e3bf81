// The float, per-tick step of one control-law axis; tether_tick.hpp says how it goes.
#include "dynamics/tether_tick.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/tether_piece.hpp"
#include "dynamics/tether_step.hpp"

namespace feel::detail {

namespace {

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
            taut = taut || w.region != TetherRegion::slack;
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
        float impulse;
        if (advance_one_watched_piece(t, gravity, state, line, impulse)) return impulse;
    }
#endif
    return advance_pieces(t, gravity, state, line, hysteresis);
}

}  // namespace feel::detail
