// Dynamic Paddle (§5.9): a ball hits the paddle the user holds, compresses it and
// rebounds; the event ends when the ball leaves.
//
// The host starts the effect "when the simulated ball first impacts the simulated paddle"
// (§5.2), so the ball starts on the paddle's surface, at the handle, moving into it.
//
// The paddle is the handle: a flat, frictionless surface through the handle whose normal
// n faces the incoming ball. It moves with the handle in x and y but does not turn (the
// handle senses where it is, not how it is tilted), so n is fixed for the event.
//
// Parameters (§8.4: BallMass → Mass, PaddleCompliance → KPos, PaddleDamping → B,
// InitialVelocity → VelInit; EngineConfig says what 10000 of each is on this device):
//   ball_mass                   m = ball_mass/10000 · dynamic_mass_ref
//   paddle_compliance           k = paddle_compliance/10000 · dynamic_stiffness_ref (the
//                               paddle's stiffness, as §8.4 maps it onto KPos)
//   paddle_damping              b = paddle_damping/10000 · dynamic_damping_ref
//   initial_velocity            V = initial_velocity/10000 · velocity_ref, the ball's
//                               speed at impact in the fixed frame (the game's ball: a paddle
//                               swung into it is hit harder, as with a real paddle)
//   initial_velocity_direction  the compass angle a the ball comes FROM (docs/conventions.md:
//                               directions name where things come from). The ball moves
//                               along −(sin a, cos a)·V; a negative V comes from the other side
//   gravity                     g = gravity/10000 · gravity_ref, position units/s², pulls the
//                               ball toward the paddle along the line it came in on (a ball
//                               dropped on a racquet); negative pulls it away. The Dynamic
//                               Struct has one signed number for it, so the incoming line is
//                               the only direction it can have that means the same for every
//                               impact.
//
// Along n the ball and paddle are the one-sided contact of paddle_contact.hpp, advanced
// exactly. Across n nothing acts (a frictionless surface; gravity is along n), so the ball
// keeps its velocity and the paddle slides under it when the user moves sideways.
//
// A tick (ball_tick.hpp): the ball is caught up to now along the handle's sensed path,
// then predicted one tick ahead with the handle going on the same way; the paddle's push
// on the ball over that tick, as an impulse, gives the mean force the motor holds, −J·n/T. It pushes the
// paddle the way the ball was going, never pulls. The ball relative to the handle goes to
// DynamicResult (the engine's interim reports). When the ball has left, free and moving
// away from the paddle (relative to the handle's estimated velocity), the event is over:
// DynamicResult::finished, and the engine sends the final report with the ball's position
// and velocity relative to the handle. Before it leaves it may rest on the paddle
// indefinitely (gravity toward the paddle, or a ball at rest on it) until the user bats it
// away. A paddle that moves away faster than the ball comes in is never touched: the
// event ends on its first tick.
#include <cmath>

#include "dynamics/ball_tick.hpp"
#include "dynamics/dynamic.hpp"
#include "dynamics/paddle_contact.hpp"
#include "turn_trig.hpp"

namespace feel::detail {

namespace {

constexpr int kX = 0;
constexpr int kY = 1;
constexpr int kPlane[2] = {kX, kY};

float along(const float n[2], const float* v) noexcept { return n[kX] * v[kX] + n[kY] * v[kY]; }

struct Paddle {
    PaddleContactParams contact{};
    float normal[2] = {};    // n on (x, y): faces the incoming ball
    float impact_speed = 0;  // |V|, position units/s, toward the paddle

    Paddle(const SlotDynamicBlock& d, const EngineConfig& config) noexcept {
        contact.mass = ball_scale(d.ball_mass, config.dynamic_mass_ref);
        contact.stiffness = ball_scale(d.paddle_compliance, config.dynamic_stiffness_ref);
        contact.damping = ball_scale(d.paddle_damping, config.dynamic_damping_ref);
        contact.gravity = ball_scale(d.gravity, config.gravity_ref);
        const float speed = ball_scale(d.initial_velocity, config.velocity_ref);
        // The compass angle in turns (0..35999 hundredths of a degree: the validator's range),
        // its sine and cosine in float (turn_trig.hpp: exact at the four cardinal points).
        const float turns = static_cast<float>(d.initial_velocity_direction) / 36000.0f;
        const float side = speed < 0 ? -1.0f : 1.0f;  // a negative speed comes from the opposite side
        normal[kX] = side * sin_turns(turns);
        normal[kY] = side * cos_turns(turns);
        impact_speed = std::fabs(speed);
    }

    // The moment of impact: on the surface, at the handle, moving into the paddle.
    void start(BallMotion& ball, const DynamicContext&) const noexcept {
        for (int a : kPlane) {
            ball.offset[a] = 0;
            ball.velocity[a] = -impact_speed * normal[a];
        }
        ball.pressed = false;
        ball.contact_s = 0;
    }

    // Along n the contact, exactly; across n free flight. The ball's offset is to the
    // handle at the path's start, so its component along n is the contact's y; it ends as
    // the offset to the path's end: across n the ball and the handle each drift at their
    // own velocity, along n the contact says where it is.
    void advance(BallMotion& ball, const BallHandlePath& handle, float h, float impulse[kMaxAxes]) const noexcept {
        const float handle_speed = along(normal, handle.velocity);
        PaddleContactParams law = contact;
        law.damper_offset = handle_speed - along(normal, handle.damper_velocity);
        PaddleContact along_n;
        along_n.y = along(normal, ball.offset);
        along_n.v = along(normal, ball.velocity) - handle_speed;
        along_n.pressed = ball.pressed;
        along_n.contact_s = ball.contact_s;
        const float start_y = along_n.y;
        const float start_v = along_n.v;
        const float drifted_y = start_y + start_v * h;
        // The contact's exact step (paddle_contact.hpp, float as the ball).
        const float push = advance_paddle_contact(along_n, law, h);
        for (int a : kPlane) {
            ball.offset[a] += (ball.velocity[a] - handle.velocity[a]) * h + normal[a] * (along_n.y - drifted_y);
            ball.velocity[a] += normal[a] * (along_n.v - start_v);
            impulse[a] = push * normal[a];
        }
        ball.pressed = along_n.pressed;
        ball.contact_s = along_n.contact_s;
    }

    // The push on the handle now: the reaction of the contact's push on the ball.
    // (ball_tick calls it after ball_expected_path: the offset is to the handle sensed now.)
    void reaction(const BallMotion& ball, const DynamicContext& c, float force[kMaxAxes]) const noexcept {
        if (!ball.pressed) return;
        const float push = paddle_contact_force(contact, along(normal, ball.offset),
                                                along(normal, ball.velocity) - along(normal, c.velocity));
        for (int a : kPlane) force[a] -= push * normal[a];
    }
};

}  // namespace

void paddle_dynamic(const DynamicContext& c, float force[kMaxAxes], DynamicResult& result) noexcept {
    const Paddle paddle(*c.params->dynamic, *c.config);
    ball_tick(paddle, kPlane, 2, c, force);
    const BallMotion& ball = c.state->ball.now;
    report_ball(ball, c, kPlane, 2, result);
    const float leaving = along(paddle.normal, ball.velocity) - along(paddle.normal, c.velocity);
    result.finished = !ball.pressed && leaving > 0;
}

}  // namespace feel::detail
