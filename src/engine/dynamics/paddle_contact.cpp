// The paddle's one-sided contact, integrated exactly; see paddle_contact.hpp.
#include "dynamics/paddle_contact.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/tether_step.hpp"

namespace feel::detail {

namespace {

// Pieces of a tick are at most this many radians of the contact's natural frequency, so
// that within one the push rises or falls through zero at most once and bisection on
// the piece's end points finds every change of stage.
constexpr float kMaxPhasePerPiece = 0.5f;
// Pieces per tick at most: the stiffest paddle under the lightest ball of the built-in
// profiles (ω ≈ 7e3 rad/s) takes 14 over a 1 ms tick; this only binds in stalls.
constexpr int kMaxPieces = 256;
// Changes of stage located per tick at most (a bounce has two). A state grazing the
// surface could chatter between stages; past this the tick ends in its current stage.
constexpr int kMaxStageChanges = 8;
// The instant of a change of stage is bisected until the bracket is 2^-24 of the piece
// (float's resolution of a time within it) or float cannot split it any more.
constexpr float kBisectionTolerance = 0x1p-24f;
// What is left of a tick after its whole pieces is their rounding (a few ulps of a piece):
// a remainder within this fraction of a piece is the last piece, not a piece and a crumb.
constexpr float kLastPieceSlack = 1.0f + 0x1p-10f;

// The motion in one stage from (y0, v0) after t.
MassStateF propagate(const PaddleContactParams& p, bool pressed, MassStateF start, float t) noexcept {
    SpringDamperF motion;
    motion.mass = p.mass;
    if (pressed) {
        // m·y'' + b·y' + k·y = −b·δ − m·g
        motion.stiffness = p.stiffness;
        motion.damping = p.damping;
        motion.force = -p.damping * p.damper_offset - p.mass * p.gravity;
    } else {
        motion.force = -p.mass * p.gravity;  // a parabola
    }
    return tether_step<float>(motion, start, t);
}

// ⌈x⌉ pieces, 1 to kMaxPieces (by a conversion: ceilf is a library call on the Cortex-M4F).
int pieces_for(float x) noexcept {
    if (!(x > 1.0f)) return 1;
    if (!(x < static_cast<float>(kMaxPieces))) return kMaxPieces;
    int n = static_cast<int>(x);
    if (static_cast<float>(n) < x) ++n;
    return n;
}

}  // namespace

float paddle_contact_force(const PaddleContactParams& p, float y, float v) noexcept {
    if (!(y < 0)) return 0.0f;
    return std::max(0.0f, -p.stiffness * y - p.damping * (v + p.damper_offset));
}

bool paddle_presses(const PaddleContactParams& p, float y, float v) noexcept {
    return y < 0 && -p.stiffness * y - p.damping * (v + p.damper_offset) > 0;
}

float advance_paddle_contact(PaddleContact& c, const PaddleContactParams& p, float dt_s) noexcept {
    if (!(dt_s > 0)) return 0.0f;
    const float start_velocity = c.v;
    const float omega = std::sqrt(p.stiffness / p.mass);
    const int pieces = pieces_for(omega * dt_s / kMaxPhasePerPiece);
    const float piece = dt_s / static_cast<float>(pieces);
    float remaining = dt_s;
    int changes = 0;
    // The pieces are laid from the start of the tick; a change of stage splits one.
    while (remaining > 0) {
        const float h = remaining < piece * kLastPieceSlack ? remaining : piece;
        const MassStateF start{c.y, c.v};
        const MassStateF end = propagate(p, c.pressed, start, h);
        if (paddle_presses(p, end.position, end.velocity) != c.pressed && changes < kMaxStageChanges) {
            // The stage changes within (0, h]: bisect for the first instant it has changed,
            // and continue from there in the new stage.
            float lo = 0;
            float hi = h;
            MassStateF at_hi = end;
            const float tolerance = kBisectionTolerance * h;
            while (hi - lo > tolerance) {
                const float mid = 0.5f * (lo + hi);
                if (!(mid > lo && mid < hi)) break;
                const MassStateF at_mid = propagate(p, c.pressed, start, mid);
                if (paddle_presses(p, at_mid.position, at_mid.velocity) != c.pressed) {
                    hi = mid;
                    at_hi = at_mid;
                } else {
                    lo = mid;
                }
            }
            c.y = at_hi.position;
            c.v = at_hi.velocity;
            if (c.pressed) c.contact_s += hi;
            c.pressed = !c.pressed;
            remaining = hi < remaining ? remaining - hi : 0.0f;
            ++changes;
            continue;
        }
        c.y = end.position;
        c.v = end.velocity;
        if (c.pressed) c.contact_s += h;
        remaining = h < remaining ? remaining - h : 0.0f;
    }
    // Only the paddle and gravity act along n: what gravity does not explain, the paddle did.
    return std::max(0.0f, p.mass * (c.v - start_velocity) + p.mass * p.gravity * dt_s);
}

}  // namespace feel::detail
