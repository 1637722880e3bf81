// Evaluating a target motion: where the hand wants the handle at time t, and how fast
// that point moves. The velocity is the exact derivative of the position (piecewise for
// ramps and csv tables), so a kinematic hand moves the handle consistently.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "feel/sim/hand.hpp"
#include "feel/units.hpp"

namespace feel::sim {

TargetMotion TargetMotion::hold_at(std::initializer_list<double> positions) {
    if (positions.size() < 1 || positions.size() > static_cast<size_t>(kMaxAxes)) {
        throw std::invalid_argument("hold_at: " + std::to_string(positions.size()) +
                                    " positions given (allowed 1.." +
                                    std::to_string(kMaxAxes) + ", one per axis)");
    }
    TargetMotion m;
    m.kind_ = Kind::hold;
    m.spec_ = "hold:";
    int i = 0;
    for (double p : positions) {
        if (!std::isfinite(p) || std::fabs(p) > kFullScale) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.10g", p);
            throw std::invalid_argument("hold_at: position " + std::to_string(i) + " = " + buf +
                                        " is outside the travel (allowed -10000..10000)");
        }
        char buf[64];
        std::snprintf(buf, sizeof buf, "%s%.17g", i == 0 ? "" : ",", p);
        m.spec_ += buf;
        m.hold_[i++] = p;
    }
    m.used_axes_ = i;
    return m;
}

TargetMotion::Sample TargetMotion::at(double t_s) const noexcept {
    Sample s;
    constexpr double kTwoPi = 2 * std::numbers::pi;
    switch (kind_) {
    case Kind::hold:
        std::copy(std::begin(hold_), std::end(hold_), std::begin(s.position));
        break;
    case Kind::ramp:  // a_ = FROM, b_ = TO over [0, duration_s_]
        if (t_s <= 0) {
            s.position[axis_] = a_;
        } else if (t_s >= duration_s_) {
            s.position[axis_] = b_;
        } else {
            s.position[axis_] = a_ + (b_ - a_) * (t_s / duration_s_);
            s.velocity[axis_] = (b_ - a_) / duration_s_;
        }
        break;
    case Kind::sine: {  // a_ = AMPLITUDE, b_ = HZ
        const double w = kTwoPi * b_;
        s.position[axis_] = a_ * std::sin(w * t_s);
        s.velocity[axis_] = a_ * w * std::cos(w * t_s);
        break;
    }
    case Kind::circle: {  // a_ = RADIUS, b_ = HZ
        const double w = kTwoPi * b_;
        const double c = std::cos(w * t_s);
        const double sn = std::sin(w * t_s);
        s.position[0] = a_ * c;
        s.position[1] = a_ * sn;
        s.velocity[0] = -a_ * w * sn;
        s.velocity[1] = a_ * w * c;
        break;
    }
    case Kind::table: {
        const size_t rows = table_t_.size();
        const size_t cols = static_cast<size_t>(table_axes_);
        // First row later than t: rows before it are behind, the segment ends at it.
        const size_t i = static_cast<size_t>(
            std::upper_bound(table_t_.begin(), table_t_.end(), t_s) - table_t_.begin());
        if (i == 0 || i == rows) {  // before the first row or after the last: held
            const size_t r = i == 0 ? 0 : rows - 1;
            for (size_t a = 0; a < cols; ++a) s.position[a] = table_x_[r * cols + a];
            break;
        }
        const double t0 = table_t_[i - 1];
        const double span = table_t_[i] - t0;
        const double f = (t_s - t0) / span;
        for (size_t a = 0; a < cols; ++a) {
            const double x0 = table_x_[(i - 1) * cols + a];
            const double x1 = table_x_[i * cols + a];
            s.position[a] = x0 + (x1 - x0) * f;
            s.velocity[a] = (x1 - x0) / span;
        }
        break;
    }
    }
    return s;
}

}  // namespace feel::sim
