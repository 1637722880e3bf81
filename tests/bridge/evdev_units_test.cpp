// evdev's units to feel's: the expectations are hid-pidff's arithmetic worked by hand
// (drivers/hid/usbhid/hid-pidff.c: pidff_set_signed, pidff_set, pidff_rescale) for feel's
// ranges, and evdev's own definitions (linux/input.h: levels ±0x7FFF, angles a turn in
// 0..0xFFFF, times in ms).
#include "evdev_units.hpp"

#include <gtest/gtest.h>

namespace feel::bridge {
namespace {

TEST(EvdevUnits, SignedLevelsScaleEachSideOntoTenThousand) {
    EXPECT_EQ(evdev_signed_level(0), 0);
    EXPECT_EQ(evdev_signed_level(32767), 10000);    // full positive
    EXPECT_EQ(evdev_signed_level(-32768), -10000);  // full negative
    EXPECT_EQ(evdev_signed_level(16384), 5000);     // 16384 * 10000 / 32767 = 5000.15
    EXPECT_EQ(evdev_signed_level(-16384), -5000);   // -16384 * 10000 / 32768
    EXPECT_EQ(evdev_signed_level(8192), 2500);      // 2500.08, toward zero
    EXPECT_EQ(evdev_signed_level(-8192), -2500);
    EXPECT_EQ(evdev_signed_level(3), 0);            // 0.9: toward zero
}

TEST(EvdevUnits, UnsignedLevelsScaleTheWholeSixteenBits) {
    EXPECT_EQ(evdev_unsigned_level(0), 0);
    EXPECT_EQ(evdev_unsigned_level(0xffff), 10000);
    EXPECT_EQ(evdev_unsigned_level(0x8000), 5000);  // 32768 * 10000 / 65535 = 5000.08
    EXPECT_EQ(evdev_unsigned_level(32767), 4999);   // 4999.92: fftest's "full" saturation is half
    EXPECT_EQ(evdev_unsigned_level(49152), 7500);   // fftest's gain 0xC000
}

TEST(EvdevUnits, EnvelopeLevelsAreFifteenBits) {
    EXPECT_EQ(evdev_envelope_level(0), 0);
    EXPECT_EQ(evdev_envelope_level(0x7fff), 10000);
    EXPECT_EQ(evdev_envelope_level(4096), 1250);  // 4096 * 10000 / 32767 = 1250.04
}

TEST(EvdevUnits, AnglesAreATurnInHundredthsOfADegree) {
    EXPECT_EQ(evdev_angle(0), 0);          // down: feel's 0, from +y
    EXPECT_EQ(evdev_angle(0x4000), 9000);  // 16384 * 36000 / 65535 = 9000.14
    EXPECT_EQ(evdev_angle(0x8000), 18000);
    EXPECT_EQ(evdev_angle(0xc000), 27000);
    EXPECT_EQ(evdev_angle(0xffff), 0);     // 36000 is a whole turn: 0
    EXPECT_EQ(evdev_angle(0xfffe), 35999);
}

TEST(EvdevUnits, MillisecondsBecomeMicroseconds) {
    EXPECT_EQ(evdev_ms_to_us(0), 0);
    EXPECT_EQ(evdev_ms_to_us(1), 1000);
    EXPECT_EQ(evdev_ms_to_us(65535), 65'535'000);
}

}  // namespace
}  // namespace feel::bridge
