// Helpers of the host API tests: a simulated device the test can reach (to press its
// buttons), polling with a deadline, and the safety fade-in wait.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "feel/host/device.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/transport/transport.hpp"

namespace feel::host::test {

using namespace std::chrono_literals;

// Polls `done` every 2 ms until it holds or `limit` passes; returns whether it held.
inline bool wait_until(const std::function<bool()>& done, std::chrono::milliseconds limit = 2000ms) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return done();
}

// Waits until the device's safety fade-in is complete (forces pass at full scale).
inline bool wait_for_full_force(Device& device) {
    return wait_until([&] { return device.input().fade_level >= 0.999f && device.input().handle_held; }, 3000ms);
}

// A spring on x of coefficient k both ways, centred, saturating at full scale, forever.
inline EffectParams spring_x(int32_t k) {
    EffectParams p;
    p.type = EffectType::spring;
    p.duration_us = kInfiniteUs;
    p.conditions[0] = ConditionBlock{k, k, 0, 10000, 10000, 0};
    return p;
}

// Open options for a device that reports its input state every millisecond.
inline OpenOptions fast_reports() {
    OpenOptions o;
    o.report_rate_hz = 1000;
    return o;
}

// The input state two full report rounds from now (so that it reflects what was just sent).
inline InputState settled(Device& dev) {
    for (int i = 0; i < 20; ++i) (void)dev.wait_input(100ms);
    return dev.input();
}

// A simulated device served over an in-process connection, with the Peripheral kept where
// the test can reach it (Device::open("sim:...") owns its Peripheral privately).
struct SimRig {
    std::unique_ptr<peripheral::Peripheral> device;
    std::optional<Device> host;  // declared after the device: closed first

    static SimRig make(const std::string& profile, const std::string& hand = "firm",
                       const std::string& motion = "hold:0", OpenOptions options = {}) {
        peripheral::PeripheralOptions po;
        po.profile = profile;
        po.hand = hand;
        po.motion = motion;
        po.runtime.realtime_priority = false;
        po.runtime.lock_memory = false;
        SimRig rig;
        rig.device = std::make_unique<peripheral::Peripheral>(po);
        transport::ConnectionPair pair = transport::in_process_pair("sim:" + profile);
        rig.device->attach(std::move(pair.device));
        Result<Device> opened = Device::attach(std::move(pair.host), "sim:" + profile, options);
        if (!opened) ADD_FAILURE() << opened.status().message;
        else rig.host.emplace(std::move(opened.value()));
        return rig;
    }

    // Presses the buttons of `mask` (bit i = button i+1) on the simulated device.
    void set_buttons(uint32_t mask) { EXPECT_TRUE(device->set_buttons(mask)); }
};

}  // namespace feel::host::test
