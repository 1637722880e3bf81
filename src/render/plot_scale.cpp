// Nice tick steps: the classic "1, 2, 2.5, 5 times a power of ten" choice, which keeps
// tick labels short and easy to read at a glance.
#include "plot_scale.hpp"

#include <cmath>
#include <cstdio>

namespace feel::render::detail {

double nice_step(double span, int target) noexcept {
    if (!(span > 0) || target < 1) return 1;
    const double raw = span / target;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    const double fraction = raw / power;  // 1 <= fraction < 10
    double nice = 10;
    if (fraction <= 1) nice = 1;
    else if (fraction <= 2) nice = 2;
    else if (fraction <= 2.5) nice = 2.5;
    else if (fraction <= 5) nice = 5;
    return nice * power;
}

std::vector<double> Scale::ticks() const {
    std::vector<double> out;
    if (!(step > 0)) return out;
    // Tolerance so that a tick that lands on an end by arithmetic is not lost to rounding.
    const double eps = step * 1e-9;
    const double first = std::ceil((lo - eps) / step);
    for (double k = first;; k += 1) {
        const double v = k * step;
        if (v > hi + eps || out.size() > 1000) break;
        out.push_back(std::fabs(v) < eps ? 0.0 : v);
    }
    return out;
}

Scale nice_scale(double lo, double hi, int target) noexcept {
    if (!(hi > lo)) {
        const double half = lo == 0 ? 1 : std::fabs(lo) * 0.5;
        lo -= half;
        hi += half;
    }
    Scale s;
    s.step = nice_step(hi - lo, target);
    s.lo = std::floor(lo / s.step) * s.step;
    s.hi = std::ceil(hi / s.step) * s.step;
    return s;
}

Scale nice_scale(double lo, double hi, int min_target, int max_target) noexcept {
    Scale best = nice_scale(lo, hi, min_target);
    for (int target = min_target + 1; target <= max_target; ++target) {
        const Scale s = nice_scale(lo, hi, target);
        if (s.hi - s.lo < (best.hi - best.lo) * (1 - 1e-9)) best = s;
    }
    return best;
}

Scale exact_scale(double lo, double hi, int target) noexcept {
    if (!(hi > lo)) hi = lo + 1;
    Scale s;
    s.lo = lo;
    s.hi = hi;
    s.step = nice_step(hi - lo, target);
    return s;
}

std::string tick_label(double value, double step) {
    int decimals = 0;
    // Enough decimals that step is a whole number of the last digit (2.5 needs one).
    while (decimals < 6) {
        const double scaled = step * std::pow(10.0, decimals);
        if (std::fabs(scaled - std::round(scaled)) < 1e-6 * scaled) break;
        ++decimals;
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, std::fabs(value));
    const bool negative = value < 0 && std::fabs(value) >= 0.5 * step * 1e-6;
    return negative ? "\u2212" + std::string(buf) : std::string(buf);
}

}  // namespace feel::render::detail
