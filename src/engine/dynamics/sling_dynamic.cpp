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
// is cut into steps with h·max(ω, Ω) ≤ 0.044 (ω = √(k/m), the string's radial rate; Ω the
// ball's angular rate about the handle at the string's length). The energy then ripples
// about Verlet's conserved shadow energy by about (ω·h)²/2 ≤ 0.1% (it scales as h²; a
// taut, turning string ripples more than the (ω·h)²/4 of a plain spring) and the phase
// runs ahead by (ω·h)²/24 ≤ 8.1e-5 per radian (Verlet's rate on a spring is
// (2/h)·asin(ω·h/2)). Until issue 14's thirteenth pass the bound was 0.025 (0.03%, 2.6e-5):
// it took 4 steps an advance on a string of ω·h = 0.082 a tick, where 2 now keep the
// energy within 0.1% (sling_test.cpp's bound) at half the steps' chain.
//
// Float (issue 14: the Cortex-M4F's FPU is single precision; on x86 a float square root
// and division have about half a double's latency, and they are the step's chain). The
// ball is integrated relative to the handle (ball_state.hpp), and its offset is summed
// with compensation within a tick: a tick takes up to hundreds of steps, each moving the
// offset by far less than its magnitude, and rounding each would make the energy drift
// (2e-4 in the minute of the energy test; with the compensation it stays within the
// test's 1e-4). The velocity is not compensated: the energy and impulse tests hold
// without it, and it would lengthen the chain by another addition.
//
// A tick (ball_tick.hpp): the ball is caught up to now along the handle's sensed path,
// then predicted one tick ahead with the handle going on the same way; the string's
// impulse on the ball over that tick (the sum of Verlet's kicks, exactly the momentum it
// gave) gives the mean pull the motor holds, the reaction −J/T: toward the ball. The ball
// relative to the handle goes to DynamicResult. The sling never ends by itself.
//
// Real-time safe: no allocation; at most kMaxSteps steps per tick.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "dynamics/ball_tick.hpp"
#include "dynamics/dynamic.hpp"

namespace feel::detail {

namespace {

// Verlet steps are at most this many radians of the fastest rate in play: (ω·h)²/2 < 1e-3,
// the energy's ripple the model promises (the header's "Integration").
constexpr float kMaxPhasePerStep = 0.044f;
// Steps per tick at most: the stiffest string on the lightest ball of the built-in
// profiles (ω ≈ 7e3 rad/s) takes 160 over a 1 ms tick. The limit only binds in stalls,
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

// The sling's law in float, from its parameters (the form's steps are left as they were).
void work_out_law(SlingForm& law, const SlotParams& p, const EngineConfig& config) noexcept {
    const SlotDynamicBlock& d = *p.dynamic;
    law.mass = ball_scale(d.ball_mass, config.dynamic_mass_ref);
    const float stiffness = ball_scale(d.string_compliance, config.dynamic_stiffness_ref);
    law.length = static_cast<float>(d.string_length);
    law.drag = ball_scale(d.ball_damping, config.dynamic_damping_ref);
    law.rate_squared = stiffness / law.mass;
    law.rate_length = law.rate_squared * law.length;
    law.rate = std::sqrt(law.rate_squared);
    law.end_r2 = std::numeric_limits<float>::quiet_NaN();  // the old law's pull
}

// −k·(|r| − L)/|r| = k·L/|r| − k per unit of r and mass when taut, for |r|² = r2: the
// string's pull on the ball per unit mass is this times r. L = 0: −k, smooth through r = 0.
// The quotient is computed either way (inf or NaN at r = 0, then not used) so that the
// choice is a select, not a branch on the step's chain that a string going slack and taut
// would make the processor mispredict.
float pull_at(const SlingForm& law, float r2) noexcept {
    const float distance = std::sqrt(r2);
    return distance > law.length ? law.rate_length / distance - law.rate_squared : 0.0f;
}

// Summed from the first square, not from +0: 0 + x is x for every square (never −0) and
// NaN, and the addition would lengthen the step's chain (sqrt, division, ...) by its latency.
template <typename Count>
float squared_norm(Count n, const float* r) noexcept {
    if (n <= 0) return 0;
    float r2 = r[0] * r[0];
    for (int i = 1; i < n; ++i) r2 += r[i] * r[i];
    return r2;
}

// Verlet steps over h_total seconds for the fastest rate in play, rad/s: the phase over
// kMaxPhasePerStep rounded up, 1 to kMaxSteps (a NaN or infinite rate: kMaxSteps). The
// rounding up is done by hand: ceilf is a library call on the Cortex-M4F.
int step_count(float rate, float h_total) noexcept {
    const float phase_steps = rate * h_total / kMaxPhasePerStep;
    if (!(phase_steps < static_cast<float>(kMaxSteps))) return kMaxSteps;
    const int whole = static_cast<int>(phase_steps);  // >= 0: rate and h_total are
    return std::max(1, whole + (static_cast<float>(whole) < phase_steps ? 1 : 0));
}

// The constants of `steps` Verlet steps over h_total seconds (Sling::VerletRun says what
// each is for).
void work_out_steps(SlingSteps& k, const SlingForm& law, int steps, float h_total) noexcept {
    k.count = steps;
    k.h = h_total / static_cast<float>(steps);
    k.half_h = 0.5f * k.h;
    k.half_drag = ball_decay(law.drag * k.h / (2.0f * law.mass));
    k.drag_squared = k.half_drag * k.half_drag;
    k.kick_gain = k.half_h * (1.0f + k.drag_squared);
    const float move_gain = k.h * k.kick_gain;
    k.move_pull = move_gain * law.rate_length;
    k.move_rate = move_gain * law.rate_squared;
}

// The slot keeps the sling's form (BallState::sling) between ticks. Not in a build for
// size (the Cortex-M4F image, whose flash is the tighter budget): there the Sling works the
// law out each tick and keeps the steps for the tick only, in a form of its own; the same
// operations on the same numbers, so the same bits.
// Nor does it take the pull the catch-up ended with for the prediction's start
// (SlingForm::end_pull), which it works out again.
// Nor does a step hand the squared distance it ends at to the next (Sling::take_step): on
// the in-order core nothing waits on the run's store and load, and summing at the next
// step's start is smaller (12 bytes, 24 instructions a tick).
#if defined(__OPTIMIZE_SIZE__)
constexpr bool kSlotKeepsForm = false;
constexpr bool kReusesEndPull = false;
constexpr bool kStepHandsOnDistance = false;
#else
constexpr bool kSlotKeepsForm = true;
constexpr bool kReusesEndPull = true;
constexpr bool kStepHandsOnDistance = true;
#endif

struct Sling {
    const SlotParams& params;
    const EngineConfig& config;
    DynamicState& state;      // the slot's: the ball, and the form (BallState::sling) once the ball is live
    int axes[kMaxAxes] = {};  // the device axis of each of the effect's axes
    int count = 0;            // the effect's axes
#if defined(__OPTIMIZE_SIZE__)
    mutable SlingForm own_form;  // the form, as the slot keeps none (kSlotKeepsForm)
    SlingForm& form = own_form;
#else
    SlingForm& form;  // the slot's
#endif

    explicit Sling(const DynamicContext& c) noexcept
#if defined(__OPTIMIZE_SIZE__)
        : params(*c.params), config(*c.config), state(*c.state) {
        work_out_law(own_form, params, config);
#else
        : params(*c.params), config(*c.config), state(*c.state), form(c.state->ball.sling) {
#endif
        count = params.axis_count;
        for (int i = 0; i < count; ++i) axes[i] = axis_index(params.axes[i]);
    }

    // The law, kept in the slot's form from one command that sets the parameters to the
    // next (DynamicState::prepared): four divisions and a square root a tick less. That
    // form is the live ball's (ball_tick starts the ball before the sling advances or
    // reacts).
    [[gnu::always_inline]] inline const SlingForm& law() const noexcept {
        if (kSlotKeepsForm && !state.prepared) {
            work_out_law(form, params, config);
            form.advance_s = 0;  // its steps were the old law's
            state.prepared = true;
        }
        return form;
    }

    // The ball's angular rate about the handle when the string is at its length, rad/s, for
    // |r|² = r2: what the steps must resolve besides the string's own radial rate. With
    // L = 0 the string is a linear spring, which Verlet integrates exactly in angle, and
    // only ω counts.
    template <typename Count>
    static float turning_rate(const SlingForm& law, Count n, float r2, const float* relative_velocity) noexcept {
        if (law.length <= 0) return 0.0f;
        const float v2 = squared_norm(n, relative_velocity);
        return std::sqrt(v2) / std::max(std::sqrt(r2), law.length);
    }

    // Hanging at the bobbin, at rest.
    void start(BallMotion& ball, const DynamicContext&) const noexcept {
        for (int i = 0; i < count; ++i) {
            ball.offset[axes[i]] = 0;
            ball.velocity[axes[i]] = 0;
        }
    }

    // Velocity Verlet with the air applied exactly around it (Strang splitting). Two axes
    // (the joystick's plane) are most slings: with the count a constant the loops unroll
    // and the ball's state stays in registers (the same operations in the same order as
    // for any count, so the same bits). Not in a build for size (-Os: the Cortex-M4F
    // image), where a second copy of the steps costs flash the board is short of.
    void advance(BallMotion& ball, const BallHandlePath& handle, float h_total,
                 float impulse[kMaxAxes]) const noexcept {
        advance_from(ball, &ball, handle, h_total, impulse);
    }

    // The impulse of an advance from `ball`, which stays as it is (ball_tick's prediction):
    // read where it lies, not copied (a copy's wide loads of what the catch-up has just
    // stored one float at a time would wait for the stores to reach the cache).
    void predict(const BallMotion& ball, const BallHandlePath& handle, float h_total,
                 float impulse[kMaxAxes]) const noexcept {
        advance_from(ball, nullptr, handle, h_total, impulse);
    }

    // An advance from `from`, its end written to *to (none: a prediction).
    void advance_from(const BallMotion& from, BallMotion* to, const BallHandlePath& handle, float h_total,
                      float impulse[kMaxAxes]) const noexcept {
#if !defined(__OPTIMIZE_SIZE__)
        if (count == 2) {
            advance_axes(std::integral_constant<int, 2>{}, from, to, handle, h_total, impulse);
            return;
        }
#endif
        advance_axes(count, from, to, handle, h_total, impulse);
    }

    template <typename Count>
    void advance_axes(Count n, const BallMotion& from, BallMotion* to, const BallHandlePath& handle,
                      float h_total, float impulse[kMaxAxes]) const noexcept {
        VerletRun<Count> run(n);
        float r2 = begin(run, from, handle, h_total);
        for (int step = 1; step < run.steps; ++step) r2 = take_step(run, r2);
        finish(run, r2, to, impulse);
    }

    // Two slings' balls advanced together (advance_pair in ball_tick.hpp): each takes
    // exactly the steps it takes alone, in lockstep while both have steps left. A Verlet
    // step is one chain of dependent operations (a square root, then a division, then the
    // move the next position needs); two independent chains side by side overlap in the
    // processor, so the pair costs about what one ball costs. The same operations on each
    // ball, so the same bits.
    // From `from_a` and `from_b`, their ends written to *to_a and *to_b (none: predictions).
    static void advance_pair(const Sling& a, const BallMotion& from_a, BallMotion* to_a, const BallHandlePath& handle_a,
                             float h_a, float impulse_a[kMaxAxes], const Sling& b, const BallMotion& from_b,
                             BallMotion* to_b, const BallHandlePath& handle_b, float h_b,
                             float impulse_b[kMaxAxes]) noexcept {
#if !defined(__OPTIMIZE_SIZE__)
        if (a.count == 2 && b.count == 2) {
            using Two = std::integral_constant<int, 2>;
            VerletRun<Two> run_a(Two{});
            VerletRun<Two> run_b(Two{});
            float r2_a = a.begin(run_a, from_a, handle_a, h_a);
            float r2_b = b.begin(run_b, from_b, handle_b, h_b);
            const int together = std::min(run_a.steps, run_b.steps);
            int step = 1;
            for (; step < together; ++step) {
                r2_a = a.take_step(run_a, r2_a);
                r2_b = b.take_step(run_b, r2_b);
            }
            for (int s = step; s < run_a.steps; ++s) r2_a = a.take_step(run_a, r2_a);
            for (int s = step; s < run_b.steps; ++s) r2_b = b.take_step(run_b, r2_b);
            a.finish(run_a, r2_a, to_a, impulse_a);
            b.finish(run_b, r2_b, to_b, impulse_b);
            return;
        }
#endif
        a.advance_from(from_a, to_a, handle_a, h_a, impulse_a);
        b.advance_from(from_b, to_b, handle_b, h_b, impulse_b);
    }

    // A ball between begin and finish: its state per effect axis, and the steps it takes.
    // Sized for the count (two axes: 2), and set by begin, not zeroed: both runs of a pair
    // then stay in registers (zeroing six axes' worth took a `rep stos` of 336 bytes each).
    // r is the ball relative to the handle moving along its path: a step moves it by
    // h·(v − path velocity), so the handle's place on the travel costs r no resolution.
    //
    // The steps are velocity Verlet with the air around each (Strang splitting): per step
    // v ← v·D + (h/2)·a(r), r ← r + h·(v − u), v ← (v + (h/2)·a(r))·D, D = e^(−c·h/2m).
    // Between two steps the second half kick and the next first half kick read the same
    // a(r): the run keeps the velocity of the drift, v_d, and takes the two half kicks
    // and the air between them as one, v_d ← v_d·D² + (h/2)·(1 + D²)·a(r) (the same
    // Verlet, the same symplectic map; only the roundings differ). And the move is
    // formed from what is known before a(r): r ← r + [h·(v_d·D² − u) − r_low] +
    // h·(h/2)·(1 + D²)·a(r), a(r) = (k·L/(m·|r|) − k/m)·r, the factor scaled by
    // h·(h/2)·(1 + D²) as one division and one subtraction. What each step waits for is
    // then the distance's square root, the division, a subtraction, a multiplication and
    // the compensated addition (about 45 cycles of latency on x86, from some 85 when the
    // move waited for the velocity's five updates).
    template <typename Count>
    struct VerletRun {
        static constexpr int kCapacity = AxisCapacity<Count>::value;
        explicit VerletRun(Count count) noexcept : n(count) {}
        Count n;
        float r[kCapacity];
        float r_low[kCapacity];  // what rounding r dropped, to add back (compensated sum)
        float v[kCapacity];      // the velocity of the last drift (v_d); the ball's, once finished
        float drift[kCapacity];  // the next move without the string's pull: h·(v_d·D² − u) − r_low
        float kicks[kCapacity];  // Σ (h/2)·(string acceleration) over the half kicks, the string's Δv
        float path_velocity[kCapacity];  // the handle's, per effect axis
        const SlingForm* form = nullptr;  // the string's law and the steps' constants (Sling::law)
        int steps = 0;                    // 0: idle (the ball stays as it is), else the Verlet steps
    };

    // The string's pull per unit mass and of r (a = pull·r), and the same scaled for the
    // move (move_pull/|r| − move_rate, when taut), from the squared distance.
    template <typename Count>
    [[gnu::always_inline]] inline void step_pulls(const VerletRun<Count>& run, float r2, float& pull,
                                                  float& move) const noexcept {
        const float distance = std::sqrt(r2);
        // Both quotients are computed either way (inf or NaN at r = 0, then not used) so
        // that the choice is a select, not a branch on the step's chain that a string going
        // slack and taut would make the processor mispredict. L = 0: pull = −k/m, smooth
        // through r = 0.
        const SlingForm& law = *run.form;
        const bool taut = distance > law.length;
        pull = taut ? law.rate_length / distance - law.rate_squared : 0.0f;
        move = taut ? run.form->steps.move_pull / distance - run.form->steps.move_rate : 0.0f;
    }

    // Returns the squared distance the first step ended at (the next step's, or finish's).
    template <typename Count>
    [[gnu::always_inline]] inline float begin(VerletRun<Count>& run, const BallMotion& ball,
                                              const BallHandlePath& handle, float h_total) const noexcept {
        const Count n = run.n;
        float relative[VerletRun<Count>::kCapacity];
        for (int i = 0; i < n; ++i) {
            const int a = axes[i];
            run.r_low[i] = 0;
            run.r[i] = ball.offset[a];
            run.v[i] = ball.velocity[a];
            run.path_velocity[i] = handle.velocity[a];
            relative[i] = run.v[i] - run.path_velocity[i];
        }
        const SlingForm& law = this->law();
        run.form = &law;
        // The prediction starts where the catch-up ended, and the next tick's catch-up where
        // this one ended (its offset is to the handle sensed then): the pull finish worked
        // out there, kept in the form (a square root and a division off the head of the chain).
        const float r2 = squared_norm(n, run.r);
        float pull;
        if (kReusesEndPull && r2 == law.end_r2) {
            pull = law.end_pull;
        } else {
            pull = pull_at(law, r2);
        }
        float acc[VerletRun<Count>::kCapacity];
        for (int i = 0; i < n; ++i) acc[i] = pull * run.r[i];
        // A ball at rest on a slack string beside a still handle stays exactly where it is
        // (every Verlet step maps it to itself): no steps, no impulse (finish writes the
        // ball back as it was and mass·0).
        // All of them ±0: their bits ORed, the sign shifted out (a NaN is not 0, as for ==).
        uint32_t bits = 0;
        for (int i = 0; i < n; ++i) {
            bits |= std::bit_cast<uint32_t>(run.v[i]) | std::bit_cast<uint32_t>(run.path_velocity[i]) |
                    std::bit_cast<uint32_t>(acc[i]);
        }
        if (bits << 1 == 0) {
            for (int i = 0; i < n; ++i) run.kicks[i] = 0;
            return r2;  // not read: no steps
        }
        // The steps the string's own rate asks for depend on the advance's length alone;
        // when the ball turns no faster (most ticks), they are the steps. Taken by a branch,
        // not a select, so that the processor predicts it and starts stepping without
        // waiting for the turning rate's square roots and division. The same numbers either
        // way: max(ω, turning) is ω. The form keeps them until the tick's length changes (at
        // a fixed loop rate, never): a division, the air's exponential and the count's
        // rounding a tick less. A ball turning faster has steps of its own for this
        // advance, worked out in the form's place and not kept.
        const float turning = turning_rate(law, n, r2, relative);
        const bool turns_faster = !(turning <= law.rate);
        if (turns_faster || form.advance_s != h_total) [[unlikely]] {
            work_out_steps(form.steps, law, step_count(std::max(law.rate, turning), h_total), h_total);
            form.advance_s = turns_faster ? 0.0f : h_total;
        }
        const SlingSteps& k = form.steps;
        run.steps = k.count;
        // The first step's half kick and drift.
        for (int i = 0; i < n; ++i) {
            const float kick = k.half_h * acc[i];
            run.kicks[i] = kick;
            run.v[i] = run.v[i] * k.half_drag + kick;
            const float move = k.h * (run.v[i] - run.path_velocity[i]);
            const float moved = run.r[i] + move;
            run.r_low[i] = (moved - run.r[i]) - move;
            run.r[i] = moved;
            run.drift[i] = k.h * (run.v[i] * k.drag_squared - run.path_velocity[i]) - run.r_low[i];
        }
        return kStepHandsOnDistance ? squared_norm(n, run.r) : 0.0f;
    }

    // The kicks between a step and the next (at the squared distance r2 the last ended at),
    // and the next step's drift; returns the squared distance this step ends at. Summed
    // here, right after the move, the compiler takes the positions from the registers that
    // computed them; summed at the next step's start, it loaded them back from the run on
    // the stack, a store and a load on every step's chain.
    template <typename Count>
    [[gnu::always_inline]] inline float take_step(VerletRun<Count>& run, float r2) const noexcept {
        const Count n = run.n;
        if (!kStepHandsOnDistance) r2 = squared_norm(n, run.r);
        float pull;
        float move_pull;
        step_pulls(run, r2, pull, move_pull);
        const SlingSteps& k = run.form->steps;
        for (int i = 0; i < n; ++i) {
            const float acc = pull * run.r[i];
            run.kicks[i] += k.h * acc;  // two half kicks: h/2 is h·0.5 exactly
            run.v[i] = run.v[i] * k.drag_squared + k.kick_gain * acc;
            const float move = run.drift[i] + move_pull * run.r[i];
            const float moved = run.r[i] + move;
            run.r_low[i] = (moved - run.r[i]) - move;
            run.r[i] = moved;
            run.drift[i] = k.h * (run.v[i] * k.drag_squared - run.path_velocity[i]) - run.r_low[i];
        }
        return kStepHandsOnDistance ? squared_norm(n, run.r) : 0.0f;
    }

    // The last step's second half kick and air, at the squared distance r2 it ended at; the
    // ball to *ball (none: a prediction, whose end no advance starts from, so its pull is not
    // kept either).
    template <typename Count>
    [[gnu::always_inline]] inline void finish(VerletRun<Count>& run, float r2, BallMotion* ball,
                                              float impulse[kMaxAxes]) const noexcept {
        if (run.steps > 0) {
            const SlingSteps& k = run.form->steps;
            if (!kStepHandsOnDistance) r2 = squared_norm(run.n, run.r);
            const float pull = pull_at(*run.form, r2);
            if (kReusesEndPull && ball != nullptr) {
                form.end_r2 = r2;
                form.end_pull = pull;
            }
            for (int i = 0; i < run.n; ++i) {
                const float kick = k.half_h * (pull * run.r[i]);
                run.v[i] = (run.v[i] + kick) * k.half_drag;
                run.kicks[i] += kick;
            }
        }
        for (int i = 0; i < run.n; ++i) {
            if (ball != nullptr) {
                ball->offset[axes[i]] = run.r[i];
                ball->velocity[axes[i]] = run.v[i];
            }
            impulse[axes[i]] = run.form->mass * run.kicks[i];
        }
    }

    // The string's pull on the handle now: toward the ball, k·(|r| − L) when taut.
    // (ball_tick calls it after ball_expected_path: the offset is to the handle sensed now.)
    void reaction(const BallMotion& ball, const DynamicContext&, float force[kMaxAxes]) const noexcept {
        float r[kMaxAxes] = {};
        for (int i = 0; i < count; ++i) r[i] = ball.offset[axes[i]];
        const SlingForm& law = this->law();
        const float pull = pull_at(law, squared_norm(count, r));
        for (int i = 0; i < count; ++i) force[axes[i]] -= law.mass * (pull * r[i]);
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
    float r2 = 0;
    for (int i = 0; i < p.axis_count; ++i) {
        const int a = axis_index(p.axes[i]);
        if (ball.now.velocity[a] != 0 || c.position[a] != ball.handle[a]) return false;
        const float r = ball.now.offset[a];
        r2 += r * r;
    }
    // The string is slack (Sling::acceleration's test, on the same r): no pull.
    return !(std::sqrt(r2) > static_cast<float>(p.dynamic->string_length));
}

void sling_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept {
    if (sling_rests(c)) {
        rest_sling(c, result);
        return;
    }
    const Sling sling(c);
    ball_tick(sling, sling.axes, sling.count, c, force);
    report_ball(c.state->ball.now, c, sling.axes, sling.count, result);
    result.finished = false;
}

void sling_pair_dynamic(const DynamicContext& a, const DynamicContext& b, float force_a[kMaxAxes],
                        float force_b[kMaxAxes], DynamicResult& result_a, DynamicResult& result_b) noexcept {
    // A resting b has nothing to overlap. A resting a (the engine asks before pairing)
    // takes its two idle advances beside b's, which leave what its short way does.
    if (sling_rests(b)) {
        sling_dynamic(a, force_a, result_a);
        sling_dynamic(b, force_b, result_b);
        return;
    }
    const Sling sling_a(a);
    const Sling sling_b(b);
    ball_tick_pair(sling_a, a, force_a, sling_b, b, force_b);
    report_ball(a.state->ball.now, a, sling_a.axes, sling_a.count, result_a);
    report_ball(b.state->ball.now, b, sling_b.axes, sling_b.count, result_b);
    result_a.finished = false;
    result_b.finished = false;
}

}  // namespace feel::detail
