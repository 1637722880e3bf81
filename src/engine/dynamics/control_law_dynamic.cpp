// The control-law dynamics (§5.3-§5.7, §5.10): recoil, impact, liquid, inertia, center
// drift and the control law itself, each a mass tethered to the handle on every axis of
// the effect (tether_law.hpp has the model, control_law_mapping.cpp the §8.4 table).
//
// How a tick works, and why. The engine computes a force once per tick and the motor holds
// it until the next one. A tether force sampled at the start of the tick and held lags the
// real tether, and a lagging spring between a handle and a mass pumps energy into the
// pair: a light mass on a stiff tether, coupled to the handle this way, rings and grows
// even on a device whose damping would hold a wall of the same stiffness (the sampled-data
// analysis in docs/dynamics.md). So each tick:
//
//   1. Catch up: the mass is advanced exactly from the previous tick to this one against
//      the path the sensor saw: the handle moving in a straight line from where it was
//      sensed then to where it is sensed now. The spring therefore never sees the handle
//      jump. The tether's damper measures the mass's velocity against the handle velocity
//      the engine estimated last tick (the same the last prediction used), not against
//      the slope of that line: a sensor count crossed in one tick would otherwise read as
//      a velocity spike of a count per tick and kick the mass.
//   2. Predict: a copy of the mass is advanced one more tick (as long as the last one)
//      against the handle going on along that line (its damper again measuring against
//      the estimated velocity). The momentum the tether gives the mass over that tick,
//      divided by its length, is the mean tether force over the tick the motor is about to
//      hold; the handle gets its reaction. Only the force is kept; the next tick catches
//      up along what the sensor then saw.
//
// The handle thus receives, over every tick, the reaction impulse of the tether force the
// mass receives if the hand does what it was doing: the pair exchanges momentum without
// the half-tick lag of a held sample (the prediction's −k·u·T/2 is the damping that
// cancels the sampled spring's energy leak). On the engine's very first tick there is no
// tick length to predict over; the force is then the tether's instantaneous reaction.
//
// Dynamic Inertia is simulated in the handle's frame instead (issue 16 §2). There the
// handle's motion reaches the mass only as the frame's force −M·a, a the engine's
// estimated acceleration, held over the tick; the same two steps then run with the handle
// standing still at 0 (the law's gravity term carries −a, the exact step stays exact).
// Why: the tension of a tether as stiff as Inertia's is k·stretch + b·rate, and driven by
// the sensed handle it moves by k·(one count) whenever a count is crossed (110 force units
// on the joystick, a quarter of the inertial force of a brisk 1 Hz sine) and by b times
// the velocity estimate's tick-to-tick wander; the review measured 83–97% error. The
// acceleration estimate is a fit over many samples, and the tether filters it once more,
// so the force is −M·a within 16% and jitters by under 4% of it (docs/dynamics.md has the
// figures).
//
// With play the frame is the same and so is the state: the stretch is the mass's offset
// from the handle, free within ±Play, and the law's regions are the gap (slack: the mass
// coasts under the frame's force −M·a alone) and its two sides (the tether's spring and damper). While
// the handle accelerates one way the mass rests against one side and the handle feels −M·a
// as without play; when the acceleration changes sign the mass leaves that side, crosses
// the gap with no force at all and lands on the other side with the impact of its closing
// speed. The mass does not need the handle's absolute position for this, only its offset,
// which the pseudo-force moves exactly as the handle's motion does (s̈ = ẍ_mass − a). What
// the estimate cannot give is an exact integral: a velocity step that the acceleration fit
// rounds off leaves the mass a small relative drift, which the sides of the gap bound
// (docs/dynamics.md, "Inertia with play").
//
// Per tick each axis costs a few float multiply-adds per piece (tether_tick.hpp): the law
// and its propagators are worked out when a command sets the parameters or the tick length
// changes, and only a piece in which the stretch may cross an edge of the law is redone by
// the exact closed form (float too).
//
// State lives in ControlLawState (in the effect's slot); nothing is allocated, no clock
// is read, nothing throws.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "dynamics/dynamic.hpp"
#include "dynamics/tether_law.hpp"
#include "dynamics/tether_piece.hpp"
#include "dynamics/tether_tick.hpp"

namespace feel::detail {

namespace {

// The mass where the law starts it: pos_init and vel_init relative to the handle, whose
// velocity is handle_velocity (0 in the handle's frame).
TetherAxisState initial_state(const PreparedTether& law, float handle_velocity, float hysteresis) noexcept {
    TetherAxisState s;
    s.stretch = law.pos_init;
    s.velocity = handle_velocity + law.vel_init;
    s.side = stretch_side(exact_law(law, law.gravity), law.pos_init, hysteresis);
    return s;
}

bool finite(const TetherAxisState& s) noexcept { return std::isfinite(s.stretch) && std::isfinite(s.velocity); }

// A stretch or velocity below float's normal range (FLT_MIN, 1.2e-38 position units or
// units/s) becomes exactly 0, as on an FPU in flush-to-zero mode. A mass settling against
// a still handle decays exponentially: without this it spends seconds in subnormal numbers,
// each operation on which takes a microcode assist of about a hundred cycles on x86 (the
// 64-effect tick at rest took twice as long), and a mass coasting in its play never
// reaches the exact rest that tether_tick skips.
void flush_subnormal(TetherAxisState& s) noexcept {
    constexpr float kSmallest = std::numeric_limits<float>::min();
    if (std::fabs(s.stretch) < kSmallest) s.stretch = 0;
    if (std::fabs(s.velocity) < kSmallest) s.velocity = 0;
}

// The gravity of the law as seen in the frame of a handle accelerating at `acceleration`:
// the frame adds the force −M·a on the mass, which the law's gravity term carries.
float gravity_in_frame(const PreparedTether& law, float acceleration) noexcept {
    return law.handle_frame ? law.gravity - acceleration : law.gravity;
}

// The prediction of one tick and the catch-up of the next advance the same state (the
// catch-up starts where the prediction started) for the same step (unless the tick length
// or the laws change), under the same gravity (in the handle's frame, the same −M·a: the
// acceleration the prediction read is the one kept for the catch-up) with the same damper
// reading (the velocity estimate the prediction read, kept likewise). They differ only in
// the handle's line when it moves: the prediction follows the last sensed line, the catch-up
// the next. When that line is the same too (always in the handle's frame, where the handle
// stands still at 0; in the fixed frame a handle at rest, or crossing counts at a steady
// rate), the catch-up is the same operations on the same inputs as the prediction, so it
// takes the state the prediction ended in, bit for bit, instead of redoing it. Only for a
// law with regions to track, whose prediction advances a copy of the state
// (predicted_impulse) by advance_watched_tether, as its catch-up does, and which counts no
// half cycles (whose count the state would then have to keep too). A build for size (the
// Cortex-M4F image, whose flash and RAM are the tighter budgets) advances twice: the same
// bits.
#if defined(__OPTIMIZE_SIZE__)
constexpr bool kKeepAhead = false;
#else
constexpr bool kKeepAhead = true;
#endif
bool keeps_ahead(const PreparedTether& law, float handle_acceleration) noexcept {
    return kKeepAhead && law.piecewise && law.half_cycles == 0 && std::isfinite(handle_acceleration);
}

// The prediction's impulse (predicted_impulse's, for a law that keeps_ahead), keeping where
// it ends and the line it followed for the next catch-up.
float predict_and_keep(DynamicState& d, int axis, const PreparedTether& law, float gravity, HandleLine line,
                       float hysteresis) noexcept {
    TetherAxisState ahead = d.law.now[axis];
    const float impulse = advance_watched_tether(law, gravity, ahead, line, hysteresis);
#if !defined(__OPTIMIZE_SIZE__)
    d.law.ahead_stretch[axis] = ahead.stretch;
    d.law.ahead_velocity[axis] = ahead.velocity;
    d.law.ahead_line[axis] = line.velocity;
#endif
    return impulse;
}

// Catches `now` up by the state the last prediction kept when it followed this line;
// returns whether it did.
bool take_kept_ahead(const DynamicState& d, int axis, float line_velocity, TetherAxisState& now) noexcept {
#if defined(__OPTIMIZE_SIZE__)
    (void)d, (void)axis, (void)line_velocity, (void)now;
    return false;
#else
    if (((d.kept_ahead >> axis) & 1u) == 0 ||
        std::bit_cast<uint32_t>(line_velocity) != std::bit_cast<uint32_t>(d.law.ahead_line[axis])) {
        return false;
    }
    now.stretch = d.law.ahead_stretch[axis];
    now.velocity = d.law.ahead_velocity[axis];
    return true;
#endif
}

#if !defined(__OPTIMIZE_SIZE__)
// One axis of a plain law (PreparedTether::plain: one region, nothing counted, the fixed
// frame) on a tick that catches up: the general loop below with every branch it does not
// take removed, the same operations in the same order, so the same bits. The handle's line
// since the last tick serves the catch-up and the prediction alike; most laws are plain
// (recoil, impact, liquid, center drift), and the general loop's bookkeeping cost them
// twice what their two propagators do.
//
// The handle's line since the last tick, which the catch-up and the prediction share: its
// velocity u, and the forces on a mass moving with it apart from the spring's and the
// damper's (the weight less the drag's share).
struct PlainLine {
    float u;
    float moving_force;
};
[[gnu::always_inline]] inline PlainLine plain_line(const PreparedTether& law, float last_position, float handle,
                                                   float inverse_step) noexcept {
    const float u = (handle - last_position) * inverse_step;
    return {u, law.weight - law.drag * u};
}

// A mass at rest on a still handle with nothing pulling it: both propagators map (0, 0) to
// (0, 0) exactly and the impulse is 0 (a settled recoil, liquid or drift at rest:
// flush_subnormal brings a settling mass to exactly 0). The handle is where it was.
[[gnu::always_inline]] inline bool plain_at_rest(const PreparedTether& law, const TetherAxisState& now, float u,
                                                 float last_velocity, float handle_velocity) noexcept {
    return now.stretch == 0 && now.velocity == 0 && u == 0 && last_velocity == 0 && handle_velocity == 0 &&
           law.weight == 0;
}

// The catch-up along the sensed line, its damper reading last tick's estimate: false, with
// `now` untouched, when the caught-up state is not finite (never expected: the caller then
// starts the mass afresh, plain_tick_afresh).
[[gnu::always_inline]] inline bool plain_catch_up(const PreparedTether& law, TetherAxisState& now, PlainLine line,
                                                  float last_velocity) noexcept {
    TetherAxisState caught = now;
    float rate = now.velocity - line.u;
    propagate(law.above, line.moving_force - law.b * (line.u - last_velocity), caught.stretch, rate);
    caught.velocity = rate + line.u;
    flush_subnormal(caught);
    if (!finite(caught)) return false;
    now.stretch = caught.stretch;
    now.velocity = caught.velocity;
    return true;
}

// The prediction from the caught-up `now` along the same line, its damper reading this
// tick's estimate: only the impulse is kept, M·Δv − M·g·h + d·(Δs + u·h), and M·Δv + d·Δs
// is a linear form of the caught-up state whose coefficients were prepared with the
// propagator (weighted_change): the predicted state is not needed. Returns the pull on the
// handle, predicted_impulse's sum in its order (a build for size takes that path).
[[gnu::always_inline]] inline float plain_predict(const PreparedTether& law, const TetherAxisState& now, PlainLine line,
                                                  float handle_velocity, float inverse_step) noexcept {
    const float change = weighted_change(law.prediction_form, line.moving_force - law.b * (line.u - handle_velocity),
                                         now.stretch, now.velocity - line.u);
    return -(change - law.weight_impulse + law.drag * (line.u * law.step_s)) * inverse_step;
}

// Axes i.. of a plain effect on a tick that catches up, the first of them started afresh
// when `afresh`; returns the axis whose caught-up state was not finite (left for
// plain_tick_afresh), or the axis count.
[[gnu::always_inline]] inline int plain_axes(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result,
                                             int i, bool afresh) noexcept {
    const SlotParams& p = *c.params;
    ControlLawState& st = c.state->law;
    const float inverse_step = c.state->inverse_step;
    for (; i < p.axis_count; ++i) {
        const int a = axis_index(p.axes[i]);
        const PreparedTether& law = st.laws[i];
        TetherAxisState& now = st.now[i];
        const float handle = c.position[a];
        const float handle_velocity = c.velocity[a];
        const PlainLine line = plain_line(law, st.handle_position[i], handle, inverse_step);
        float pull = 0;
        if (afresh || !plain_at_rest(law, now, line.u, st.handle_velocity[i], handle_velocity)) {
            if (afresh) {
                now = initial_state(law, handle_velocity, c.config->sensor_step);
                afresh = false;
            } else if (!plain_catch_up(law, now, line, st.handle_velocity[i])) {
                return i;
            }
            pull = plain_predict(law, now, line, handle_velocity, inverse_step);
            st.handle_position[i] = handle;
            st.handle_velocity[i] = handle_velocity;
        }
        force[a] += std::isfinite(pull) ? pull : 0.0f;
        // The acceleration is read only in the handle's frame: a plain law keeps none.
        result.mass_position[a] = now.stretch;
        result.mass_velocity[a] = now.velocity - handle_velocity;
    }
    return i;
}

// The rest of plain_tick from axis i on, whose caught-up state was not finite: it starts
// afresh (initial_state). Never expected; out of the loop's way, whose registers it would
// otherwise have the loop save on every call.
[[gnu::noinline, gnu::cold]] void plain_tick_afresh(const DynamicContext& c, float force[kMaxAxes],
                                                    DynamicResult& result, int i) noexcept {
    while (i < c.params->axis_count) i = plain_axes(c, force, result, i, true);
}

// A tick of an effect whose laws are all plain, once it catches up at the step they are
// prepared for: its own loop, so that none of the general tick's state is kept alive
// across it, and with no call on its way (no registers to save).
[[gnu::noinline]] void plain_tick(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept {
    const int i = plain_axes(c, force, result, 0, false);
    if (i < c.params->axis_count) [[unlikely]] plain_tick_afresh(c, force, result, i);
}

// Whether a law's every tick is one watched piece (advance_one_watched_piece): regions
// to track, one piece a step, nothing counted.
bool one_watched_piece(const PreparedTether& law) noexcept {
    return law.piecewise && law.pieces == 1 && law.half_cycles == 0;
}

// Advances `state` as advance_watched_tether does, its common piece inline.
[[gnu::always_inline]] inline float advance_watched(const PreparedTether& law, float gravity, TetherAxisState& state,
                                                    HandleLine line, float hysteresis) noexcept {
    float impulse;
    if (advance_one_watched_piece(law, gravity, state, line, impulse)) return impulse;
    return advance_watched_tether(law, gravity, state, line, hysteresis);
}

// A tick of an effect whose laws are all watched in one piece (ControlLawState::watched:
// the control law with play, Dynamic Inertia), once it catches up at the step they are
// prepared for, the acceleration estimated: control_law_tick's catch-up and prediction
// with every branch they do not take removed and the piece inline, the same operations
// in the same order, so the same bits. Such a law always keeps its prediction's end
// (keeps_ahead) for a finite acceleration. One axis at a time: the general tick's two
// loops served its calls, here the axes' chains overlap without them.
[[gnu::noinline, gnu::flatten]] void watched_tick(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept {
    const SlotParams& p = *c.params;
    DynamicState& d = *c.state;
    ControlLawState& st = d.law;
    const float inverse_step = d.inverse_step;
    const float hysteresis = c.config->sensor_step;
    for (int i = 0; i < p.axis_count; ++i) {
        const PreparedTether& law = st.laws[i];
        const int a = axis_index(p.axes[i]);
        const float handle = c.position[a];
        const float handle_velocity = c.velocity[a];
        const float handle_acceleration = c.acceleration[a];
        const float frame_velocity = law.handle_frame ? 0.0f : handle_velocity;
        // The sensed line, which the prediction's heading is too (the handle's frame: still).
        const float line_velocity = law.handle_frame ? 0.0f : (handle - st.handle_position[i]) * inverse_step;
        TetherAxisState& now = st.now[i];
        if (!take_kept_ahead(d, i, line_velocity, now)) {
            const HandleLine sensed = law.handle_frame ? HandleLine{} : HandleLine{line_velocity, st.handle_velocity[i]};
            advance_watched(law, gravity_in_frame(law, st.handle_acceleration[i]), now, sensed, hysteresis);
        }
        flush_subnormal(now);
        if (!finite(now)) [[unlikely]] now = initial_state(law, frame_velocity, hysteresis);  // never expected
        st.handle_position[i] = handle;
        st.handle_velocity[i] = handle_velocity;
        st.handle_acceleration[i] = std::isfinite(handle_acceleration) ? handle_acceleration : 0.0f;
        result.mass_position[a] = now.stretch;
        result.mass_velocity[a] = now.velocity - frame_velocity;
        const HandleLine expected = law.handle_frame ? HandleLine{} : HandleLine{line_velocity, handle_velocity};
        // The prediction's copy field by field: copied whole, the 13 bytes went through the
        // stack as two overlapping 8-byte moves, whose load waited for both stores.
        TetherAxisState ahead;
        ahead.stretch = now.stretch;
        ahead.velocity = now.velocity;
        ahead.half_cycles = now.half_cycles;
        ahead.side = now.side;
        const float impulse =
            advance_watched(law, gravity_in_frame(law, handle_acceleration), ahead, expected, hysteresis);
        const bool keep = std::isfinite(handle_acceleration);
        if (keep) {
            st.ahead_stretch[i] = ahead.stretch;
            st.ahead_velocity[i] = ahead.velocity;
            st.ahead_line[i] = expected.velocity;
        }
        const float pull = -impulse * inverse_step;
        force[a] += std::isfinite(pull) ? pull : 0.0f;
        const auto bit = static_cast<uint8_t>(1u << i);
        d.kept_ahead = keep ? (d.kept_ahead | bit) : (d.kept_ahead & static_cast<uint8_t>(~bit));
    }
}
#endif

// Every tick of a control-law dynamic but a plain one's ordinary tick (control_law_dynamic):
// the laws prepared when a command or the tick length asks, the first tick, and every tick
// of a law with regions to track.
[[gnu::noinline]] void control_law_tick(const DynamicContext& c, float force[kMaxAxes],
                                        DynamicResult& result) noexcept {
    const SlotParams& p = *c.params;
    ControlLawState& st = c.state->law;
    const int32_t n = p.axis_count;
    if (!c.state->prepared) {
        TetherLaw laws[kMaxAxes];
        tether_laws(p, *c.config, laws);
        c.state->plain = true;
        for (int i = 0; i < n; ++i) {
            st.laws[i] = prepare_tether(laws[i]);
            c.state->plain = c.state->plain && st.laws[i].plain;
        }
        c.state->prepared = true;
        if (kKeepAhead) c.state->kept_ahead = 0;  // predicted by the old laws
#if !defined(__OPTIMIZE_SIZE__)
        st.watched = false;  // until the pieces are prepared
#endif
    }
    // A half cycle counts once the stretch swings a sensor count past its rest value: the
    // sensor's flicker around a mass at rest never counts.
    const float hysteresis = c.config->sensor_step;
    // The catch-up's, and the prediction's: the next tick as long. The laws are float (their
    // time too: a tick of at most seconds, to 6e-8 of itself; the engine's clock is integer µs).
    const float step = c.dt_s;
    // The axes' pieces are prepared together, here, and unprepared together (prepare_tether,
    // above), so the first axis's step is every axis's: one test a tick, not one an axis
    // (without axes the first law is never read).
    if (step > 0 && st.laws[0].step_s != step) {
        for (int i = 0; i < n; ++i) {
            prepare_pieces(st.laws[i], step);
            if (kKeepAhead) c.state->kept_ahead &= static_cast<uint8_t>(~(1u << i));  // predicted over another step
        }
        c.state->inverse_step = 1.0f / step;
#if !defined(__OPTIMIZE_SIZE__)
        st.watched = true;
        for (int i = 0; i < n; ++i) st.watched = st.watched && one_watched_piece(st.laws[i]);
#endif
    }

    const bool fresh = !c.state->initialized || !(step > 0);
    const bool catch_up = c.state->initialized && step > 0;
    const float inverse_step = step > 0 ? c.state->inverse_step : 0.0f;
#if !defined(__OPTIMIZE_SIZE__)
    // Not in a build for size (the Cortex-M4F image, whose flash is the tighter budget): the
    // general loop below does the same operations.
    if (catch_up && c.state->plain) {
        plain_tick(c, force, result);
        return;
    }
#endif
    // Each axis is a mass of its own: every axis is caught up, then every axis predicted.
    // An axis's catch-up and prediction are one chain of dependent operations (the
    // prediction starts where the catch-up ends), the axes' chains are independent: in this
    // order the processor runs the second axis's catch-up beside the first's, where one
    // axis at a time left it waiting for each call's result. Each axis's operations are
    // the same, in the same order. A build for size keeps one loop (the same bits).
    const auto catch_up_axis = [&](int i) {
        const PreparedTether& law = st.laws[i];
        const int a = axis_index(p.axes[i]);
        const float handle = c.position[a];
        const float handle_velocity = c.velocity[a];
        // The velocity the mass's own is seen from: the handle's, unless simulated in its frame.
        const float frame_velocity = law.handle_frame ? 0.0f : handle_velocity;
        TetherAxisState& now = st.now[i];
        if (!c.state->initialized) {
            now = initial_state(law, frame_velocity, hysteresis);
        } else if (catch_up) {
            const HandleLine sensed = law.handle_frame ? HandleLine{}
                                                       : HandleLine{(handle - st.handle_position[i]) * inverse_step,
                                                                    st.handle_velocity[i]};
            if (!take_kept_ahead(*c.state, i, sensed.velocity, now)) {
                advance_prepared_tether(law, gravity_in_frame(law, st.handle_acceleration[i]), now, sensed,
                                        hysteresis);
            }
        }
        flush_subnormal(now);
        if (!finite(now)) now = initial_state(law, frame_velocity, hysteresis);  // never expected
        if (law.half_cycles > 0 && now.half_cycles >= law.half_cycles) result.finished = true;
    };
    const auto predict_axis = [&](int i) {
        const PreparedTether& law = st.laws[i];
        const int a = axis_index(p.axes[i]);
        const float handle = c.position[a];
        const float handle_velocity = c.velocity[a];
        const float handle_acceleration = c.acceleration != nullptr ? c.acceleration[a] : 0.0f;
        const float frame_velocity = law.handle_frame ? 0.0f : handle_velocity;
        const TetherAxisState& now = st.now[i];
        // The handle is expected to go on along the line through its last two sensed
        // positions; before there are two, at its estimated velocity.
        const float heading = fresh ? handle_velocity : (handle - st.handle_position[i]) * inverse_step;
        // The handle kept for the next tick and the mass reported before the prediction's
        // call, which reads neither: none of their values is then held across it.
        st.handle_position[i] = handle;
        st.handle_velocity[i] = handle_velocity;
        st.handle_acceleration[i] = std::isfinite(handle_acceleration) ? handle_acceleration : 0.0f;
        result.mass_position[a] = now.stretch;
        result.mass_velocity[a] = now.velocity - frame_velocity;
        float pull = 0;
        bool keep = false;
        if (step > 0) {
            const HandleLine expected = law.handle_frame ? HandleLine{} : HandleLine{heading, handle_velocity};
            const float gravity = gravity_in_frame(law, handle_acceleration);
            keep = keeps_ahead(law, handle_acceleration);
            pull = -(keep ? predict_and_keep(*c.state, i, law, gravity, expected, hysteresis)
                          : predicted_impulse(law, gravity, now, expected, hysteresis)) *
                   inverse_step;
        } else {
            pull = tether_reaction(exact_law(law, law.gravity), now.stretch, now.velocity - frame_velocity);
        }
        force[a] += std::isfinite(pull) ? pull : 0.0f;
        if (kKeepAhead) {
            const auto bit = static_cast<uint8_t>(1u << i);
            c.state->kept_ahead = keep ? (c.state->kept_ahead | bit) : (c.state->kept_ahead & static_cast<uint8_t>(~bit));
        }
    };
#if defined(__OPTIMIZE_SIZE__)
    for (int i = 0; i < n; ++i) {
        catch_up_axis(i);
        predict_axis(i);
    }
#else
    for (int i = 0; i < n; ++i) catch_up_axis(i);
    for (int i = 0; i < n; ++i) predict_axis(i);
#endif
    c.state->initialized = true;
}

}  // namespace

void control_law_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept {
#if !defined(__OPTIMIZE_SIZE__)
    // Most ticks of most effects are a plain law's (recoil, impact, liquid, center drift)
    // that catches up at the step its laws are prepared for: straight to its loop, before
    // the general tick saves a register or reads its state.
    // The watched laws likewise (a control law with play, Dynamic Inertia), with the
    // acceleration estimated (always, in the engine).
    const DynamicState& d = *c.state;
    if (d.prepared && d.initialized && c.dt_s > 0 && d.law.laws[0].step_s == c.dt_s) {
        if (d.plain) {
            plain_tick(c, force, result);
            return;
        }
        if (d.law.watched && c.acceleration != nullptr) {
            watched_tick(c, force, result);
            return;
        }
    }
#endif
    control_law_tick(c, force, result);
}

}  // namespace feel::detail
