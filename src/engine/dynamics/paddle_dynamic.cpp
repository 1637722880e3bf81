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
#include <numbers>

#include "dynamics/ball_tick.hpp"
#include "dynamics/dynamic.hpp"
#include "dynamics/dynamic_units.hpp"
#include "dynamics/paddle_contact.hpp"

namespace feel::detail {

namespace {

constexpr int kX = 0;
constexpr int kY = 1;
constexpr int kPlane[2] = {kX, kY};
constexpr double kCentidegree = std::numbers::pi / 18000.0;

template <typename T>
double along(const double n[2], const T* v) noexcept {
    return n[kX] * v[kX] + n[kY] * v[kY];
}

struct Paddle {
    PaddleContactParams contact{};
    double normal[2] = {};    // n on (x, y): faces the incoming ball
    double impact_speed = 0;  // |V|, position units/s, toward the paddle

    Paddle(const SlotDynamicBlock& d, const EngineConfig& config) noexcept {
        contact.mass = dynamic_mass(config, d.ball_mass);
        contact.stiffness = dynamic_stiffness(config, d.paddle_compliance);
        contact.damping = dynamic_damping(config, d.paddle_damping);
        contact.gravity = dynamic_gravity(config, d.gravity);
        const double speed = dynamic_velocity(config, d.initial_velocity);
        const double angle = d.initial_velocity_direction * kCentidegree;
        const double side = speed < 0 ? -1.0 : 1.0;  // a negative speed comes from the opposite side
        normal[kX] = side * std::sin(angle);
        normal[kY] = side * std::cos(angle);
        impact_speed = std::fabs(speed);
    }

    // The moment of impact: on the surface, at the handle, moving into the paddle.
    void start(BallMotion& ball, const DynamicContext& c) const noexcept {
        for (int a : kPlane) {
            ball.position[a] = c.position[a];
            ball.velocity[a] = -impact_speed * normal[a];
        }
        ball.pressed = false;
        ball.contact_s = 0;
    }

    // Along n the contact, exactly; across n free flight.
    void advance(BallMotion& ball, const BallHandlePath& handle, double h, double impulse[kMaxAxes]) const noexcept {
        const double handle_speed = along(normal, handle.velocity);
        PaddleContactParams law = contact;
        law.damper_offset = handle_speed - along(normal, handle.damper_velocity);
        PaddleContact along_n;
        along_n.y = along(normal, ball.position) - along(normal, handle.from);
        along_n.v = along(normal, ball.velocity) - handle_speed;
        along_n.pressed = ball.pressed;
        along_n.contact_s = ball.contact_s;
        const double push = advance_paddle_contact(along_n, law, h);
        const double normal_position = along_n.y + along(normal, handle.from) + handle_speed * h;
        const double normal_velocity = along_n.v + handle_speed;
        const double drifted_normal = along(normal, ball.position) + along(normal, ball.velocity) * h;
        const double old_normal_velocity = along(normal, ball.velocity);
        for (int a : kPlane) {
            ball.position[a] += ball.velocity[a] * h + normal[a] * (normal_position - drifted_normal);
            ball.velocity[a] += normal[a] * (normal_velocity - old_normal_velocity);
            impulse[a] = push * normal[a];
        }
        ball.pressed = along_n.pressed;
        ball.contact_s = along_n.contact_s;
    }

    // The push on the handle now: the reaction of the contact's push on the ball.
    void reaction(const BallMotion& ball, const DynamicContext& c, double force[kMaxAxes]) const noexcept {
        if (!ball.pressed) return;
        const double push = paddle_contact_force(contact, along(normal, ball.position) - along(normal, c.position),
                                                 along(normal, ball.velocity) - along(normal, c.velocity));
        for (int a : kPlane) force[a] -= push * normal[a];
    }
};

}  // namespace

void paddle_dynamic(const DynamicContext& c, double force[kMaxAxes], DynamicResult& result) noexcept {
    const Paddle paddle(*c.params->dynamic, *c.config);
    ball_tick(paddle, kPlane, 2, c, force);
    const BallMotion& ball = c.state->ball.now;
    report_ball(ball, c, kPlane, 2, result);
    const double leaving = along(paddle.normal, ball.velocity) - along(paddle.normal, c.velocity);
    result.finished = !ball.pressed && leaving > 0;
}

}  // namespace feel::detail
