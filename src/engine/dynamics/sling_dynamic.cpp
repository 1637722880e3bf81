// Dynamic Sling (§5.8): a ball on a string whose other end, the "bobbin", is the handle.
//
// The model. The ball is a point mass m free in the space of the effect's axes (the x-y
// plane for the §5.8 joystick sling; one axis gives a ball on a line, three a ball in
// space). The string, of rest length L, is a spring of stiffness k that pulls only when
// taut:
//
//     F = −k·(|r| − L)·r/|r|   when |r| > L,   0 otherwise        (on the ball; r = ball − handle)
//
// It pulls radially, along the string, and only inward. Nothing makes the ball spin but
// the user: circling the handle drags the ball around, and a ball circling at speed u at
// radius R needs the centripetal pull m·u²/R, so the faster it spins the harder the handle
// is pulled (§5.8). Ball damping is air resistance on the ball against the fixed frame,
// −c·v (§5.8: "in air versus in water"), not against the handle: a ball left spinning
// around a still handle winds down at the rate c/m.
//
// Parameters (§8.4: BallMass → Mass, StringCompliance → KPos, StringLength → Length,
// BallDamping → Drag; EngineConfig says what 10000 of each is on this device):
//   ball_mass          m = ball_mass/10000 · dynamic_mass_ref
//   string_length      L = string_length, position units (the control law's Length, free
//                      play between mass and handle): 10000 is half the handle's travel
//   string_compliance  k = string_compliance/10000 · dynamic_stiffness_ref: as §8.4 maps it
//                      onto KPos, the string's stiffness (10000 the stiffest, a steel
//                      cable; 1 a soft bungee)
//   ball_damping       c = ball_damping/10000 · dynamic_damping_ref
//
// The start. The ball hangs at the bobbin, at rest: seen from above, a ball hanging on a
// string is right under the hand, r = 0. No direction is preferred, and the user feels
// nothing until the handle has moved the string taut.
//
// Integration. The string is nonlinear (it switches between slack and taut, and turns with
// the ball), so no exact step exists; the ball is advanced with velocity Verlet, which is
// symplectic: with the handle still and no air resistance the energy ½m·v² + ½k·(|r| − L)²
// oscillates about its true value and does not drift. Air resistance is applied exactly,
// v·e^(−c·h/2m) before and after each step (Strang splitting), so any c is stable. The tick
// is cut into steps with h·max(ω, Ω) ≤ 0.025 (ω = √(k/m), the string's radial rate; Ω the
// ball's angular rate about the handle at the string's length). The energy then ripples
// about Verlet's conserved shadow energy by about (ω·h)²/2 = 0.03% (it scales as h²; a
// taut, turning string ripples more than the (ω·h)²/4 of a plain spring) and the phase
// error is (ω·h)²/24 = 3e-5 per radian.
//
// A tick (ball_tick.hpp): the ball is caught up to now along the handle's sensed path,
// then predicted one tick ahead with the handle going on the same way; the string's
// impulse on the ball over that tick (the sum of Verlet's kicks, exactly the momentum it
// gave) gives the mean pull the motor holds, the reaction −J/T: toward the ball. The ball
// relative to the handle goes to DynamicResult. The sling never ends by itself.
//
// Real-time safe: no allocation; at most kMaxSteps steps per tick.
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "dynamics/ball_tick.hpp"
#include "dynamics/dynamic.hpp"
#include "dynamics/dynamic_units.hpp"

namespace feel::detail {

namespace {

// Verlet steps are at most this many radians of the fastest rate in play.
constexpr double kMaxPhasePerStep = 0.025;
// Steps per tick at most: the stiffest string on the lightest ball of the built-in
// profiles (ω ≈ 7e3 rad/s) takes 280 over a 1 ms tick. The limit only binds in stalls,
// where h·ω stays below Verlet's stability limit of 2 for advances up to kBallMaxAdvanceS.
constexpr int kMaxSteps = 1024;

struct Sling {
    double mass = 1;          // m, force units per (position unit/s²)
    double stiffness = 0;     // k, force units per position unit
    double length = 0;        // L, position units
    double drag = 0;          // c, force units per (position unit/s)
    double rate_squared = 0;  // ω² = k/m, the string's radial rate squared: its pull per unit mass and stretch
    int axes[kMaxAxes] = {};  // the device axis of each of the effect's axes
    int count = 0;            // the effect's axes
    mutable double air_step_s = -1;  // the step length air_factor is for (air_over_half_step)
    mutable double air_factor = 1;

    Sling(const SlotParams& p, const EngineConfig& config) noexcept {
        const SlotDynamicBlock& d = *p.dynamic;
        mass = dynamic_mass(config, d.ball_mass);
        stiffness = dynamic_stiffness(config, d.string_compliance);
        length = d.string_length;
        drag = dynamic_damping(config, d.ball_damping);
        rate_squared = stiffness / mass;
        count = p.axis_count;
        for (int i = 0; i < p.axis_count; ++i) axes[i] = axis_index(p.axes[i]);
    }

    // e^(−c·h/2m), what the air leaves of the velocity over half a step of h seconds. The
    // catch-up and the prediction of a tick mostly take steps of the same length: the
    // exponential of the last length asked is kept (the Sling lives for one tick).
    double air_over_half_step(double h) const noexcept {
        if (h != air_step_s) {
            air_step_s = h;
            air_factor = std::exp(-drag * h / (2.0 * mass));
        }
        return air_factor;
    }

    // The string's pull on the ball per unit mass, for r = ball − handle (per effect axis).
    // Count is the number of the effect's axes: an int, or a compile-time constant for the
    // common two (advance says why).
    template <typename Count>
    void acceleration(Count n, const double r[kMaxAxes], double a[kMaxAxes]) const noexcept {
        double r2 = 0;
        for (int i = 0; i < n; ++i) r2 += r[i] * r[i];
        const double distance = std::sqrt(r2);
        // −k·(|r| − L)/|r| per unit of r, when taut. L = 0: −k·r, smooth through r = 0.
        const double pull = distance > length ? -rate_squared * (1.0 - length / distance) : 0.0;
        for (int i = 0; i < n; ++i) a[i] = pull * r[i];
    }

    // The ball's angular rate about the handle when the string is at its length, rad/s:
    // what the steps must resolve besides the string's own radial rate. With L = 0 the
    // string is a linear spring, which Verlet integrates exactly in angle, and only ω counts.
    template <typename Count>
    double turning_rate(Count n, const double r[kMaxAxes], const double relative_velocity[kMaxAxes]) const noexcept {
        if (length <= 0) return 0.0;
        double r2 = 0;
        double v2 = 0;
        for (int i = 0; i < n; ++i) {
            r2 += r[i] * r[i];
            v2 += relative_velocity[i] * relative_velocity[i];
        }
        return std::sqrt(v2) / std::max(std::sqrt(r2), length);
    }

    // Hanging at the bobbin, at rest.
    void start(BallMotion& ball, const DynamicContext& c) const noexcept {
        for (int i = 0; i < count; ++i) {
            ball.position[axes[i]] = c.position[axes[i]];
            ball.velocity[axes[i]] = 0;
        }
    }

    // Velocity Verlet with the air applied exactly around it (Strang splitting). Two axes
    // (the joystick's plane) are most slings: with the count a constant the loops unroll
    // and the ball's state stays in registers (the same operations in the same order as
    // for any count, so the same bits). Not in a build for size (-Os: the Cortex-M4F
    // image, whose double arithmetic is library calls either way), where the second copy
    // of the steps would cost 1.2 KB of flash.
    void advance(BallMotion& ball, const BallHandlePath& handle, double h_total,
                 double impulse[kMaxAxes]) const noexcept {
#if !defined(__OPTIMIZE_SIZE__)
        if (count == 2) {
            advance_axes(std::integral_constant<int, 2>{}, ball, handle, h_total, impulse);
            return;
        }
#endif
        advance_axes(count, ball, handle, h_total, impulse);
    }

    template <typename Count>
    void advance_axes(Count n, BallMotion& ball, const BallHandlePath& handle, double h_total,
                      double impulse[kMaxAxes]) const noexcept {
        double q[kMaxAxes] = {};
        double v[kMaxAxes] = {};
        double r[kMaxAxes] = {};
        double relative[kMaxAxes] = {};
        double kicks[kMaxAxes] = {};  // Σ h·(string acceleration), the string's Δv
        double from[kMaxAxes] = {};   // the handle's path, per effect axis
        double path_velocity[kMaxAxes] = {};
        for (int i = 0; i < n; ++i) {
            const int a = axes[i];
            q[i] = ball.position[a];
            v[i] = ball.velocity[a];
            from[i] = handle.from[a];
            path_velocity[i] = handle.velocity[a];
            r[i] = q[i] - from[i];
            relative[i] = v[i] - path_velocity[i];
        }
        // A ball at rest on a slack string beside a still handle stays exactly where it is
        // (every Verlet step maps it to itself): no steps, no impulse.
        bool idle = true;
        for (int i = 0; i < n; ++i) idle = idle && v[i] == 0 && path_velocity[i] == 0;
        if (idle) {
            double acc[kMaxAxes] = {};
            acceleration(n, r, acc);
            for (int i = 0; i < n; ++i) idle = idle && acc[i] == 0;
            if (idle) {
                for (int i = 0; i < n; ++i) impulse[axes[i]] = 0;
                return;
            }
        }
        const double rate = std::max(std::sqrt(rate_squared), turning_rate(n, r, relative));
        const int steps = static_cast<int>(
            std::clamp(std::ceil(rate * h_total / kMaxPhasePerStep), 1.0, static_cast<double>(kMaxSteps)));
        const double h = h_total / steps;
        const double half_h = 0.5 * h;
        const double half_drag = air_over_half_step(h);

        double acc[kMaxAxes] = {};
        acceleration(n, r, acc);
        for (int step = 0; step < steps; ++step) {
            const double t_end = (step + 1) * h;
            for (int i = 0; i < n; ++i) {
                const double kick = half_h * acc[i];
                v[i] = v[i] * half_drag + kick;
                kicks[i] += kick;
                q[i] += h * v[i];
                r[i] = q[i] - (from[i] + path_velocity[i] * t_end);
            }
            acceleration(n, r, acc);
            for (int i = 0; i < n; ++i) {
                const double kick = half_h * acc[i];
                v[i] = (v[i] + kick) * half_drag;
                kicks[i] += kick;
            }
        }
        for (int i = 0; i < n; ++i) {
            ball.position[axes[i]] = q[i];
            ball.velocity[axes[i]] = v[i];
            impulse[axes[i]] = mass * kicks[i];
        }
    }

    // The string's pull on the handle now: toward the ball, k·(|r| − L) when taut.
    void reaction(const BallMotion& ball, const DynamicContext& c, double force[kMaxAxes]) const noexcept {
        double r[kMaxAxes] = {};
        for (int i = 0; i < count; ++i) r[i] = ball.position[axes[i]] - c.position[axes[i]];
        double acc[kMaxAxes] = {};
        acceleration(count, r, acc);
        for (int i = 0; i < count; ++i) force[axes[i]] -= mass * acc[i];
    }
};

}  // namespace

void sling_dynamic(const DynamicContext& c, double force[kMaxAxes], DynamicResult& result) noexcept {
    const Sling sling(*c.params, *c.config);
    ball_tick(sling, sling.axes, sling.count, c, force);
    report_ball(c.state->ball.now, c, sling.axes, sling.count, result);
    result.finished = false;
}

}  // namespace feel::detail
