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
// Dynamic Inertia without play is simulated in the handle's frame instead (issue 16 §2).
// There the handle's motion reaches the mass only as the frame's force −M·a, a the
// engine's estimated acceleration, held over the tick; the same two steps then run with
// the handle standing still at 0 (the law's gravity term carries −a, the exact step stays
// exact). Why: the tension of a tether as stiff as Inertia's is k·stretch + b·rate, and
// driven by the sensed handle it moves by k·(one count) whenever a count is crossed (110
// force units on the joystick, a quarter of the inertial force of a brisk 1 Hz sine) and by
// b times the velocity estimate's tick-to-tick wander; the review measured 83–97% error.
// The acceleration estimate is a fit over many samples, and the tether filters it once
// more, so the force is −M·a within 16% and jitters by under 4% of it (docs/dynamics.md
// has the figures). With play the mass must know where the handle is to rattle within
// it, which double-integrating an estimated acceleration cannot tell, so it keeps the
// sensed-path drive above.
//
// State lives in ControlLawState (in the effect's slot); nothing is allocated, no clock
// is read, nothing throws.
#include <cmath>

#include "dynamics/dynamic.hpp"
#include "dynamics/tether_law.hpp"

namespace feel::detail {

namespace {

// The mass where the law starts it: pos_init and vel_init relative to the handle.
TetherAxisState initial_state(const TetherLaw& law, double handle, double handle_velocity, double hysteresis) noexcept {
    TetherAxisState s;
    s.position = handle + law.pos_init;
    s.velocity = handle_velocity + law.vel_init;
    s.side = stretch_side(law, law.pos_init, hysteresis);
    return s;
}

bool finite(const TetherAxisState& s) noexcept { return std::isfinite(s.position) && std::isfinite(s.velocity); }

// The law as seen in the frame of a handle accelerating at `acceleration`: the frame adds
// the force −M·a on the mass, which the law's gravity term carries.
TetherLaw in_handle_frame(const TetherLaw& law, double acceleration) noexcept {
    TetherLaw framed = law;
    framed.gravity = law.gravity - acceleration;
    return framed;
}

}  // namespace

void control_law_dynamic(const DynamicContext& c, double force[kMaxAxes], DynamicResult& result) noexcept {
    const EffectParams& p = *c.params;
    TetherLaw laws[kMaxAxes];
    const int32_t n = tether_laws(p, *c.config, laws);
    ControlLawState& st = c.state->law;
    // A half cycle counts once the stretch swings a sensor count past its rest value: the
    // sensor's flicker around a mass at rest never counts.
    const double hysteresis = c.config->sensor_step;

    const bool fresh = !c.state->initialized || !(c.dt_s > 0);
    if (!c.state->initialized) {
        for (int i = 0; i < n; ++i) {
            const int a = axis_index(p.axes[i]);
            st.now[i] = laws[i].handle_frame ? initial_state(laws[i], 0.0, 0.0, hysteresis)
                                             : initial_state(laws[i], c.position[a], c.velocity[a], hysteresis);
        }
        c.state->initialized = true;
    } else if (c.dt_s > 0) {
        for (int i = 0; i < n; ++i) {
            const int a = axis_index(p.axes[i]);
            if (laws[i].handle_frame) {
                advance_tether(in_handle_frame(laws[i], st.handle_acceleration[i]), st.now[i], HandlePath{}, c.dt_s,
                               hysteresis);
                continue;
            }
            const HandlePath sensed{st.handle_position[i], (c.position[a] - st.handle_position[i]) / c.dt_s,
                                    st.handle_velocity[i]};
            advance_tether(laws[i], st.now[i], sensed, c.dt_s, hysteresis);
        }
    }

    const double horizon = c.dt_s;  // the next tick is assumed as long as the last
    for (int i = 0; i < n; ++i) {
        const TetherLaw& law = laws[i];
        const int a = axis_index(p.axes[i]);
        const double handle = c.position[a];
        const double handle_velocity = c.velocity[a];
        // The handle is expected to go on along the line through its last two sensed
        // positions; before there are two, at its estimated velocity.
        const double heading = fresh ? handle_velocity : (handle - st.handle_position[i]) / horizon;
        const double handle_acceleration = c.acceleration != nullptr ? c.acceleration[a] : 0.0;
        // Where the mass is seen from: the handle, for a law simulated in its frame.
        const double frame_position = law.handle_frame ? 0.0 : handle;
        const double frame_velocity = law.handle_frame ? 0.0 : handle_velocity;
        TetherAxisState& now = st.now[i];
        if (!finite(now)) now = initial_state(law, frame_position, frame_velocity, hysteresis);  // never expected
        if (law.half_cycles > 0 && now.half_cycles >= law.half_cycles) result.finished = true;

        double pull = 0;
        if (horizon > 0) {
            TetherAxisState ahead = now;
            if (law.handle_frame) {
                pull = -advance_tether(in_handle_frame(law, handle_acceleration), ahead, HandlePath{}, horizon,
                                       hysteresis) / horizon;
            } else {
                const HandlePath expected{handle, heading, handle_velocity};
                pull = -advance_tether(law, ahead, expected, horizon, hysteresis) / horizon;
            }
        } else {
            pull = tether_reaction(law, now.position - frame_position, now.velocity - frame_velocity);
        }
        force[a] += std::isfinite(pull) ? pull : 0.0;
        st.handle_position[i] = handle;
        st.handle_velocity[i] = handle_velocity;
        st.handle_acceleration[i] = std::isfinite(handle_acceleration) ? static_cast<float>(handle_acceleration) : 0.0f;
        result.mass_position[a] = static_cast<float>(now.position - frame_position);
        result.mass_velocity[a] = static_cast<float>(now.velocity - frame_velocity);
    }
}

}  // namespace feel::detail
