// Axis scales for plots: "nice" tick steps (1, 2, 2.5, 5 × 10^k) and their labels.
//
// Internal to feel_render; the tests include it to check the tick arithmetic.
#pragma once

#include <string>
#include <vector>

namespace feel::render::detail {

struct Scale {
    double lo = 0;    // the axis range, in data units; lo < hi
    double hi = 1;
    double step = 1;  // distance between ticks
    [[nodiscard]] std::vector<double> ticks() const;  // multiples of step within [lo, hi]
};

// The nice step that gives about `target` intervals over `span` (> 0).
[[nodiscard]] double nice_step(double span, int target) noexcept;

// A scale covering [lo, hi] with about `target` intervals, widened outward to whole steps.
// A degenerate range (lo == hi) is widened around its value first.
[[nodiscard]] Scale nice_scale(double lo, double hi, int target) noexcept;

// The tightest of the nice scales for targets min_target..max_target: the one that wastes
// the least room beyond [lo, hi] (the fewest intervals among equals).
[[nodiscard]] Scale nice_scale(double lo, double hi, int min_target, int max_target) noexcept;

// A scale over exactly [lo, hi] (for time: the data starts and ends where it does), with
// nice ticks inside it.
[[nodiscard]] Scale exact_scale(double lo, double hi, int target) noexcept;

// A tick label with as many decimals as the step needs, and a real minus sign (U+2212).
[[nodiscard]] std::string tick_label(double value, double step);

}  // namespace feel::render::detail
