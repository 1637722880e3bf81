// Friction shoved and released (the review of issue 16): a free handle is shoved by a
// force larger than the friction, then let go. §3.5: friction "always resists the
// direction of motion", so once released the handle must coast to a stop and stay there:
// friction may never push it along its motion (beyond what one sensor count can hide),
// and the handle may not travel back the way it came.
//
// Without the stop guard (src/engine/conditions/stop_guard.hpp) the Dahl bristle fails every
// case: it stops a free handle with its full force stored and throws it back (the joystick,
// f = 8000, 1 kHz: 971 units back after 1720 forward; docs/conditions.md, "Friction").
#include <cstdio>

#include "friction_loop.hpp"

namespace feel::test {
namespace {

// A constant force on x for the first `shove_s` seconds, then nothing.
EffectParams shove_on_x(int32_t magnitude, double shove_s) {
    EffectParams p = constant_force_on_x(magnitude);
    p.duration_us = static_cast<int64_t>(std::llround(shove_s * 1e6));
    return p;
}

struct ShoveResult {
    double forward = 0;        // from rest to the furthest point, position units
    double back = 0;           // from the furthest point after the release back toward the start
    double along_work = 0;     // work friction did along the motion after release, force units · position units
    int along_fast_ticks = 0;  // ticks where friction pushed along a motion faster than one count per tick
    double largest_step = 0;   // the largest tick-to-tick change of the force after release
    double final_force = 0;
};

// A free handle pushed by `push` for `shove_s` seconds against a friction, then let go.
ShoveResult push_and_release(const char* profile_name, const EffectParams& resistance, double rate_hz, int32_t push,
                             double shove_s, bool mass_known) {
    const auto rows = run_loop(profile_name, sim::Grip::none, "hold:0", {resistance, shove_on_x(push, shove_s)},
                               shove_s + 1.0, rate_hz, 0, mass_known);
    const sim::DeviceProfile& profile = *sim::find_device_profile(profile_name);
    const double count = 2.0 * 10000 / profile.axes[0].sensor_counts;
    const double dt = 1.0 / rate_hz;
    ShoveResult r;
    const double start = rows[0].x[0];
    double furthest = start;
    const size_t released = static_cast<size_t>(std::llround(shove_s * rate_hz)) + 1;
    // Back travel counts from the furthest point after the release: a held push may rock the
    // handle in the presliding zone before it is let go, which is not a released handle's.
    double furthest_released = rows[released - 1].x[0];
    for (size_t i = 0; i < rows.size(); ++i) {
        furthest = std::max(furthest, rows[i].x[0]);
        if (i < released) continue;
        furthest_released = std::max(furthest_released, rows[i].x[0]);
        r.back = std::max(r.back, furthest_released - rows[i].x[0]);
        // After release the engine's force is friction alone.
        const double f = rows[i].force[0], v = rows[i].v[0];
        if (f * v > 0) {
            r.along_work += f * v * dt;
            if (std::fabs(v) > count * rate_hz) ++r.along_fast_ticks;
        }
        if (i > released) r.largest_step = std::max(r.largest_step, std::fabs(f - rows[i - 1].force[0]));
    }
    r.forward = furthest - start;
    r.final_force = rows.back().force[0];
    return r;
}

ShoveResult shove_and_release(const char* profile_name, int32_t friction, double rate_hz, int32_t push = 10000,
                              double shove_s = 0.02, bool mass_known = true) {
    return push_and_release(profile_name, friction_on({Axis::x}, friction), rate_hz, push, shove_s, mass_known);
}

TEST(FrictionShove, AReleasedHandleStaysWhereItStoppedOnEveryProfile) {
    // The review's case: friction 8000, shoved by 10000 for 20 ms. Required: friction never
    // pushes along the motion beyond one sensor count's worth of work, and the handle
    // travels back no more than max(2 sensor counts, 1% of its forward travel).
    for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
        for (double rate : {500.0, 1000.0, 10000.0}) {
            for (int32_t f : {3000, 8000}) {
                SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz f=" + std::to_string(f));
                const sim::DeviceProfile& profile = *sim::find_device_profile(profile_name);
                const double count = 2.0 * 10000 / profile.axes[0].sensor_counts;
                const ShoveResult r = shove_and_release(profile_name, f, rate);
                EXPECT_GT(r.forward, 10 * count);  // it really was shoved
                EXPECT_LE(r.back, std::max(2 * count, 0.01 * r.forward));
                EXPECT_EQ(r.along_fast_ticks, 0);
                EXPECT_LE(r.along_work, f * count);
                EXPECT_LE(std::fabs(r.final_force), 0.05 * f);
                std::printf("shove %s %5.0f Hz f %d: forward %.1f back %.2f step %.0f\n", profile_name, rate, f,
                            r.forward, r.back, r.largest_step);
            }
        }
    }
}

TEST(FrictionShove, AReleasedHeldPushDoesNotSpringBack) {
    // A push smaller than the friction holds the free handle still (stiction), deflecting
    // the bristle; then the push ends. Coulomb friction lets go with the push: the handle,
    // with nothing on it, stays. Required as for the shove: back travel at most max(2 sensor
    // counts, 1% of the forward travel), and no friction pushing along the motion. The push
    // is an effect, so the engine knows when it ends: this holds without the device's mass.
    const int32_t f = 6000;
    for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
        const sim::DeviceProfile& profile = *sim::find_device_profile(profile_name);
        const double count = 2.0 * 10000 / profile.axes[0].sensor_counts;
        for (double rate : {500.0, 1000.0, 10000.0}) {
            for (int32_t push : {1500, 3000, 5000}) {
                for (bool mass_known : {true, false}) {
                    SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz push=" +
                                 std::to_string(push) + (mass_known ? "" : " mass unknown"));
                    const ShoveResult r = shove_and_release(profile_name, f, rate, push, 0.5, mass_known);
                    EXPECT_LE(r.back, std::max(2 * count, 0.01 * r.forward));
                    EXPECT_EQ(r.along_fast_ticks, 0);
                    EXPECT_LE(r.along_work, f * count);
                    EXPECT_LE(std::fabs(r.final_force), 0.05 * f);
                    std::printf("held %s %5.0f Hz push %d%s: forward %.1f back %.2f (bound %.2f) step %.0f\n",
                                profile_name, rate, push, mass_known ? "" : " (no mass)", r.forward, r.back,
                                std::max(2 * count, 0.01 * r.forward), r.largest_step);
                }
            }
        }
    }
}

TEST(FrictionShove, AReleasedPushOnATextureDoesNotSpringBack) {
    // The same on a texture (§3.6, a patch of friction per bump): the handle rests on a bump's
    // top (bumps 10000 apart and as wide, a long sinusoidal washboard, so that the push holds
    // on the bump rather than sliding off it), held still by a push smaller than the
    // roughness, then let go.
    const EffectParams texture = texture_on_x(6000, 6000, 10000, 10000);
    for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
        const sim::DeviceProfile& profile = *sim::find_device_profile(profile_name);
        const double count = 2.0 * 10000 / profile.axes[0].sensor_counts;
        for (double rate : {1000.0, 10000.0}) {
            for (int32_t push : {1000, 2000}) {
                SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz push=" +
                             std::to_string(push));
                const ShoveResult r = push_and_release(profile_name, texture, rate, push, 0.5, true);
                EXPECT_LE(r.back, std::max(2 * count, 0.01 * r.forward));
                EXPECT_EQ(r.along_fast_ticks, 0);
                EXPECT_LE(r.along_work, 6000 * count);
                std::printf("texture %s %5.0f Hz push %d: forward %.1f back %.2f (bound %.2f) step %.0f\n",
                            profile_name, rate, push, r.forward, r.back, std::max(2 * count, 0.01 * r.forward),
                            r.largest_step);
            }
        }
    }
}

TEST(FrictionShove, AShovedHandleStopsOnATextureWithoutSpringingBack) {
    // Issue 16 §1: "textures ... built on the same model get the same guarantee". A free
    // handle resting on a bump's top (bumps 10000 apart and as wide: a long washboard, so
    // that it stops on a bump's flank rather than in a gap) is shoved by 10000 for 10 ms (within the travel) and
    // let go. The texture is friction of strength R·bump(s) (§3.6, "a spatially varying
    // resistance", §3.1), so the handle must coast to rest and stay, as on friction:
    // back travel at most max(2 sensor counts, 1% of the forward travel).
    for (const char* profile_name : {"joystick", "wheel", "3axis"}) {
        const sim::DeviceProfile& profile = *sim::find_device_profile(profile_name);
        const double count = 2.0 * 10000 / profile.axes[0].sensor_counts;
        for (double rate : {500.0, 1000.0, 10000.0}) {
            for (int32_t roughness : {3000, 8000}) {
                SCOPED_TRACE(std::string(profile_name) + " " + std::to_string(rate) + " Hz R=" +
                             std::to_string(roughness));
                const EffectParams texture = texture_on_x(roughness, roughness, 10000, 10000);
                const ShoveResult r = push_and_release(profile_name, texture, rate, 10000, 0.01, true);
                EXPECT_GT(r.forward, 10 * count);  // it really was shoved
                EXPECT_LE(r.back, std::max(2 * count, 0.01 * r.forward));
                EXPECT_EQ(r.along_fast_ticks, 0);
                EXPECT_LE(r.along_work, roughness * count);
                std::printf("texture shove %s %5.0f Hz R %d: forward %.1f back %.2f (bound %.2f) step %.0f\n",
                            profile_name, rate, roughness, r.forward, r.back, std::max(2 * count, 0.01 * r.forward),
                            r.largest_step);
            }
        }
    }
}

}  // namespace
}  // namespace feel::test
