// The passivity observer and controller of wall and barrier ports (passivity.hpp), driven
// directly with an ideal spring's port readings.
//
// Independent truths used here:
//   * the stored energy of a spring is the integral of its force over the depth;
//   * a spring F = −K·s sampled and held for a tick while the handle moves Δs puts out
//     exactly K·Δs²/2 more than the continuous spring would (the zero-order-hold lag:
//     ∫K·s ds − K·s(n−1)·Δs over the tick), whichever way the handle moves;
//   * over a closed cycle (back to where it started) a passive element cannot give the
//     handle more energy than the handle gave it.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "conditions/passivity.hpp"

namespace feel::detail {
namespace {

constexpr double kStep = 20000.0 / 4096.0;  // the joystick's sensor count
constexpr double kT = 1e-3;                  // tick, s

// An ideal linear spring port: wall at s = 0, solid for s > 0, stiffness k, saturating
// at 10000; the handle moves along `path` one sample per tick.
struct SpringPort {
    double k;
    double force(double s) const { return s > 0 ? -std::min(k * s, 10000.0) : 0.0; }
    double energy(double s) const {  // ∫0..s of −force, written out
        if (s <= 0) return 0;
        const double sat = 10000.0 / k;
        return s <= sat ? 0.5 * k * s * s : 0.5 * k * sat * sat + 10000.0 * (s - sat);
    }
};

struct PortRun {
    std::vector<double> out;       // the force commanded each tick
    double handle_gain = 0;        // Σ F(n−1)·Δs(n): energy the element gave the handle
    double ledger = 0;             // the observer's generated energy at the end
};

PortRun drive(const SpringPort& spring, const std::vector<double>& path, bool control) {
    ContactState state;
    PortRun run;
    for (size_t n = 0; n < path.size(); ++n) {
        // The port is single precision (passivity.hpp): the double readings rounded once.
        PortTick tick;
        tick.coordinate = static_cast<float>(path[n]);
        tick.ideal_energy_change =
            static_cast<float>(n > 0 ? spring.energy(path[n]) - spring.energy(path[n - 1]) : 0.0);
        tick.force = static_cast<float>(spring.force(path[n]));
        tick.stiffness = static_cast<float>(spring.k);
        tick.velocity = static_cast<float>(n > 0 ? (path[n] - path[n - 1]) / kT : 0.0);
        tick.dt_s = static_cast<float>(n > 0 ? kT : 0.0);
        tick.resolution = static_cast<float>(kStep);
        const double f = passive_port_force(state, tick, control);
        if (n > 0) run.handle_gain += run.out.back() * (path[n] - path[n - 1]);
        run.out.push_back(f);
    }
    run.ledger = generated_energy(state);
    return run;
}

std::vector<double> in_and_out(double from, double to, double step) {
    std::vector<double> p;
    for (double s = from; s <= to; s += step) p.push_back(s);
    for (double s = to - step; s >= from; s -= step) p.push_back(s);
    return p;
}

TEST(SaturatedSpring, EnergyIsTheIntegralOfItsForce) {
    for (const double k : {50.0, -30.0, 0.5, 2000.0}) {
        const float kf = static_cast<float>(k);
        for (const double depth : {0.0, 3.0, 100.0, 199.0, 333.0, 1000.0, 30000.0}) {
            // Trapezoid rule on a fine grid; the force is piecewise linear so it is exact
            // up to the one panel containing the saturation kink.
            const int panels = 200000;
            double integral = 0;
            for (int i = 0; i < panels; ++i) {
                const double a = depth * i / panels, b = depth * (i + 1) / panels;
                integral -= 0.5 *
                            (saturated_spring_force(kf, static_cast<float>(a)) +
                             saturated_spring_force(kf, static_cast<float>(b))) *
                            (b - a);
            }
            // Single precision: float's 7 digits of the energy.
            EXPECT_NEAR(saturated_spring_energy(kf, static_cast<float>(depth)), integral,
                        1e-6 * std::fabs(integral) + 1e-6)
                << "k=" << k << " depth=" << depth;
        }
    }
    EXPECT_EQ(saturated_spring_energy(50, -10), 0.0f);
    EXPECT_EQ(saturated_spring_force(50, -10), 0.0f);
    EXPECT_EQ(saturated_spring_force(50, 100), -5000.0f);
    EXPECT_EQ(saturated_spring_force(50, 1000), -10000.0f);
    EXPECT_EQ(saturated_spring_force(-50, 1000), 10000.0f);
}

TEST(SaturatedSpring, AnEnergyChangeKeepsItsDigitsHoweverMuchIsStored) {
    // Deep in a stiff wall the stored energy is ~10^8 and a tick's change a few units:
    // the difference of two float energies would round to multiples of 8. The change is
    // computed as one difference, so its error is float's relative 7 digits of k·depth·Δ
    // (the force times the move), against the double-precision energies written out.
    for (const double k : {50.0, -30.0, 5.0, 2000.0}) {
        const SpringPort spring{std::fabs(k)};
        for (const double from : {-40.0, 0.0, 3.0, 150.0, 199.5, 1999.0, 9000.0, 15000.0}) {
            for (const double move : {-300.0, -7.0, -0.25, 0.0, 0.125, 1.0, 5.0, 250.0}) {
                const double to = from + move;
                const double truth = (k > 0 ? 1 : -1) * (spring.energy(to) - spring.energy(from));
                const double force_times_move = std::min(std::fabs(k) * std::fabs(from) + std::fabs(k) * std::fabs(move),
                                                         10000.0) * std::fabs(move);
                const float change = saturated_spring_energy_change(static_cast<float>(k), static_cast<float>(from),
                                                                    static_cast<float>(to));
                EXPECT_NEAR(change, truth, 1e-6 * force_times_move + 1e-9)
                    << "k=" << k << " from=" << from << " to=" << to;
            }
        }
    }
}

TEST(PassivityObserver, BooksTheZeroOrderHoldEnergyOfEveryTickInContact) {
    // K = 10, 20 units per tick in and out, never saturating (K·980 < 10000). Each tick
    // with both ends in contact creates K·Δs²/2 = 2000, of which one count's worth,
    // ½·K·q² = 119.2, is forgiven as possibly the sensor's.
    const SpringPort spring{10.0};
    const std::vector<double> path = in_and_out(0, 980, 20);
    const PortRun naive = drive(spring, path, false);
    const double per_tick = 0.5 * 10 * 20 * 20 - 0.5 * 10 * kStep * kStep;
    const double ticks_in_contact = static_cast<double>(path.size() - 1);
    EXPECT_NEAR(naive.ledger, ticks_in_contact * per_tick, 1e-6 * ticks_in_contact * per_tick);
    // The naive element's force is the spring's, and over the closed cycle it gave the
    // handle exactly K·Δs²/2 per tick more than it took.
    for (size_t n = 0; n < path.size(); ++n) ASSERT_EQ(naive.out[n], spring.force(path[n]));
    EXPECT_NEAR(naive.handle_gain, ticks_in_contact * 0.5 * 10 * 20 * 20, 1e-6);
}

TEST(PassivityObserver, BooksNothingWhileTheForceIsSaturated) {
    // A held constant force is exact: no lag, no energy created.
    const SpringPort spring{100.0};  // saturates beyond 100
    const PortRun naive = drive(spring, in_and_out(200, 2000, 37), false);
    EXPECT_EQ(naive.ledger, 0.0);
}

TEST(PassivityObserver, ForgivesAHandleFlickeringAcrossOneCount) {
    const SpringPort spring{50.0};
    std::vector<double> path;
    for (int i = 0; i < 1000; ++i) path.push_back(100 + (i % 2) * kStep);
    EXPECT_EQ(drive(spring, path, false).ledger, 0.0);
}

TEST(PassivityObserver, BooksNothingOutOfContact) {
    const SpringPort spring{50.0};
    EXPECT_EQ(drive(spring, in_and_out(-3000, -1, 50), false).ledger, 0.0);
}

TEST(PassivityController, AClosedCycleGivesTheHandleNoMoreThanItPutIn) {
    // Fast in-and-out cycles (2 to 16 counts a tick), five contacts, several stiffnesses.
    // The naive element hands out K·Δs²/2 per tick. The controlled one spends all the
    // ledger books; it may hand out only what the ledger forgives as possibly the
    // sensor's (one count's worth, ½·K·q², a tick in contact) and what one tick creates
    // before the controller can answer, once per contact.
    for (const double k : {5.0, 20.0, 56.0}) {
        for (const double step : {10.0, 30.0, 80.0}) {
            const SpringPort spring{k};
            std::vector<double> path;
            for (int cycle = 0; cycle < 5; ++cycle) {
                const std::vector<double> one = in_and_out(-100, 9000.0 / k, step);
                path.insert(path.end(), one.begin(), one.end());
            }
            double unprovable = 0;
            for (size_t n = 1; n < path.size(); ++n) {
                if (path[n] > 0 && path[n - 1] > 0) unprovable += 0.5 * k * kStep * kStep;
            }
            const PortRun naive = drive(spring, path, false);
            const PortRun controlled = drive(spring, path, true);
            const double one_tick = 0.5 * k * step * step;
            EXPECT_GT(naive.handle_gain, 10 * one_tick) << "k=" << k << " step=" << step;
            const double contacts = 5;
            EXPECT_LE(controlled.handle_gain, unprovable + contacts * one_tick) << "k=" << k << " step=" << step;
            EXPECT_LT(controlled.handle_gain, 0.5 * naive.handle_gain) << "k=" << k << " step=" << step;
        }
    }
}

TEST(PassivityController, OffLeavesTheForceAlone) {
    const SpringPort spring{30.0};
    const std::vector<double> path = in_and_out(0, 300, 40);
    const PortRun naive = drive(spring, path, false);
    for (size_t n = 0; n < path.size(); ++n) EXPECT_EQ(naive.out[n], spring.force(path[n]));
    EXPECT_GT(naive.ledger, 0.0);  // the observer still watches
}

// For any ledger, reading and speed: the controlled force keeps the sign of the element's
// force (a wall never pulls), stays within full scale, and moves at most k·|v|·T from it.
RC_GTEST_PROP(PassivityController, StaysWithinItsBounds, ()) {
    const double k = *rc::gen::inRange(1, 2000) / 10.0;
    const double depth = *rc::gen::inRange(-2000, 20000) / 10.0;
    const double previous = depth - *rc::gen::inRange(-500, 500) / 10.0;
    const double speed = *rc::gen::inRange(-200000, 200000) * 1.0;
    const double debt = *rc::gen::inRange(0, 1000000) * 10.0;

    ContactState state;
    state.observing = true;
    state.coordinate = static_cast<float>(previous);
    state.force = static_cast<float>(-std::clamp(k * previous, -10000.0, 10000.0) * (previous > 0));
    state.generated_energy = static_cast<int64_t>(debt * kLedgerScale);
    PortTick tick;
    tick.coordinate = static_cast<float>(depth);
    tick.ideal_energy_change =
        saturated_spring_energy_change(static_cast<float>(k), static_cast<float>(previous), static_cast<float>(depth));
    tick.force = saturated_spring_force(static_cast<float>(k), static_cast<float>(depth));
    tick.stiffness = static_cast<float>(k);
    tick.velocity = static_cast<float>(speed);
    tick.dt_s = static_cast<float>(kT);
    tick.resolution = static_cast<float>(kStep);
    const double out = passive_port_force(state, tick, true);

    RC_ASSERT(std::isfinite(out));
    RC_ASSERT(std::fabs(out) <= 10000.0);
    RC_ASSERT(out * tick.force >= 0.0);
    if (tick.force == 0.0) RC_ASSERT(out == 0.0);
    // Within float's rounding of the controller's arithmetic (a few ulps of the force).
    RC_ASSERT(std::fabs(out - tick.force) <= k * std::fabs(speed) * kT * (1 + 1e-6) + 1e-3);
    RC_ASSERT(generated_energy(state) >= 0.0);
}


// The ledger's conversion against the cast it replaces (on x86 the cast is exact by the
// language's definition): every float from the edges of each binade up to 2^62, both
// signs, with the values either side of each, and the two ends of int32.
TEST(LedgerConversion, TruncatesToInt64AsTheCastDoes) {
    int checked = 0;
    for (int e = -2; e <= 62; ++e) {
        const float base = std::ldexp(1.0f, e);
        for (float x : {base, std::nextafter(base, 0.0f), std::nextafter(base, 2 * base), base * 1.5f,
                        std::nextafter(base * 1.5f, 0.0f), base * 1.999999f}) {
            for (float s : {x, -x}) {
                ASSERT_EQ(truncate_to_int64(s), static_cast<int64_t>(s)) << "x = " << s;
                ++checked;
            }
        }
    }
    for (float x : {2147483520.0f, 2147483648.0f, -2147483648.0f, -2147483520.0f, 0.0f, -0.0f, 0.99f, -0.99f}) {
        EXPECT_EQ(truncate_to_int64(x), static_cast<int64_t>(x)) << "x = " << x;
    }
    EXPECT_GT(checked, 700);
}

RC_GTEST_PROP(LedgerConversion, AgreesWithTheCastOnAnyFloatInRange, (uint32_t bits)) {
    float x = 0;
    std::memcpy(&x, &bits, sizeof x);
    RC_PRE(std::isfinite(x) && std::fabs(x) < 0x1p62f);
    RC_ASSERT(truncate_to_int64(x) == static_cast<int64_t>(x));
}
}  // namespace
}  // namespace feel::detail
