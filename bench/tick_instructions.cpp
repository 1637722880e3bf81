// Instructions per engine tick, for valgrind's callgrind (issue 14). Times on the shared
// CI machine swing with its load; instruction counts do not, so this is how the README's
// "instructions per tick" figures are taken:
//
//   valgrind --tool=callgrind --toggle-collect='*measured_ticks*'
//            build/bench/feel_tick_instructions peer_moving 2000     (one command line)
//   callgrind_annotate --inclusive=yes callgrind.out.<pid>
//
// and the total divided by the ticks measured (the program prints the divisor). The
// handle's inputs are computed before the measured ticks, so the motion's own sin and cos
// are not counted, and the first 1000 ticks (the estimator's history filling, the
// effects' start) run outside the measured function.
//
//   feel_tick_instructions MIX [TICKS]
//     MIX: peer_moving, peer_at_rest (bench/peer_mix.hpp's 40 effects),
//          busy_64 (bench/busy_mix.hpp's 64 effects of every type, moving),
//          busy_N (its first N effects, 0..64), busy_rest_N (the same with the handle
//          held still where the motion starts), busy_one_I (its effect I alone: the cost
//          of one effect type is busy_one_I minus busy_0, the engine and estimator alone),
//          estimator, estimator_velocity (the estimator alone on the slow circle,
//          with and without the acceleration), estimator_at_rest,
//          friction_32, friction_0 (bench/bench_friction.cpp's 32 two-axis frictions on
//          the joystick's damping and mass, and the same engine with none: friction's
//          cost per effect is their difference over 32),
//          damper_32 (the same with 32 two-axis dampers: what any condition costs)
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "busy_mix.hpp"
#include "condition_mix.hpp"
#include "feel/engine.hpp"
#include "motion_estimator.hpp"
#include "peer_mix.hpp"

namespace {

using namespace feel;

constexpr int kWarmupTicks = 1000;

struct Run {
    std::unique_ptr<Engine> engine;
    detail::MotionEstimator estimator;
    bool estimator_only = false;
    bool with_acceleration = true;
};

[[gnu::noipa]] void run_ticks(Run& run, const std::vector<TickInput>& inputs, size_t begin, size_t end) {
    TickOutput out;
    DynamicReport report;
    float sink = 0;
    for (size_t k = begin; k < end; ++k) {
        if (run.estimator_only) {
            run.estimator.update(inputs[k].t_us, inputs[k].position, 2, run.with_acceleration);
            sink += run.estimator.velocity(0);
        } else {
            run.engine->tick(inputs[k], out);
            while (run.engine->pop_report(report)) sink += report.position[0];
            sink += out.force[0];
        }
    }
    if (sink == 12345.678f) std::puts("");  // keeps the work observable
}

// The function callgrind's --toggle-collect names (noipa: not folded into run_ticks, whose
// warm-up ticks must stay outside the count).
[[gnu::noipa]] void measured_ticks(Run& run, const std::vector<TickInput>& inputs, size_t begin, size_t end) {
    run_ticks(run, inputs, begin, end);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: feel_tick_instructions MIX [TICKS]\n");
        return 2;
    }
    const char* mix = argv[1];
    const int ticks = argc > 2 ? std::atoi(argv[2]) : 2000;
    if (ticks < 1) {
        std::fprintf(stderr, "TICKS must be >= 1\n");
        return 2;
    }
    const bool moving = std::strcmp(mix, "peer_at_rest") != 0 && std::strcmp(mix, "estimator_at_rest") != 0 &&
                        std::strncmp(mix, "busy_rest_", 10) != 0;
    Run run;
    std::vector<TickInput> inputs(static_cast<size_t>(kWarmupTicks + ticks));
    for (size_t k = 0; k < inputs.size(); ++k) {
        const int64_t n = static_cast<int64_t>(k) + 1;
        if (std::strncmp(mix, "busy_", 5) == 0 || std::strncmp(mix, "friction_", 9) == 0 ||
            std::strncmp(mix, "damper_", 7) == 0) {
            bench::move_handle(inputs[k], moving ? n : 0);
            inputs[k].t_us = n * 1000;
        } else {
            bench::move_handle_in_slow_circle(inputs[k], moving ? n : 0);
            inputs[k].t_us = n * 1000;
        }
    }
    if (std::strncmp(mix, "estimator", 9) == 0) {
        run.estimator_only = true;
        run.with_acceleration = std::strcmp(mix, "estimator_velocity") != 0;
        run.estimator.configure(20000.0f / 4096.0f);
    } else if (std::strncmp(mix, "peer_", 5) == 0) {
        run.engine = std::make_unique<Engine>(EngineConfig{});
        if (!bench::load_peer_mix(*run.engine)) return 1;
    } else if (std::strncmp(mix, "friction_", 9) == 0 || std::strncmp(mix, "damper_", 7) == 0) {
        const bool friction = mix[0] == 'f';
        const int count = std::atoi(mix + (friction ? 9 : 7));
        run.engine = std::make_unique<Engine>(bench::joystick_condition_config());
        if (!bench::load_conditions(*run.engine, friction ? EffectType::friction : EffectType::damper, count)) {
            std::fprintf(stderr, "could not create the conditions\n");
            return 1;
        }
    } else if (std::strncmp(mix, "busy_", 5) == 0) {
        run.engine = std::make_unique<Engine>(EngineConfig{});
        const bool one = std::strncmp(mix, "busy_one_", 9) == 0;
        const bool rest = std::strncmp(mix, "busy_rest_", 10) == 0;
        const int n = std::atoi(mix + (one ? 9 : rest ? 10 : 5));
        if (n < 0 || n > 64) {
            std::fprintf(stderr, "busy_N, busy_rest_N and busy_one_I take 0..64\n");
            return 2;
        }
        const bench::BusyMixResult r = one ? bench::load_busy_mix_effect(*run.engine, n)
                                           : bench::load_busy_mix(*run.engine, n);
        if (!r.ok()) {
            std::fprintf(stderr, "effect %d refused: %s\n", r.failed_index, r.error.message().c_str());
            return 1;
        }
    } else {
        std::fprintf(stderr, "unknown MIX %s\n", mix);
        return 2;
    }
    run_ticks(run, inputs, 0, kWarmupTicks);
    measured_ticks(run, inputs, kWarmupTicks, inputs.size());
    std::printf("%s: %d ticks measured\n", mix, ticks);
    return 0;
}
