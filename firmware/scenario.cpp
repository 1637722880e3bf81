#include "scenario.hpp"

#include <cmath>

#include "busy_mix.hpp"

namespace feel::firmware {
namespace {

// A smooth back-and-forth in [-1, 1] of period 1 in p: a triangle eased by a smoothstep,
// so the speed is continuous and the direction reverses at the ends.
double swing(double p) noexcept {
    const double f = p - std::floor(p);
    const double q = f < 0.5 ? 2 * f : 2 - 2 * f;
    return 2 * (q * q * (3 - 2 * q)) - 1;
}

}  // namespace

EngineConfig scenario_config() noexcept {
    EngineConfig c;
    c.axis_count = 2;
    c.max_effects = kScenarioEffects;
    c.max_samples = 1024;
    c.report_capacity = 64;
    return c;
}

bool load_scenario(Engine& engine) noexcept { return bench::load_busy_mix(engine, kScenarioEffects).ok(); }

void scenario_handle(TickInput& in, int64_t n) noexcept {
    constexpr double kStep = 20000.0 / 4096.0;
    // Moves for 2 s, holds still for 0.5 s (the estimator's rest path), moves again.
    const int64_t m = n < 2000 ? n : n < 2500 ? 2000 : n - 500;
    const double t = static_cast<double>(m) * 1e-3;
    const double x = 7000 * swing(t / 1.7) + 300 * swing(t * 9.0);
    const double y = 6000 * swing(t / 1.1 + 0.3);
    in.t_us = n * 1000;
    in.position[0] = static_cast<float>(std::round(x / kStep) * kStep);
    in.position[1] = static_cast<float>(std::round(y / kStep) * kStep);
}

}  // namespace feel::firmware
