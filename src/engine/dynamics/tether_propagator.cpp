// The float propagator of a spring-damper piece (tether_propagator.hpp says why it is
// shaped this way).
#include "dynamics/tether_propagator.hpp"

#include <cmath>

#include "float_exp.hpp"

namespace feel::detail {

namespace {

// Below this E = e^{−c·h/2m} the oscillation is gone within the piece and the plain matrix
// (entries of order E) is as good; M = Φ/E would only lose range.
constexpr float kMinShearDecay = 1e-12f;

}  // namespace

TetherPropagator tether_propagator(const SpringDamperF& s, float h) noexcept {
    SpringDamperF unforced = s;
    unforced.force = 0;
    SpringDamperF unit = s;
    unit.force = 1;
    const MassStateF forced = tether_step(unit, {0, 0}, h);  // Γ

    TetherPropagator p;
    p.force_y = forced.position;
    p.force_v = forced.velocity;
    const float gamma = s.damping / (2 * s.mass);
    const float w2 = s.stiffness / s.mass;
    const float delta = w2 - gamma * gamma;
    const float decay = float_exp(-gamma * h);
    if (delta > 0 && decay > kMinShearDecay) {
        const float wd = std::sqrt(delta);
        const float theta = wd * h;
        const float sine = tether_step_impl::sin_of(theta);
        const float cosine = tether_step_impl::cos_of(theta);
        if (sine != 0) {
            // q = ωd·tan(θ/2), from whichever form does not cancel.
            const float half_tan = cosine >= 0 ? sine / (1 + cosine) : (1 - cosine) / sine;
            const float q = wd * half_tan;
            p.sheared = true;
            p.c0 = (q - gamma) / w2;
            p.c1 = -w2 * (sine / wd);
            p.c2 = (q + gamma) / w2;
            p.c3 = -float_expm1(-gamma * h);  // 1 − E, to its own precision
            return p;
        }
    }
    const MassStateF from_position = tether_step(unforced, {1, 0}, h);  // first column of Φ
    const MassStateF from_velocity = tether_step(unforced, {0, 1}, h);  // second column
    p.c0 = from_position.position;
    p.c1 = from_velocity.position;
    p.c2 = from_position.velocity;
    p.c3 = from_velocity.velocity;
    return p;
}

}  // namespace feel::detail
