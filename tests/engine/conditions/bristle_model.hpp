// The documented friction model (docs/conditions.md, "Friction"), written out for the tests
// from its closed forms: a Dahl bristle z advanced exactly over each monotone step, its
// force -f·z, and the LuGre microdamping faded out with speed.
#pragma once

#include <algorithm>
#include <cmath>

namespace feel::test {

// The joystick profile: b = 0.5 N·s/m · 0.05 m / 4.45 N in normalized units.
inline constexpr double kJoystickDamping = 0.5 * 0.05 / 4.45;
inline constexpr double kJoystickVelocityRef = 1e5;

// Presliding distance Z = f/K, K = 2b/T (the device's passivity bound), at least f/1000
// (force built up within 1000 units), at most 200/(2·sensor_step) (2% of full force per
// count).
inline double presliding(double f, double damping, double dt_s, double step) {
    double k = std::max(2 * damping / dt_s, f / 1000);
    k = std::min(k, 200 / (2 * step));
    return f / k;
}

// z after travelling dx (one monotone stretch) from z0: ±1 + (z0 ∓ 1)·exp(-|dx|/Z).
inline double bristle(double z0, double dx, double Z) {
    if (dx > 0) return 1 + (z0 - 1) * std::exp(-dx / Z);
    if (dx < 0) return -1 + (z0 + 1) * std::exp(dx / Z);
    return z0;
}

// LuGre microdamping: -σ0·τ·ż·exp(-(v/v_d)²), σ0 = stiffness, τ = 2 ms,
// ż = v·(1 - z·sign v), v_d = 10% of velocity_ref.
inline double microdamping(double stiffness, double z, double v, double velocity_ref = kJoystickVelocityRef) {
    if (v == 0) return 0;
    const double rate = v * (1 - z * (v > 0 ? 1 : -1));
    const double r = v / (0.1 * velocity_ref);
    return -stiffness * 0.002 * rate * std::exp(-r * r);
}

}  // namespace feel::test
