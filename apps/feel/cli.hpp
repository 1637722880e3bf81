// The feel command line: subcommands as plain functions, so tests can call them directly.
//
// Exit codes (docs/cli.md):
//   0  success
//   1  the work failed: an unreadable or invalid file, a sensation the engine refuses,
//      an output that cannot be written
//   2  the command line is wrong: an unknown flag, a missing or out-of-range option, an
//      unknown device, hand or sensation name
#pragma once

#include <iosfwd>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace feel::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// A mistake on the command line (exit code 2). Anything else thrown is a failure (1),
// except std::invalid_argument from the libraries, which also names a flag (2).
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct RenderArgs {
    std::string file;
    std::string sensation;
    std::string device = "joystick";
    std::string motion = "hold:0";
    std::string hand = "firm";
    std::optional<double> duration_s;  // unset: the sensation's own length
    double rate_hz = 1000;
    std::string output;                // CSV path, "-" for stdout
    std::string plot;                  // empty: no plot
};

struct CheckArgs {
    std::string file;
};

struct CapsArgs {
    std::string device = "joystick";
};

struct BenchLoopArgs {
    double rate_hz = 1000;  // whole Hz, runtime::kMinLoopRateHz..kMaxLoopRateHz
    double seconds = 60;    // 1..3600
};

// Each writes its results to `out` and its diagnostics to `err`, and throws on error.
void run_render(const RenderArgs& args, std::ostream& out, std::ostream& err);
void run_check(const CheckArgs& args, std::ostream& out, std::ostream& err);
void run_devices(std::ostream& out);
// feel caps: a device's capabilities (docs/cli.md, docs/runtime.md).
void run_caps(const CapsArgs& args, std::ostream& out);
// feel bench loop: the real-time loop's period jitter under a busy mix (docs/runtime.md).
void run_bench_loop(const BenchLoopArgs& args, std::ostream& out, std::ostream& err);

// The whole command line: args[0] is the program name. Never throws; returns the exit code.
[[nodiscard]] int run(std::span<const std::string> args, std::ostream& out, std::ostream& err);

}  // namespace feel::cli
