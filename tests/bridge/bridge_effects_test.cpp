// The bridge's effect table on the in-process simulated I-FORCE 2.0 device: what the
// kernel asks (upload, change, play with a count, stop, erase, gain, autocenter) reaches
// the device as the documented feel effects, and what the device refuses comes back as the
// errno the kernel passes to the game.
#include "bridge_effects.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <chrono>
#include <thread>

namespace feel::bridge {
namespace {

using namespace std::chrono_literals;

struct Bench {
    host::Device device = host::Device::open("sim:iforce2").value();
    std::vector<std::string> lines;
    BridgeEffects effects{device, [this](const std::string& l) { lines.push_back(l); }};
};

ff_effect constant(int16_t id, int16_t level) {
    ff_effect e{};
    e.type = FF_CONSTANT;
    e.id = id;
    e.direction = 0x8000;
    e.u.constant.level = level;
    return e;
}

// Waits until the device's state reports say `n` effects play (or 2 s pass).
int32_t playing_after_settle(host::Device& d, int32_t n) {
    const auto until = std::chrono::steady_clock::now() + 2s;
    int32_t now = -1;
    while (std::chrono::steady_clock::now() < until) {
        auto s = d.wait_input(100ms);
        if (s) now = s->playing_effects;
        if (now == n) break;
    }
    return now;
}

TEST(BridgeEffects, UploadReachesTheDeviceAsTheDocumentedEffect) {
    Bench b;
    ASSERT_EQ(b.effects.upload(constant(0, 16384)), 0);
    auto made = b.effects.feel_effects(0);
    ASSERT_EQ(made.size(), 1u);
    EXPECT_TRUE(made[0]->downloaded());
    EXPECT_EQ(made[0]->parameters().type, EffectType::constant);
    EXPECT_EQ(made[0]->parameters().constant.magnitude, 5000);
    EXPECT_EQ(made[0]->parameters().direction.value[0], 18000);  // 0x8000: half a turn
    // A change of the same id is made in place: the same device block, the new level.
    const uint16_t block = made[0]->block();
    ASSERT_EQ(b.effects.upload(constant(0, -32768)), 0);
    made = b.effects.feel_effects(0);
    ASSERT_EQ(made.size(), 1u);
    EXPECT_EQ(made[0]->block(), block);
    EXPECT_EQ(made[0]->parameters().constant.magnitude, -10000);
    EXPECT_TRUE(b.lines.empty());
}

TEST(BridgeEffects, PlayStopAndErase) {
    Bench b;
    ASSERT_EQ(b.effects.upload(constant(3, 8192)), 0);
    b.effects.play(3, 1);
    EXPECT_EQ(playing_after_settle(b.device, 1), 1);
    b.effects.play(3, 0);
    EXPECT_EQ(playing_after_settle(b.device, 0), 0);
    EXPECT_EQ(b.effects.erase(3), 0);
    EXPECT_EQ(b.effects.size(), 0u);
    EXPECT_EQ(b.effects.erase(3), -EINVAL);  // nothing there any more
    b.effects.play(3, 1);                    // logged, not fatal
    EXPECT_EQ(b.lines.size(), 2u);
}

TEST(BridgeEffects, RumbleHoldsTwoSinesThatPlayTogether) {
    Bench b;
    ff_effect e{};
    e.type = FF_RUMBLE;
    e.id = 1;
    e.u.rumble.strong_magnitude = 0xffff;
    e.u.rumble.weak_magnitude = 0x8000;
    ASSERT_EQ(b.effects.upload(e), 0);
    auto made = b.effects.feel_effects(1);
    ASSERT_EQ(made.size(), 2u);
    EXPECT_EQ(made[0]->parameters().periodic.magnitude, 10000);
    EXPECT_EQ(made[1]->parameters().periodic.magnitude, 5000);
    b.effects.play(1, 1);
    EXPECT_EQ(playing_after_settle(b.device, 2), 2);
}

TEST(BridgeEffects, RefusalsBecomeErrnosAndLogLines) {
    Bench b;
    ff_effect bad{};
    bad.type = FF_PERIODIC;
    bad.id = 0;
    bad.u.periodic.waveform = FF_SINE;  // period 0
    EXPECT_EQ(b.effects.upload(bad), -EINVAL);
    ASSERT_EQ(b.lines.size(), 1u);
    EXPECT_NE(b.lines[0].find("u.periodic.period = 0"), std::string::npos) << b.lines[0];
    EXPECT_EQ(b.effects.size(), 0u);
    // A refused change leaves the effect as it was (no state lost).
    ASSERT_EQ(b.effects.upload(constant(2, 8192)), 0);
    ff_effect change = constant(2, 8192);
    change.u.constant.envelope.fade_level = 0x9000;
    EXPECT_EQ(b.effects.upload(change), -EINVAL);
    EXPECT_EQ(b.effects.feel_effects(2).at(0)->parameters().constant.magnitude, 2500);
}

TEST(BridgeEffects, AFullDeviceIsNoSpace) {
    Bench b;
    const int32_t slots = b.device.capabilities().effect_slots;
    int result = 0;
    int16_t id = 0;
    for (; id < slots + 1 && result == 0; ++id) result = b.effects.upload(constant(id, 100));
    EXPECT_EQ(result, -ENOSPC);
    EXPECT_LE(static_cast<int32_t>(b.effects.size()), slots);
}

TEST(BridgeEffects, GainAndAutocenter) {
    Bench b;
    b.effects.set_gain(0x8000);
    auto s = b.device.wait_input(500ms);
    for (int i = 0; i < 5 && s && s->gain != 5000; ++i) s = b.device.wait_input(500ms);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->gain, 5000);  // 0x8000 of 0xFFFF
    b.effects.set_autocenter(0xffff);
    EXPECT_EQ(playing_after_settle(b.device, 1), 1);
    b.effects.set_autocenter(0x4000);  // changed in place
    EXPECT_EQ(playing_after_settle(b.device, 1), 1);
    b.effects.set_autocenter(0);
    EXPECT_EQ(playing_after_settle(b.device, 0), 0);
    EXPECT_TRUE(b.lines.empty());
}

TEST(BridgeEffects, OnAOneAxisWheelAForceAlongTheAxisPlays) {
    host::Device wheel = host::Device::open("sim:wheel").value();
    ASSERT_EQ(wheel.capabilities().axis_count, 1);
    std::vector<std::string> lines;
    BridgeEffects effects(wheel, [&](const std::string& l) { lines.push_back(l); });
    ff_effect right = constant(0, 16384);
    right.direction = 0xc000;  // from the right: 270°, sin = -1
    ASSERT_EQ(effects.upload(right), 0) << (lines.empty() ? "" : lines.back());
    const EffectParams& p = effects.feel_effects(0).at(0)->parameters();
    EXPECT_EQ(p.axis_count, 1);
    EXPECT_EQ(p.direction.kind, DirectionKind::cartesian);
    EXPECT_EQ(p.direction.value[0], -10000);
    ff_effect spring{};
    spring.type = FF_SPRING;
    spring.id = 1;
    spring.u.condition[0].right_coeff = 32767;
    spring.u.condition[0].left_coeff = 32767;
    ASSERT_EQ(effects.upload(spring), 0) << (lines.empty() ? "" : lines.back());
    EXPECT_EQ(effects.feel_effects(1).at(0)->parameters().axis_count, 1);
}

}  // namespace
}  // namespace feel::bridge
