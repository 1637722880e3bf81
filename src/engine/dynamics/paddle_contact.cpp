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
constexpr double kMaxPhasePerPiece = 0.5;
// Pieces per tick at most: the stiffest paddle under the lightest ball of the built-in
// profiles (ω ≈ 7e3 rad/s) takes 14 over a 1 ms tick; this only binds in stalls.
constexpr int kMaxPieces = 256;
// Changes of stage located per tick at most (a bounce has two). A state grazing the
// surface could chatter between stages; past this the tick ends in its current stage.
constexpr int kMaxStageChanges = 8;
// Bisection steps for the instant of a change of stage: 2⁻⁴⁰ (1e-12) of a piece, a
// picosecond at the 1 kHz loop.
constexpr int kBisectionSteps = 40;

// The motion in one stage from (y0, v0) after t.
void propagate(const PaddleContactParams& p, bool pressed, double y0, double v0, double t, double& y,
               double& v) noexcept {
    SpringDamper motion;
    motion.mass = p.mass;
    if (pressed) {
        // m·y'' + b·y' + k·y = −b·δ − m·g
        motion.stiffness = p.stiffness;
        motion.damping = p.damping;
        motion.force = -p.damping * p.damper_offset - p.mass * p.gravity;
    } else {
        motion.force = -p.mass * p.gravity;  // a parabola
    }
    const MassState end = tether_step(motion, MassState{y0, v0}, t);
    y = end.position;
    v = end.velocity;
}

}  // namespace

double paddle_contact_force(const PaddleContactParams& p, double y, double v) noexcept {
    if (!(y < 0)) return 0.0;
    return std::max(0.0, -p.stiffness * y - p.damping * (v + p.damper_offset));
}

bool paddle_presses(const PaddleContactParams& p, double y, double v) noexcept {
    return y < 0 && -p.stiffness * y - p.damping * (v + p.damper_offset) > 0;
}

double advance_paddle_contact(PaddleContact& c, const PaddleContactParams& p, double dt_s) noexcept {
    if (!(dt_s > 0)) return 0.0;
    const double start_velocity = c.v;
    const double omega = std::sqrt(p.stiffness / p.mass);
    const int pieces = static_cast<int>(std::clamp(std::ceil(omega * dt_s / kMaxPhasePerPiece), 1.0,
                                                   static_cast<double>(kMaxPieces)));
    const double piece = dt_s / pieces;
    double remaining = dt_s;
    int changes = 0;
    // The pieces are laid from the start of the tick; a change of stage splits one.
    while (remaining > 0) {
        const double h = std::min(piece, remaining);
        double y = 0;
        double v = 0;
        propagate(p, c.pressed, c.y, c.v, h, y, v);
        if (paddle_presses(p, y, v) != c.pressed && changes < kMaxStageChanges) {
            // The stage changes within (0, h]: bisect for the first instant it has changed,
            // and continue from there in the new stage.
            double lo = 0;
            double hi = h;
            for (int i = 0; i < kBisectionSteps; ++i) {
                const double mid = 0.5 * (lo + hi);
                double ym = 0;
                double vm = 0;
                propagate(p, c.pressed, c.y, c.v, mid, ym, vm);
                (paddle_presses(p, ym, vm) != c.pressed ? hi : lo) = mid;
            }
            propagate(p, c.pressed, c.y, c.v, hi, c.y, c.v);
            if (c.pressed) c.contact_s += hi;
            c.pressed = !c.pressed;
            remaining = hi < remaining ? remaining - hi : 0.0;
            ++changes;
            continue;
        }
        c.y = y;
        c.v = v;
        if (c.pressed) c.contact_s += h;
        remaining = h < remaining ? remaining - h : 0.0;
    }
    // Only the paddle and gravity act along n: what gravity does not explain, the paddle did.
    return std::max(0.0, p.mass * (c.v - start_velocity) + p.mass * p.gravity * dt_s);
}

}  // namespace feel::detail
