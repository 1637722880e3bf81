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
//
//   feel_tick_instructions MIX TICKS --digest [--jitter]
//     runs the same ticks (warm-up included) and prints a 64-bit FNV-1a digest of every
//     output's bits (forces, reported position, velocity, acceleration, mass state) and
//     every report's: two builds that print the same digest rendered the same bits, which
//     is how a pass that claims to be bit for bit is checked. --jitter spreads the ticks'
//     lengths over 900..1100 µs (a fixed sequence), so that the tick-length paths run too.
//
//   feel_tick_instructions MIX TICKS --forces [--jitter]
//     the same ticks, printing every tick's force on each axis (%a, exact): how a pass that
//     moves forces measures its largest difference against another build.
#include <cstdint>
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
    bool digest = false;
    bool print_forces = false;
    uint64_t hash = 1469598103934665603ull;  // FNV-1a's offset basis
};

void mix_bits(uint64_t& hash, const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
}

template <typename T>
void mix_value(uint64_t& hash, const T& value) {
    mix_bits(hash, &value, sizeof value);
}

void mix_output(uint64_t& hash, const TickOutput& out) {
    for (int a = 0; a < kMaxAxes; ++a) {
        mix_value(hash, out.force[a]);
        mix_value(hash, out.reported_position[a]);
        mix_value(hash, out.velocity[a]);
        mix_value(hash, out.acceleration[a]);
        mix_value(hash, out.mass_position[a]);
        mix_value(hash, out.mass_velocity[a]);
    }
    mix_value(hash, out.saturated);
    mix_value(hash, out.has_mass);
    mix_value(hash, out.playing_effects);
}

void mix_report(uint64_t& hash, const DynamicReport& r) {
    mix_value(hash, r.effect);
    mix_value(hash, r.kind);
    mix_value(hash, r.t_us);
    mix_value(hash, r.axis_count);
    for (int a = 0; a < kMaxAxes; ++a) {
        mix_value(hash, r.position[a]);
        mix_value(hash, r.velocity[a]);
        mix_value(hash, r.handle_velocity[a]);
    }
}

[[gnu::noipa]] void run_ticks(Run& run, const std::vector<TickInput>& inputs, size_t begin, size_t end) {
    TickOutput out;
    DynamicReport report;
    float sink = 0;
    for (size_t k = begin; k < end; ++k) {
        if (run.estimator_only) {
            run.estimator.update(inputs[k].t_us, inputs[k].position, 2, run.with_acceleration);
            sink += run.estimator.velocity(0);
            if (run.digest) {
                for (int a = 0; a < 2; ++a) {
                    mix_value(run.hash, run.estimator.velocity(a));
                    mix_value(run.hash, run.estimator.acceleration(a));
                }
            }
        } else {
            run.engine->tick(inputs[k], out);
            while (run.engine->pop_report(report)) {
                sink += report.position[0];
                if (run.digest) mix_report(run.hash, report);
            }
            sink += out.force[0];
            if (run.digest) {  // --forces sets digest too: the measured runs test one flag, as before
                mix_output(run.hash, out);
                if (run.print_forces) {
                    std::printf("%a %a\n", static_cast<double>(out.force[0]), static_cast<double>(out.force[1]));
                }
            }
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
        std::fprintf(stderr, "usage: feel_tick_instructions MIX [TICKS] [--digest | --forces [--jitter]]\n");
        return 2;
    }
    const char* mix = argv[1];
    const int ticks = argc > 2 ? std::atoi(argv[2]) : 2000;
    bool digest = false;
    bool jitter = false;
    bool print_forces = false;
    for (int i = 3; i < argc; ++i) {
        if (std::strcmp(argv[i], "--digest") == 0) {
            digest = true;
        } else if (std::strcmp(argv[i], "--forces") == 0) {
            digest = true;
            print_forces = true;
        } else if (std::strcmp(argv[i], "--jitter") == 0) {
            jitter = true;
        } else {
            std::fprintf(stderr, "unknown option %s (--digest, --forces, --jitter)\n", argv[i]);
            return 2;
        }
    }
    if (jitter && !digest) {
        std::fprintf(stderr, "--jitter is for --digest runs (the instruction counts are taken at 1 kHz)\n");
        return 2;
    }
    if (ticks < 1) {
        std::fprintf(stderr, "TICKS must be >= 1\n");
        return 2;
    }
    const bool moving = std::strcmp(mix, "peer_at_rest") != 0 && std::strcmp(mix, "estimator_at_rest") != 0 &&
                        std::strncmp(mix, "busy_rest_", 10) != 0;
    Run run;
    run.digest = digest;
    run.print_forces = print_forces;
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
    if (jitter) {
        // A fixed sequence of tick lengths in 900..1100 µs (a linear congruential walk).
        uint32_t lcg = 12345;
        int64_t t_us = 0;
        for (TickInput& in : inputs) {
            lcg = lcg * 1664525u + 1013904223u;
            t_us += 900 + static_cast<int64_t>((lcg >> 8) % 201);
            in.t_us = t_us;
        }
    }
    run_ticks(run, inputs, 0, kWarmupTicks);
    measured_ticks(run, inputs, kWarmupTicks, inputs.size());
    if (digest) {
        std::printf("%s%s: %d ticks, digest %016llx\n", mix, jitter ? " (jittered ticks)" : "", ticks,
                    static_cast<unsigned long long>(run.hash));
        return 0;
    }
    std::printf("%s: %d ticks measured\n", mix, ticks);
    return 0;
}
