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

// The axes a run of Verlet steps holds: as many as a compile-time count says, else all.
template <typename Count>
struct AxisCapacity {
    static constexpr int value = kMaxAxes;
};
template <int N>
struct AxisCapacity<std::integral_constant<int, N>> {
    static constexpr int value = N;
};

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
    void acceleration(Count n, const double* r, double* a) const noexcept {
        double r2 = 0;
        for (int i = 0; i < n; ++i) r2 += r[i] * r[i];
        const double distance = std::sqrt(r2);
        // −k·(|r| − L)/|r| per unit of r, when taut. L = 0: −k·r, smooth through r = 0.
        // The ratio is computed either way (inf or NaN at r = 0, then not used) so that the
        // choice is a select, not a branch on the step's chain that a string going slack
        // and taut would make the processor mispredict.
        const double ratio = length / distance;
        const double pull = distance > length ? -rate_squared * (1.0 - ratio) : 0.0;
        for (int i = 0; i < n; ++i) a[i] = pull * r[i];
    }

    // Verlet steps over h_total seconds for the fastest rate in play, rad/s.
    static int step_count(double rate, double h_total) noexcept {
        return static_cast<int>(
            std::clamp(std::ceil(rate * h_total / kMaxPhasePerStep), 1.0, static_cast<double>(kMaxSteps)));
    }

    // The ball's angular rate about the handle when the string is at its length, rad/s:
    // what the steps must resolve besides the string's own radial rate. With L = 0 the
    // string is a linear spring, which Verlet integrates exactly in angle, and only ω counts.
    template <typename Count>
    double turning_rate(Count n, const double* r, const double* relative_velocity) const noexcept {
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
        VerletRun<Count> run(n);
        begin(run, ball, handle, h_total);
        for (int step = 0; step < run.steps; ++step) take_step(run, step);
        finish(run, ball, impulse);
    }

    // Two slings' balls advanced together (advance_pair in ball_tick.hpp): each takes
    // exactly the steps it takes alone, in lockstep while both have steps left. A Verlet
    // step is one chain of dependent operations (a square root, then a division, then the
    // kick the next position needs), about 75 cycles of latency for a few instructions;
    // two independent chains side by side overlap in the processor, so the pair costs
    // about what one ball costs. The same operations on each ball, so the same bits.
    static void advance_pair(const Sling& a, BallMotion& ball_a, const BallHandlePath& handle_a, double h_a,
                             double impulse_a[kMaxAxes], const Sling& b, BallMotion& ball_b,
                             const BallHandlePath& handle_b, double h_b, double impulse_b[kMaxAxes]) noexcept {
#if !defined(__OPTIMIZE_SIZE__)
        if (a.count == 2 && b.count == 2) {
            using Two = std::integral_constant<int, 2>;
            VerletRun<Two> run_a(Two{});
            VerletRun<Two> run_b(Two{});
            a.begin(run_a, ball_a, handle_a, h_a);
            b.begin(run_b, ball_b, handle_b, h_b);
            const int together = std::min(run_a.steps, run_b.steps);
            int step = 0;
            for (; step < together; ++step) {
                a.take_step(run_a, step);
                b.take_step(run_b, step);
            }
            for (int s = step; s < run_a.steps; ++s) a.take_step(run_a, s);
            for (int s = step; s < run_b.steps; ++s) b.take_step(run_b, s);
            a.finish(run_a, ball_a, impulse_a);
            b.finish(run_b, ball_b, impulse_b);
            return;
        }
#endif
        a.advance(ball_a, handle_a, h_a, impulse_a);
        b.advance(ball_b, handle_b, h_b, impulse_b);
    }

    // A ball between begin and finish: its state per effect axis, and the steps it takes.
    // Sized for the count (two axes: 2), and set by begin, not zeroed: both runs of a pair
    // then stay in registers (zeroing six axes' worth took a `rep stos` of 336 bytes each).
    template <typename Count>
    struct VerletRun {
        static constexpr int kCapacity = AxisCapacity<Count>::value;
        explicit VerletRun(Count count) noexcept : n(count) {}
        Count n;
        double q[kCapacity];
        double v[kCapacity];
        double acc[kCapacity];    // the string's acceleration at q
        double kicks[kCapacity];  // Σ h·(string acceleration), the string's Δv
        double from[kCapacity];   // the handle's path, per effect axis
        double path_velocity[kCapacity];
        int steps = 0;
        double h = 0;
        double half_h = 0;
        double half_drag = 1;
    };

    template <typename Count>
    [[gnu::always_inline]] inline void begin(VerletRun<Count>& run, const BallMotion& ball, const BallHandlePath& handle,
               double h_total) const noexcept {
        const Count n = run.n;
        double r[VerletRun<Count>::kCapacity];
        double relative[VerletRun<Count>::kCapacity];
        for (int i = 0; i < n; ++i) {
            const int a = axes[i];
            run.kicks[i] = 0;
            run.q[i] = ball.position[a];
            run.v[i] = ball.velocity[a];
            run.from[i] = handle.from[a];
            run.path_velocity[i] = handle.velocity[a];
            r[i] = run.q[i] - run.from[i];
            relative[i] = run.v[i] - run.path_velocity[i];
        }
        acceleration(n, r, run.acc);
        // A ball at rest on a slack string beside a still handle stays exactly where it is
        // (every Verlet step maps it to itself): no steps, no impulse (finish writes the
        // ball back as it was and mass·0).
        bool idle = true;
        for (int i = 0; i < n; ++i) idle = idle && run.v[i] == 0 && run.path_velocity[i] == 0 && run.acc[i] == 0;
        if (idle) return;
        // The steps the string's own rate asks for depend on the advance's length alone;
        // when the ball turns no faster (most ticks), they are the steps. Taken by a branch,
        // not a select, so that the processor predicts it and starts stepping without
        // waiting for the turning rate's square roots and division, then the count's
        // division, rounding and conversions (about a hundred cycles on the ball's chain).
        // The same numbers either way: max(ω, turning) is ω.
        const double omega = std::sqrt(rate_squared);
        const int string_steps = step_count(omega, h_total);
        const double string_h = h_total / string_steps;
        const double turning = turning_rate(n, r, relative);
        if (turning <= omega) [[likely]] {
            run.steps = string_steps;
            run.h = string_h;
        } else {
            run.steps = step_count(std::max(omega, turning), h_total);
            run.h = h_total / run.steps;
        }
        run.half_h = 0.5 * run.h;
        run.half_drag = air_over_half_step(run.h);
    }

    template <typename Count>
    [[gnu::always_inline]] inline void take_step(VerletRun<Count>& run, int step) const noexcept {
        const Count n = run.n;
        const double t_end = (step + 1) * run.h;
        double r[VerletRun<Count>::kCapacity];
        for (int i = 0; i < n; ++i) {
            const double kick = run.half_h * run.acc[i];
            run.v[i] = run.v[i] * run.half_drag + kick;
            run.kicks[i] += kick;
            run.q[i] += run.h * run.v[i];
            r[i] = run.q[i] - (run.from[i] + run.path_velocity[i] * t_end);
        }
        acceleration(n, r, run.acc);
        for (int i = 0; i < n; ++i) {
            const double kick = run.half_h * run.acc[i];
            run.v[i] = (run.v[i] + kick) * run.half_drag;
            run.kicks[i] += kick;
        }
    }

    template <typename Count>
    [[gnu::always_inline]] inline void finish(const VerletRun<Count>& run, BallMotion& ball, double impulse[kMaxAxes]) const noexcept {
        for (int i = 0; i < run.n; ++i) {
            ball.position[axes[i]] = run.q[i];
            ball.velocity[axes[i]] = run.v[i];
            impulse[axes[i]] = mass * run.kicks[i];
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

void rest_sling(const DynamicContext& c, DynamicResult& result) noexcept {
    const SlotParams& p = *c.params;
    BallState& ball = c.state->ball;
    int axes[kMaxAxes] = {};
    for (int i = 0; i < p.axis_count; ++i) {
        axes[i] = axis_index(p.axes[i]);
        ball.handle[axes[i]] = c.position[axes[i]];  // the same value; as ball_expected_path writes it
        ball.handle_velocity[axes[i]] = c.velocity[axes[i]];
    }
    report_ball(ball.now, c, axes, p.axis_count, result);
    result.finished = false;
}

}  // namespace

// A ball at rest on a slack string beside a handle sensed where it was last tick: both of
// the tick's advances would be idle (Sling::begin: the handle's line has slope 0, the ball
// no velocity, the string no pull), the ball stays where it is and the reaction is 0 (ball_tick
// would add −0/T to a force of +0, which leaves +0). Only the handle's velocity is taken
// over; the rest of the tick, the Sling's units and both advances' set-up, is skipped. A
// sling left hanging beside a handle at rest costs this much.
bool sling_rests(const DynamicContext& c) noexcept {
    const DynamicState& state = *c.state;
    if (!state.initialized || !(c.dt_s > 0)) return false;
    const SlotParams& p = *c.params;
    const BallState& ball = state.ball;
    double r2 = 0;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = axis_index(p.axes[i]);
        if (ball.now.velocity[a] != 0 || c.position[a] != ball.handle[a]) return false;
        const double r = ball.now.position[a] - c.position[a];
        r2 += r * r;
    }
    // The string is slack (Sling::acceleration's test, on the same r): no pull.
    return !(std::sqrt(r2) > static_cast<double>(p.dynamic->string_length));
}

void sling_dynamic(const DynamicContext& c, double force[kMaxAxes], DynamicResult& result) noexcept {
    if (sling_rests(c)) {
        rest_sling(c, result);
        return;
    }
    const Sling sling(*c.params, *c.config);
    ball_tick(sling, sling.axes, sling.count, c, force);
    report_ball(c.state->ball.now, c, sling.axes, sling.count, result);
    result.finished = false;
}

void sling_pair_dynamic(const DynamicContext& a, const DynamicContext& b, double force_a[kMaxAxes],
                        double force_b[kMaxAxes], DynamicResult& result_a, DynamicResult& result_b) noexcept {
    if (sling_rests(a) || sling_rests(b)) {  // nothing to overlap
        sling_dynamic(a, force_a, result_a);
        sling_dynamic(b, force_b, result_b);
        return;
    }
    const Sling sling_a(*a.params, *a.config);
    const Sling sling_b(*b.params, *b.config);
    ball_tick_pair(sling_a, a, force_a, sling_b, b, force_b);
    report_ball(a.state->ball.now, a, sling_a.axes, sling_a.count, result_a);
    report_ball(b.state->ball.now, b, sling_b.axes, sling_b.count, result_b);
    result_a.finished = false;
    result_b.finished = false;
}

}  // namespace feel::detail
