// Edge cases of the C ABI's boundary: handles outliving their device, borrowed devices,
// bad enumerations, the thread-locality of the last error, and every §8 wrapper through C.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "feel/feel.h"

namespace {

std::string last_message() { return feel_last_error_message(); }

struct DeviceCloser {
    void operator()(feel_device* d) const { feel_close(d); }
};
using DevicePtr = std::unique_ptr<feel_device, DeviceCloser>;

DevicePtr open_device(const char* address = "sim:iforce2") {
    DevicePtr d(feel_open(address));
    EXPECT_NE(d, nullptr) << last_message();
    return d;
}

TEST(CapiErrors, EveryCodeHasAName) {
    EXPECT_STREQ(feel_error_name(FEEL_OK), "ok");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_INVALID_PARAMETER), "invalid parameter");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_DEVICE_FULL), "device full");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_NOT_SUPPORTED), "not supported");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_INVALID_HANDLE), "invalid handle");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_DISCONNECTED), "disconnected");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_TIMEOUT), "timeout");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_PROTOCOL), "protocol error");
    EXPECT_STREQ(feel_error_name(FEEL_ERROR_INTERNAL), "internal error");
    EXPECT_STREQ(feel_error_name(99), "unknown error");
}

TEST(CapiErrors, TheLastErrorBelongsToItsThread) {
    EXPECT_EQ(feel_set_gain(nullptr, 0), FEEL_ERROR_INVALID_PARAMETER);
    EXPECT_EQ(last_message(), "feel_set_gain: device is NULL");
    std::thread other([] {
        EXPECT_EQ(feel_last_error(), FEEL_OK);
        EXPECT_STREQ(feel_last_error_message(), "");
        EXPECT_EQ(feel_device_command(nullptr, 0), FEEL_ERROR_INVALID_PARAMETER);
    });
    other.join();
    EXPECT_EQ(last_message(), "feel_set_gain: device is NULL");  // untouched by the other thread
}

TEST(CapiDevice, AnUnknownProfileIsNamed) {
    EXPECT_EQ(feel_open("sim:warp_drive"), nullptr);
    EXPECT_EQ(feel_last_error(), FEEL_ERROR_INVALID_PARAMETER);
    EXPECT_NE(last_message().find("warp_drive"), std::string::npos) << last_message();
    EXPECT_NE(last_message().find("iforce2"), std::string::npos) << "lists the known profiles: " << last_message();
}

TEST(CapiDevice, BadArgumentsAreRefusedWithTheirRange) {
    DevicePtr d = open_device();
    ASSERT_TRUE(d);
    EXPECT_EQ(feel_device_command(d.get(), 6), FEEL_ERROR_INVALID_PARAMETER);
    EXPECT_EQ(last_message(), "feel_device_command: command = 6 is out of range (allowed 0..5)");
    const int32_t force[3] = {0, 0, 0};
    EXPECT_EQ(feel_stream_force(d.get(), force, 3), FEEL_ERROR_INVALID_PARAMETER);
    EXPECT_EQ(last_message(), "feel_stream_force: axis_count = 3 is out of range (allowed 2..2)");
    EXPECT_EQ(feel_stream_force(d.get(), nullptr, 2), FEEL_ERROR_INVALID_PARAMETER);
    feel_input in{};
    in.size = sizeof in;
    EXPECT_EQ(feel_wait_input(d.get(), 0, &in), FEEL_ERROR_INVALID_PARAMETER);
    EXPECT_EQ(last_message(), "feel_wait_input: timeout_ms = 0 is out of range (allowed 1..60000)");
    feel_open_options o{};
    o.size = sizeof o;
    o.sim_hand = "octopus";
    EXPECT_EQ(feel_open_ex("sim:iforce2", &o), nullptr);
    EXPECT_EQ(feel_last_error(), FEEL_ERROR_INVALID_PARAMETER);
    EXPECT_NE(last_message().find("octopus"), std::string::npos) << last_message();
    EXPECT_EQ(feel_open_ex("sim:iforce2", nullptr), nullptr);
    EXPECT_EQ(last_message(), "feel_open_ex: options is NULL");
}

TEST(CapiDevice, CommandsAndStreamingSucceed) {
    DevicePtr d = open_device();
    ASSERT_TRUE(d);
    EXPECT_EQ(feel_device_command(d.get(), FEEL_COMMAND_STOP_ALL), FEEL_OK) << last_message();
    const int32_t force[2] = {1000, -1000};
    EXPECT_EQ(feel_stream_force(d.get(), force, 2), FEEL_OK) << last_message();
    EXPECT_EQ(feel_set_gain(d.get(), 10000), FEEL_OK) << last_message();
}

TEST(CapiEffect, AnEffectOutlivingItsDeviceIsAnInvalidHandle) {
    feel_device* d = feel_open("sim:iforce2");
    ASSERT_NE(d, nullptr) << last_message();
    feel_effect* e = feel_center_spring(d, 3000, 10000, 0);
    ASSERT_NE(e, nullptr) << last_message();
    EXPECT_EQ(feel_effect_start(e, 1, false), FEEL_OK) << last_message();
    feel_close(d);
    EXPECT_EQ(feel_effect_start(e, 1, false), FEEL_ERROR_INVALID_HANDLE) << last_message();
    feel_effect_status_info s{};
    s.size = sizeof s;
    EXPECT_EQ(feel_effect_status(e, &s), FEEL_ERROR_INVALID_HANDLE);
    feel_effect_destroy(e);  // still must be freed, and that works
    EXPECT_EQ(feel_last_error(), FEEL_OK);
}

TEST(CapiEffect, BadEnumerationsAreNamedBeforeTheyBecomeEnums) {
    DevicePtr d = open_device();
    ASSERT_TRUE(d);
    EXPECT_EQ(feel_wall(d.get(), 5000, 2, 0, 0), nullptr);
    EXPECT_EQ(last_message(), "feel_wall: sense = 2 is out of range (allowed 0..1)");
    EXPECT_EQ(feel_sweep_periodic(d.get(), 0, 9000, 258, FEEL_WAVEFORM_SINE, 1000, 0, 10000, 0, 100000), nullptr);
    EXPECT_EQ(last_message(), "feel_sweep_periodic: sense = 258 is out of range (allowed 0..1)");
    feel_trigger t{7, 1};
    EXPECT_EQ(feel_ramp(d.get(), 0, 1000, 100000, 0, t, 0), nullptr);
    EXPECT_EQ(last_message(), "feel_ramp: trigger.kind = 7 is out of range (allowed 0..2)");
    EXPECT_EQ(feel_dynamic_control_law(d.get(), 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, false, 6), nullptr);
    EXPECT_EQ(last_message(), "feel_dynamic_control_law: axis = 6 is out of range (allowed 0..5)");
    EXPECT_EQ(feel_ramp(d.get(), 0, 1000, 100000, 0, feel_button_trigger(33), 0), nullptr);
    EXPECT_EQ(last_message(), "ramp: trigger button = 33 is out of range (allowed 1..32)");
}

TEST(CapiEffect, EveryWrapperCreatesItsEffectThroughC) {
    DevicePtr d = open_device();
    ASSERT_TRUE(d);
    feel_device* dev = d.get();
    const feel_trigger none = feel_no_trigger();
    std::vector<std::string> errors;
    // Records the error of a failed call right after it (the elements of a braced list are
    // evaluated in order) and frees the effect: the device holds 32 at once.
    auto keep = [&](feel_effect* e) {
        errors.push_back(e ? "" : last_message());
        feel_effect_destroy(e);
        return e != nullptr;
    };
    const bool made[] = {
        keep(feel_x_spring(dev, 1000, 1000, 0, 10000, 10000, 0)),
        keep(feel_y_spring(dev, 1000, 1000, 0, 10000, 10000, 0)),
        keep(feel_spring(dev, 1, 1, 0, 1, 1, 0, 1, 1, 0, 1, 1, 0)),
        keep(feel_angle_spring(dev, 1000, 1000, 0, 10000, 10000, 0, 4500)),
        keep(feel_center_spring(dev, 1000, 10000, 0)),
        keep(feel_spring_at_current_location(dev, 1000, 10000, 0)),
        keep(feel_x_damper(dev, 1000, 1000, 0, 10000, 10000, 0)),
        keep(feel_y_damper(dev, 1000, 1000, 0, 10000, 10000, 0)),
        keep(feel_damper(dev, 1, 1, 0, 1, 1, 0, 1, 1, 0, 1, 1, 0)),
        keep(feel_x_inertia(dev, 100, 10000)),
        keep(feel_y_inertia(dev, 100, 10000)),
        keep(feel_inertia(dev, 100, 10000)),
        keep(feel_friction(dev, 2000)),
        keep(feel_x_friction(dev, 2000, 1000)),
        keep(feel_y_friction(dev, 2000, 1000)),
        keep(feel_texture(dev, 5000, 2000, 7500, 0)),
        keep(feel_x_texture(dev, 5000, 2000, 7500)),
        keep(feel_x_texture_pos_neg(dev, 5000, 1000, 2000, 7500)),
        keep(feel_y_texture(dev, 5000, 1000, 2000, 7500)),
        keep(feel_wall(dev, 5000, FEEL_WALL_SENSE_POSITIVE, 5000, 9000)),
        keep(feel_horizontal_wall(dev, 5000, FEEL_WALL_SENSE_POSITIVE, 5000, 0, 0, true)),
        keep(feel_vertical_wall(dev, 5000, FEEL_WALL_SENSE_NEGATIVE, -5000, 0, 0, false)),
        keep(feel_barrier(dev, 5000, 5000, 500, 0, 0)),
        keep(feel_horizontal_barrier(dev, 5000, 5000, 500, 0, 0, 0)),
        keep(feel_vertical_barrier(dev, 5000, 5000, 500, 0, 0, 0)),
        keep(feel_vector_force(dev, 1000, FEEL_INFINITE, 0)),
        keep(feel_constant_force(dev, 1000, 100000, 0)),
        keep(feel_constant_force_trigger(dev, 1000, 100000, 0, feel_button_trigger(1), 0)),
        keep(feel_envelope_constant(dev, 1000, 100000, 0, 5000, 10000, 0, 10000, none, 0)),
        keep(feel_ramp(dev, 0, 1000, 100000, 0, none, 0)),
        keep(feel_ramp_envelope(dev, 0, 1000, 100000, 0, 5000, 10000, 0, 10000, none, 0)),
        keep(feel_periodic(dev, FEEL_WAVEFORM_SINE, 1000, 0, 0, 10000, FEEL_INFINITE, 0, none, 0)),
        keep(feel_envelope_periodic(dev, FEEL_WAVEFORM_SQUARE, 1000, 0, 0, 10000, 100000, 0, 5000, 10000, 0, 10000, none, 0)),
        keep(feel_delayed_periodic(dev, 10000, FEEL_WAVEFORM_TRIANGLE, 1000, 0, 0, 10000, 100000, 0, none, 0)),
        keep(feel_sweep_periodic(dev, 0, 9000, FEEL_SWEEP_CLOCKWISE, FEEL_WAVEFORM_SAW_UP, 1000, 0, 10000, 0, 100000)),
        keep(feel_dynamic_recoil(dev, 0, 3000, 5000, 5000, 500)),
        keep(feel_dynamic_impact(dev, 9000, 3000, 5000, 5000, 500)),
        keep(feel_dynamic_liquid(dev, 5000, 3000, 500)),
        keep(feel_dynamic_inertia(dev, 5000, 200)),
        keep(feel_dynamic_center_drift(dev, 5000, 5000)),
        keep(feel_dynamic_sling(dev, 5000, 1000, 5000, 200, true)),
        keep(feel_dynamic_paddle(dev, 3000, 5000, 0, 5000, 200, 0, true)),
        keep(feel_dynamic_control_law(dev, 5000, 5000, 5000, 500, 0, 0, 0, 0, 0, 0, false, FEEL_AXIS_Y)),
    };
    int i = 0;
    for (const bool ok : made) {
        EXPECT_TRUE(ok) << "wrapper #" << i << ": " << errors[static_cast<size_t>(i)];
        ++i;
    }
    EXPECT_EQ(i, 43);
}

TEST(CapiEffect, AFullDeviceSaysSo) {
    DevicePtr d = open_device();
    ASSERT_TRUE(d);
    feel_caps caps{};
    caps.size = sizeof caps;
    ASSERT_EQ(feel_device_caps(d.get(), &caps), FEEL_OK);
    std::vector<feel_effect*> effects;
    for (int i = 0; i < caps.effect_slots; ++i) {
        effects.push_back(feel_x_spring(d.get(), 100, 100, 0, 10000, 10000, 0));
        ASSERT_NE(effects.back(), nullptr) << i << ": " << last_message();
    }
    EXPECT_EQ(feel_x_spring(d.get(), 100, 100, 0, 10000, 10000, 0), nullptr);
    EXPECT_EQ(feel_last_error(), FEEL_ERROR_DEVICE_FULL) << last_message();
    feel_effect_destroy(effects.back());  // frees a block
    effects.back() = feel_x_spring(d.get(), 100, 100, 0, 10000, 10000, 0);
    EXPECT_NE(effects.back(), nullptr) << last_message();
    for (feel_effect* e : effects) feel_effect_destroy(e);
}

TEST(CapiEffect, ADynamicOnAnIForce1DeviceIsRenderedByTheHost) {
    DevicePtr d = open_device("sim:iforce1");
    ASSERT_TRUE(d);
    feel_caps caps{};
    caps.size = sizeof caps;
    ASSERT_EQ(feel_device_caps(d.get(), &caps), FEEL_OK);
    ASSERT_EQ(caps.supported_types & FEEL_TYPE_BIT(FEEL_TYPE_DYNAMIC_IMPACT), 0u);  // not the device's
    feel_effect* impact = feel_dynamic_impact(d.get(), 0, 3000, 5000, 5000, 500);
    ASSERT_NE(impact, nullptr) << last_message();
    feel_effect_status_info st{};
    st.size = sizeof st;
    ASSERT_EQ(feel_effect_status(impact, &st), FEEL_OK) << last_message();
    EXPECT_TRUE(st.emulated);
    feel_effect_destroy(impact);
}

TEST(CapiLibrary, ALibrarysDeviceIsClosedByTheLibraryNotByFeelClose) {
    feel_library* lib = feel_library_load(FEEL_SOURCE_DIR "/examples/conditions.feel.json", "sim:iforce2");
    ASSERT_NE(lib, nullptr) << last_message();
    feel_device* dev = feel_library_device(lib);
    ASSERT_NE(dev, nullptr);
    feel_close(dev);
    EXPECT_EQ(feel_last_error(), FEEL_ERROR_INVALID_PARAMETER);
    EXPECT_EQ(last_message(), "feel_close: this device belongs to a library; feel_library_free closes it");
    feel_caps caps{};
    caps.size = sizeof caps;
    EXPECT_EQ(feel_device_caps(dev, &caps), FEEL_OK);  // still open
    feel_input in{};
    in.size = sizeof in;
    EXPECT_EQ(feel_poll_input(dev, &in), FEEL_OK) << last_message();
    feel_library_free(lib);
    EXPECT_EQ(feel_library_device(nullptr), nullptr);
    EXPECT_EQ(last_message(), "feel_library_device: library is NULL");
}

}  // namespace
