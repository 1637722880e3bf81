// Buttons (SimDevice::set_buttons) reach TickInput::buttons, and an InputSchedule plays a
// script of presses, releases, let-gos and grabs into a device at the right ticks.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "feel/sim/input_schedule.hpp"
#include "sim_test_support.hpp"

namespace feel::sim {
namespace {

std::string thrown_message(const auto& f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(nothing thrown)";
}

TEST(Buttons, StartReleasedAndAppearInTickInput) {
    SimDevice device(*find_device_profile("joystick"), Grip::firm, TargetMotion::hold_at({0}));
    TickInput in;
    in.buttons = 0xFFu;
    device.sense(in);
    EXPECT_EQ(in.buttons, 0u);
    ASSERT_TRUE(device.set_buttons(0b0101));  // buttons 1 and 3
    device.sense(in);
    EXPECT_EQ(in.buttons, 0b0101u);
    EXPECT_EQ(device.buttons(), 0b0101u);
    // Stepping does not touch them.
    test::run(device, 3000, 1e-3, 10);
    device.sense(in);
    EXPECT_EQ(in.buttons, 0b0101u);
}

TEST(Buttons, AButtonTheDeviceLacksIsRefused) {
    SimDevice joystick(*find_device_profile("joystick"), Grip::none, TargetMotion::hold_at({0}));
    ASSERT_TRUE(joystick.set_buttons(0b1000));     // button 4 of 4
    EXPECT_FALSE(joystick.set_buttons(0b10000));   // button 5
    EXPECT_FALSE(joystick.set_buttons(0x80000000u));
    EXPECT_EQ(joystick.buttons(), 0b1000u);        // unchanged
    SimDevice wheel(*find_device_profile("wheel"), Grip::none, TargetMotion::hold_at({0}));
    EXPECT_TRUE(wheel.set_buttons(0x80u));         // button 8 of 8
    EXPECT_FALSE(wheel.set_buttons(0x100u));

    DeviceProfile many = test::bare_profile(0.1, 0.1, 0.0);
    many.button_count = 32;
    SimDevice all(many, Grip::none, TargetMotion::hold_at({0}));
    EXPECT_TRUE(all.set_buttons(0xFFFFFFFFu));
    many.button_count = 0;
    SimDevice none(many, Grip::none, TargetMotion::hold_at({0}));
    EXPECT_FALSE(none.set_buttons(1u));
    EXPECT_TRUE(none.set_buttons(0u));
}

// Stepping at 1 kHz and applying the schedule before each sense(): every tick sees exactly
// what the script says at its time, including presses one tick apart.
TEST(Hats, PushedHatsAppearInTickInputAndUnknownHatsAreRefused) {
    // The joystick class has two hats (§1.2.c's reflex table names hat switch #2).
    const DeviceProfile& profile = *find_device_profile("joystick");
    ASSERT_EQ(profile.hat_count, 2);
    SimDevice device(profile, Grip::firm, TargetMotion::hold_at({0}));
    TickInput in;
    in.hats = 0xFu;
    device.sense(in);
    EXPECT_EQ(in.hats, 0u);  // every hat centred at start
    ASSERT_TRUE(device.set_hats(0b10));  // hat 2
    device.sense(in);
    EXPECT_EQ(in.hats, 0b10u);
    EXPECT_FALSE(device.set_hats(0b100));  // hat 3: the profile has two
    EXPECT_EQ(device.hats(), 0b10u);       // unchanged
}

TEST(InputSchedule, PlaysHatPushesAtTheirTicks) {
    const DeviceProfile& profile = *find_device_profile("iforce2");
    SimDevice device(profile, Grip::firm, TargetMotion::hold_at({0}));
    InputSchedule script(profile);
    script.push_hat(2000, 2).center_hat(5000, 2).push_hat(3000, 1);
    EXPECT_EQ(script.hats_at(1999), 0u);
    EXPECT_EQ(script.hats_at(3000), 0b11u);
    EXPECT_EQ(script.hats_at(5000), 0b01u);
    TickInput in;
    for (int64_t t = 0; t <= 6000; t += 1000) {
        script.apply(device, t);
        device.sense(in);
        EXPECT_EQ(in.hats, script.hats_at(t)) << "t = " << t;
        EXPECT_EQ(in.buttons, 0u);
    }
    EXPECT_EQ(thrown_message([&] { script.push_hat(0, 3); }),
              "input schedule: push_hat hat = 3 is out of range (allowed 1..2, the device's hat switches)");
    EXPECT_EQ(thrown_message([&] { script.center_hat(0, 0); }),
              "input schedule: center_hat hat = 0 is out of range (allowed 1..2, the device's hat switches)");
}

TEST(InputSchedule, TicksSeeTheScriptedButtonsAndHand) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    InputSchedule schedule(joystick);
    schedule.press(10'000, 1)
        .release(11'000, 1)
        .press(12'000, 1)  // a burst: a press every 2 ms
        .release(13'000, 1)
        .press(12'500, 2)  // between ticks: seen at 13 ms
        .let_go(20'000)
        .set_buttons(25'000, 0b1111)
        .grab(30'000)
        .release(40'000, 3);
    EXPECT_EQ(schedule.size(), 9u);
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0, 0}));
    const float no_force[kMaxAxes] = {};
    for (int64_t t = 0; t <= 50'000; t += 1000) {
        schedule.apply(device, t);
        TickInput in;
        in.t_us = t;
        device.sense(in);
        EXPECT_EQ(in.buttons, schedule.buttons_at(t)) << "t = " << t;
        EXPECT_EQ(in.handle_held, schedule.hand_present_at(t)) << "t = " << t;
        device.step(no_force, 1e-3);
    }
    // The script itself, checked by hand.
    EXPECT_EQ(schedule.buttons_at(9'999), 0u);
    EXPECT_EQ(schedule.buttons_at(10'000), 0b1u);
    EXPECT_EQ(schedule.buttons_at(11'000), 0u);
    EXPECT_EQ(schedule.buttons_at(12'000), 0b1u);
    EXPECT_EQ(schedule.buttons_at(12'999), 0b11u);
    EXPECT_EQ(schedule.buttons_at(13'000), 0b10u);
    EXPECT_EQ(schedule.buttons_at(25'000), 0b1111u);
    EXPECT_EQ(schedule.buttons_at(40'000), 0b1011u);
    EXPECT_TRUE(schedule.hand_present_at(19'999));
    EXPECT_FALSE(schedule.hand_present_at(20'000));
    EXPECT_TRUE(schedule.hand_present_at(30'000));
    EXPECT_EQ(schedule.pending(), 0u);
    EXPECT_EQ(schedule.rejected(), 0);
}

TEST(InputSchedule, SameTimeEventsApplyInTheOrderAdded) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    InputSchedule schedule(joystick);
    schedule.press(5'000, 2).let_go(5'000).release(5'000, 2).grab(5'000).press(5'000, 4);
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0}));
    EXPECT_EQ(schedule.apply(device, 4'999), 0);
    EXPECT_EQ(schedule.apply(device, 5'000), 5);
    EXPECT_EQ(device.buttons(), 0b1000u);
    EXPECT_TRUE(device.hand_present());
    EXPECT_EQ(schedule.apply(device, 6'000), 0);

    schedule.rewind();
    EXPECT_EQ(schedule.pending(), 5u);
    SimDevice again(joystick, Grip::firm, TargetMotion::hold_at({0}));
    EXPECT_EQ(schedule.apply(again, 1'000'000), 5);
    EXPECT_EQ(again.buttons(), 0b1000u);
}

TEST(InputSchedule, BadEventsAreRefusedWithTheAllowedRange) {
    const DeviceProfile& joystick = *find_device_profile("joystick");
    InputSchedule schedule(joystick);
    EXPECT_EQ(thrown_message([&] { schedule.press(-1, 1); }),
              "input schedule: t_us = -1 is out of range (allowed >= 0, µs)");
    EXPECT_EQ(thrown_message([&] { schedule.press(0, 5); }),
              "input schedule: press button = 5 is out of range (allowed 1..4, the device's "
              "buttons)");
    EXPECT_EQ(thrown_message([&] { schedule.release(0, 0); }),
              "input schedule: release button = 0 is out of range (allowed 1..4, the "
              "device's buttons)");
    EXPECT_EQ(thrown_message([&] { schedule.set_buttons(0, 0x10); }),
              "input schedule: set_buttons mask = 16 names a button the device lacks (it has "
              "4 buttons; bit i is button i+1)");
    EXPECT_EQ(thrown_message([&] { schedule.let_go(-5); }),
              "input schedule: t_us = -5 is out of range (allowed >= 0, µs)");
    EXPECT_EQ(schedule.size(), 0u);

    // An event that would fall before ones already applied cannot be honoured.
    schedule.grab(1'000);
    SimDevice device(joystick, Grip::firm, TargetMotion::hold_at({0}));
    schedule.apply(device, 2'000);
    EXPECT_EQ(thrown_message([&] { schedule.let_go(500); }),
              "input schedule: t_us = 500 is before events already applied (rewind() first)");
    EXPECT_NO_THROW(schedule.let_go(1'000));  // after the applied one at the same time

    DeviceProfile bad = joystick;
    bad.button_count = 33;
    EXPECT_EQ(thrown_message([&] { InputSchedule s(bad); }),
              "input schedule: button_count = 33 is out of range (allowed 0..32)");
}

// A schedule built for the wheel's 8 buttons, played into a 4-button joystick: the presses
// the joystick cannot have are skipped and counted, the others go through.
TEST(InputSchedule, EventsTheDeviceRefusesAreCounted) {
    InputSchedule schedule(*find_device_profile("wheel"));
    schedule.press(0, 2).press(1'000, 8).press(2'000, 3);
    SimDevice joystick(*find_device_profile("joystick"), Grip::none, TargetMotion::hold_at({0}));
    EXPECT_EQ(schedule.apply(joystick, 5'000), 3);
    EXPECT_EQ(schedule.rejected(), 1);
    EXPECT_EQ(joystick.buttons(), 0b0110u);
}

}  // namespace
}  // namespace feel::sim
