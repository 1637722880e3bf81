// The estimator's general path (motion_estimator.cpp describes both): the history
// gathered and summed in one pass, for uneven older intervals or positions the running
// sums cannot hold. Apart from the common path's file, which it shares the fits with.
#include <cmath>

#include "motion_estimator.hpp"

namespace feel::detail {
namespace {

// Sums of y, u·y and u²·y over samples begin..end-1, added to sum[0..2]: a short segment
// (the short windows' few samples) one by one, a longer one in four partial sums in a fixed
// order (vectorizable and the same on every platform). The line fits do not read Σ u²·y;
// it is summed anyway, on the general path only, for one copy of this code (issue 14's flash).
void add_moments(const float* y, const float* u, int begin, int end, float sum[3]) noexcept {
    if (end - begin < 8) {
        for (int i = begin; i < end; ++i) {
            sum[0] += y[i];
            sum[1] += u[i] * y[i];
            sum[2] += (u[i] * u[i]) * y[i];
        }
        return;
    }
    float a0[4] = {}, a1[4] = {}, a2[4] = {};
    int i = begin;
    for (; i + 4 <= end; i += 4) {
        for (int j = 0; j < 4; ++j) {
            a0[j] += y[i + j];
            a1[j] += u[i + j] * y[i + j];
            a2[j] += (u[i + j] * u[i + j]) * y[i + j];
        }
    }
    for (int j = 0; i < end; ++i, ++j) {
        a0[j] += y[i];
        a1[j] += u[i] * y[i];
        a2[j] += (u[i] * u[i]) * y[i];
    }
    sum[0] += (a0[0] + a0[1]) + (a0[2] + a0[3]);
    sum[1] += (a1[0] + a1[1]) + (a1[2] + a1[3]);
    sum[2] += (a2[0] + a2[1]) + (a2[2] + a2[3]);
}

}  // namespace

void MotionEstimator::gather_axis(int axis, float* y, float (*sums)[kRungs]) const noexcept {
    const TimePattern& p = pattern_;
    const int max_n = p.max_n;
    // The samples newest first, relative to the newest: the ring from head_ to its end,
    // then from its start.
    const float* x = x_[axis];
    const float x0 = x[head_];
    const int first = head_ + max_n < kHistory ? max_n + 1 : kHistory - head_;
    for (int i = 0; i < first; ++i) y[i] = x[head_ + i] - x0;
    for (int i = first; i <= max_n; ++i) y[i] = x[i - first] - x0;
    // The window sums at every rung: one pass, segment by segment.
    float running[3] = {};
    int begin = 0;
    for (int r = 0; r < p.rung_count; ++r) {
        const int end = p.rung_n[r] + 1;
        add_moments(y, p.u, begin, end, running);
        begin = end;
        for (int k = 0; k < 3; ++k) sums[k][r] = running[k];
    }
}

// The general path keeps the gathered samples and sums on its own stack frame, apart from
// the tick's common path (fast_fit_possible), which needs neither.
void MotionEstimator::estimate_general(int axis, bool velocity, bool acceleration) noexcept {
    if (velocity) velocity_rung_[axis] = acceleration_rung_[axis] = kRungs;
    float y[kHistory];
    float sums[3][kRungs];
    gather_axis(axis, y, sums);
    float buffer[kDenseSlots];
    const float* dense = dense_samples(axis, buffer);
    if (velocity) fit(axis, 1, dense, y, sums);
    if (acceleration) fit(axis, 2, dense, y, sums);
}

}  // namespace feel::detail
