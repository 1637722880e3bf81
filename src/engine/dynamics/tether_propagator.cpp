// The float propagator of a spring-damper piece (tether_propagator.hpp says why it is
// shaped this way).
#include "dynamics/tether_propagator.hpp"

#include <cmath>

namespace feel::detail {

namespace {

// Below this E = e^{−c·h/2m} the oscillation is gone within the piece and the plain matrix
// (entries of order E) is as good; M = Φ/E would only lose range.
constexpr double kMinShearDecay = 1e-12;

}  // namespace

TetherPropagator tether_propagator(const SpringDamper& s, double h) noexcept {
    SpringDamper unforced = s;
    unforced.force = 0;
    const MassState from_position = tether_step(unforced, {1, 0}, h);  // first column of Φ
    const MassState from_velocity = tether_step(unforced, {0, 1}, h);  // second column
    SpringDamper unit = s;
    unit.force = 1;
    const MassState forced = tether_step(unit, {0, 0}, h);  // Γ

    TetherPropagator p;
    p.force_y = static_cast<float>(forced.position);
    p.force_v = static_cast<float>(forced.velocity);
    const double m11 = from_position.position, m21 = from_position.velocity;
    const double m12 = from_velocity.position, m22 = from_velocity.velocity;
    const double gamma = s.damping / (2 * s.mass);
    const double w2 = s.stiffness / s.mass;
    const double decay = std::exp(-gamma * h);
    const bool oscillating = w2 > gamma * gamma && m21 != 0;
    if (oscillating && decay > kMinShearDecay) {
        const double w = m21 / decay;
        const double x = (m11 / decay - 1) / w;
        const double z = (m22 / decay - 1) / w;
        p.sheared = true;
        p.c0 = static_cast<float>(x);
        p.c1 = static_cast<float>(w);
        p.c2 = static_cast<float>(z);
        p.lo0 = static_cast<float>(x - p.c0);
        p.lo1 = static_cast<float>(w - p.c1);
        p.lo2 = static_cast<float>(z - p.c2);
        p.c3 = static_cast<float>(-std::expm1(-gamma * h));  // 1 − E, to its own precision
        return p;
    }
    p.c0 = static_cast<float>(m11);
    p.c1 = static_cast<float>(m12);
    p.c2 = static_cast<float>(m21);
    p.c3 = static_cast<float>(m22);
    return p;
}

}  // namespace feel::detail
