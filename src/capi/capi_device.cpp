// feel.h: devices — open, close, capabilities, gain, commands, input, force streaming.
#include <chrono>
#include <cstdio>
#include <cstdint>
#include <span>
#include <utility>

#include "capi_internal.hpp"

namespace feel::capi {
namespace {

feel_caps caps_of(const host::DeviceCaps& c) noexcept {
    feel_caps out{};
    copy_string(out.device, c.device);
    copy_string(out.description, c.description);
    copy_string(out.class_name, c.class_name);
    copy_string(out.firmware_version, c.firmware_version);
    copy_string(out.protocol_version, c.protocol_version);
    out.device_class = static_cast<int32_t>(c.device_class);
    out.axis_count = c.axis_count;
    for (int i = 0; i < kMaxAxes; ++i) {
        out.axes[i].axis = axis_index(c.axes[i].axis);
        out.axes[i].rotary = c.axes[i].rotary;
        out.axes[i].half_travel = c.axes[i].half_travel;
        out.axes[i].max_force = c.axes[i].max_force;
        out.axes[i].sensor_counts = c.axes[i].sensor_counts;
    }
    out.button_count = c.button_count;
    out.hat_count = c.hat_count;
    out.dead_man_switch = c.dead_man_switch;
    out.max_force = c.max_force;
    out.supported_types = c.supported_types;
    out.effect_slots = c.effect_slots;
    out.pool_bytes = c.pool_bytes;
    out.sample_memory = c.sample_memory;
    out.local_reflexes = c.local_reflexes;
    out.interim_reports = c.interim_reports;
    out.loop_rate_hz = c.loop_rate_hz;
    out.max_loop_rate_hz = c.max_loop_rate_hz;
    out.interim_report_hz = c.interim_report_hz;
    out.report_rate_hz = c.report_rate_hz;
    return out;
}

feel_input input_of(const host::InputState& s) noexcept {
    feel_input out{};
    out.t_us = s.t_us;
    out.axis_count = s.axis_count;
    for (int i = 0; i < kMaxAxes; ++i) {
        out.position[i] = s.position[i];
        out.velocity[i] = s.velocity[i];
        out.force[i] = s.force[i];
    }
    out.buttons = s.buttons;
    out.hats = s.hats;
    out.handle_held = s.handle_held;
    out.hands_off = s.hands_off;
    out.host_lost = s.host_lost;
    out.fade_level = s.fade_level;
    out.paused = s.paused;
    out.actuators_enabled = s.actuators_enabled;
    out.gain = s.gain;
    out.playing_effects = s.playing_effects;
    out.resident_effects = s.resident_effects;
    out.loop_rate_hz = s.loop_rate_hz;
    out.measured_loop_hz = s.measured_loop_hz;
    out.overruns = s.overruns;
    out.dropped_reports = s.dropped_reports;
    out.reports_received = s.reports_received;
    return out;
}

// The C enumeration of device commands is runtime::DeviceControl's order.
static_assert(static_cast<int>(runtime::DeviceControl::actuators_on) == FEEL_COMMAND_ACTUATORS_ON);
static_assert(static_cast<int>(runtime::DeviceControl::actuators_off) == FEEL_COMMAND_ACTUATORS_OFF);
static_assert(static_cast<int>(runtime::DeviceControl::stop_all) == FEEL_COMMAND_STOP_ALL);
static_assert(static_cast<int>(runtime::DeviceControl::reset) == FEEL_COMMAND_RESET);
static_assert(static_cast<int>(runtime::DeviceControl::pause) == FEEL_COMMAND_PAUSE);
static_assert(static_cast<int>(runtime::DeviceControl::resume) == FEEL_COMMAND_RESUME);
static_assert(runtime::kDeviceControlCount == FEEL_COMMAND_RESUME + 1);

static_assert(static_cast<int>(sim::DeviceClass::iforce1) == FEEL_DEVICE_CLASS_IFORCE1);
static_assert(static_cast<int>(sim::DeviceClass::iforce2) == FEEL_DEVICE_CLASS_IFORCE2);
static_assert(FEEL_MAX_AXES == kMaxAxes);
static_assert(FEEL_INFINITE == kInfiniteUs);
static_assert(FEEL_INFINITE_ITERATIONS == kInfiniteIterations);
static_assert(FEEL_EFFECT_ITERATIONS == runtime::kEffectIterations);

}  // namespace
}  // namespace feel::capi

using namespace feel::capi;

extern "C" {

feel_device* feel_open(const char* address) {
    return guard_ptr<feel_device>("feel_open", [&]() -> feel_device* {
        const std::string_view where = address && *address ? address : "sim:iforce2";
        feel::host::Result<feel::host::Device> device = feel::host::Device::open(where);
        if (!device) {
            fail(device.status());
            return nullptr;
        }
        return new feel_device{std::move(device).value(), false};
    });
}

feel_device* feel_open_ex(const char* address, const feel_open_options* options) {
    return guard_ptr<feel_device>("feel_open_ex", [&]() -> feel_device* {
        feel_open_options in{};
        if (read_in("feel_open_ex", "options", options, in) != FEEL_OK) return nullptr;
        feel::host::OpenOptions o;
        if (in.timeout_ms != 0) o.timeout = std::chrono::milliseconds(in.timeout_ms);
        o.report_rate_hz = in.report_rate_hz;
        if (in.sim_hand) o.sim_hand = in.sim_hand;
        if (in.sim_motion) o.sim_motion = in.sim_motion;
        const std::string_view where = address && *address ? address : "sim:iforce2";
        feel::host::Result<feel::host::Device> device = feel::host::Device::open(where, o);
        if (!device) return no_handle(fail(device.status()));
        return new feel_device{std::move(device).value(), false};
    });
}

void feel_close(feel_device* device) {
    (void)guard("feel_close", [&] {
        if (!device) return succeed();
        if (device->borrowed) {
            return fail(FEEL_ERROR_INVALID_PARAMETER,
                        "feel_close: this device belongs to a library; feel_library_free closes it");
        }
        device->device.close();
        delete device;
        return succeed();
    });
}

int feel_device_caps(const feel_device* device, feel_caps* out) {
    return guard("feel_device_caps", [&] {
        if (!device) return null_argument("feel_device_caps", "device");
        if (const int rc = check_out("feel_device_caps", "out", out); rc != FEEL_OK) return rc;
        write_out(caps_of(device->device.capabilities()), out);
        return succeed();
    });
}

int feel_set_gain(feel_device* device, int32_t gain) {
    return guard("feel_set_gain", [&] {
        if (!device) return null_argument("feel_set_gain", "device");
        return from_status(device->device.set_gain(gain));
    });
}

int feel_device_command(feel_device* device, int32_t command) {
    return guard("feel_device_command", [&] {
        if (!device) return null_argument("feel_device_command", "device");
        if (command < FEEL_COMMAND_ACTUATORS_ON || command > FEEL_COMMAND_RESUME) {
            return out_of_range("feel_device_command", "command", command, FEEL_COMMAND_ACTUATORS_ON,
                                FEEL_COMMAND_RESUME);
        }
        return from_status(device->device.command(static_cast<feel::runtime::DeviceControl>(command)));
    });
}

int feel_poll_input(feel_device* device, feel_input* out) {
    return guard("feel_poll_input", [&] {
        if (!device) return null_argument("feel_poll_input", "device");
        if (const int rc = check_out("feel_poll_input", "out", out); rc != FEEL_OK) return rc;
        if (!device->device.connected()) {
            return fail(FEEL_ERROR_DISCONNECTED, "feel_poll_input: the device is not connected");
        }
        write_out(input_of(device->device.input()), out);
        return succeed();
    });
}

int feel_wait_input(feel_device* device, int32_t timeout_ms, feel_input* out) {
    return guard("feel_wait_input", [&] {
        if (!device) return null_argument("feel_wait_input", "device");
        if (const int rc = check_out("feel_wait_input", "out", out); rc != FEEL_OK) return rc;
        if (timeout_ms < 1 || timeout_ms > 60000) {
            return out_of_range("feel_wait_input", "timeout_ms", timeout_ms, 1, 60000);
        }
        feel::host::Result<feel::host::InputState> s =
            device->device.wait_input(std::chrono::milliseconds(timeout_ms));
        if (!s) return fail(s.status());
        write_out(input_of(s.value()), out);
        return succeed();
    });
}

feel_input_subscription* feel_subscribe_input(feel_device* device, uint32_t capacity) {
    return guard_ptr<feel_input_subscription>("feel_subscribe_input", [&]() -> feel_input_subscription* {
        if (!device) return no_handle(null_argument("feel_subscribe_input", "device"));
        if (capacity < 1 || capacity > 1000000) {
            return no_handle(out_of_range("feel_subscribe_input", "capacity", capacity, 1, 1000000));
        }
        feel::host::Result<feel::host::InputSubscription> sub = device->device.subscribe_input(capacity);
        if (!sub) return no_handle(fail(sub.status()));
        auto* out = new feel_input_subscription{};
        out->subscription = std::move(sub.value());
        return out;
    });
}

int feel_input_subscription_wait(feel_input_subscription* subscription, int32_t timeout_ms, feel_input* reports,
                                 int32_t max_reports, int32_t* count, uint64_t* dropped) {
    return guard("feel_input_subscription_wait", [&] {
        const char* fn = "feel_input_subscription_wait";
        if (!subscription) return null_argument(fn, "subscription");
        if (!count) return null_argument(fn, "count");
        *count = 0;
        if (const int rc = check_out(fn, "reports", reports); rc != FEEL_OK) return rc;
        if (max_reports < 1) return out_of_range(fn, "max_reports", max_reports, 1, INT32_MAX);
        if (timeout_ms < 0 || timeout_ms > 60000) return out_of_range(fn, "timeout_ms", timeout_ms, 0, 60000);
        if (subscription->pending.empty()) {
            feel::host::Result<feel::host::InputBatch> batch =
                subscription->subscription.wait(std::chrono::milliseconds(timeout_ms));
            if (!batch) return fail(batch.status());
            subscription->dropped += batch->dropped;
            subscription->pending.assign(batch->reports.begin(), batch->reports.end());
        }
        // The caller's struct size is the array's stride.
        const uint32_t stride = reports->size;
        auto* base = reinterpret_cast<unsigned char*>(reports);
        int32_t n = 0;
        while (n < max_reports && !subscription->pending.empty()) {
            auto* out = reinterpret_cast<feel_input*>(base + static_cast<size_t>(n) * stride);
            out->size = stride;
            write_out(input_of(subscription->pending.front()), out);
            subscription->pending.pop_front();
            ++n;
        }
        *count = n;
        if (dropped) *dropped = std::exchange(subscription->dropped, 0);
        return succeed();
    });
}

void feel_unsubscribe_input(feel_input_subscription* subscription) {
    (void)guard("feel_unsubscribe_input", [&] {
        delete subscription;  // the subscription's destructor unsubscribes
        return succeed();
    });
}

int feel_stream_force(feel_device* device, const int32_t* force, int32_t axis_count) {
    return guard("feel_stream_force", [&] {
        if (!device) return null_argument("feel_stream_force", "device");
        if (!force) return null_argument("feel_stream_force", "force");
        const int32_t axes = device->device.capabilities().axis_count;
        if (axis_count != axes) {
            return out_of_range("feel_stream_force", "axis_count", axis_count, axes, axes);
        }
        return from_status(device->device.stream_force(std::span<const int32_t>(force, static_cast<size_t>(axis_count))));
    });
}

int feel_device_effect_types(const feel_device* device, uint64_t* types) {
    return guard("feel_device_effect_types", [&] {
        if (!device) return null_argument("feel_device_effect_types", "device");
        if (!types) return null_argument("feel_device_effect_types", "types");
        uint64_t bits = 0;
        for (const feel::host::EffectSupport& e : device->device.effects()) bits |= feel::effect_type_bit(e.type);
        *types = bits;
        return succeed();
    });
}

int feel_device_pool(feel_device* device, feel_pool_info* out) {
    return guard("feel_device_pool", [&] {
        if (!device) return null_argument("feel_device_pool", "device");
        if (const int rc = check_out("feel_device_pool", "out", out); rc != FEEL_OK) return rc;
        feel::host::Result<feel::PoolInfo> pool = device->device.pool();
        if (!pool) return fail(pool.status());
        const feel::PoolInfo& p = pool.value();
        feel_pool_info info{};
        info.total_bytes = p.total_bytes;
        info.free_bytes = p.free_bytes;
        info.max_effects = p.max_effects;
        info.free_effects = p.free_effects;
        info.total_samples = p.total_samples;
        info.free_samples = p.free_samples;
        write_out(info, out);
        return succeed();
    });
}

int feel_device_address(const feel_device* device, char* out, int32_t capacity) {
    return guard("feel_device_address", [&] {
        if (!device) return null_argument("feel_device_address", "device");
        if (!out) return null_argument("feel_device_address", "out");
        if (capacity < 1) return out_of_range("feel_device_address", "capacity", capacity, 1, INT32_MAX);
        std::snprintf(out, static_cast<std::size_t>(capacity), "%s", device->device.address().c_str());
        return succeed();
    });
}

bool feel_device_connected(const feel_device* device) {
    bool connected = false;
    (void)guard("feel_device_connected", [&] {
        if (!device) return null_argument("feel_device_connected", "device");
        connected = device->device.connected();
        return succeed();
    });
    return connected;
}

int feel_set_idf(feel_device* device, bool periodic, bool impulse) {
    return guard("feel_set_idf", [&] {
        if (!device) return null_argument("feel_set_idf", "device");
        return from_status(device->device.set_idf(feel::runtime::IdfSettings{periodic, impulse}));
    });
}

int feel_set_report_rate(feel_device* device, int32_t hz) {
    return guard("feel_set_report_rate", [&] {
        if (!device) return null_argument("feel_set_report_rate", "device");
        return from_status(device->device.set_report_rate(hz));
    });
}

}  // extern "C"
