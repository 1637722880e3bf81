// feel::peripheral — the simulated device as a USB-like peripheral.
//
// A Peripheral is what sits at the far end of the cable: the device runtime (the primer's
// local processor, feel/runtime/device_runtime.hpp) on its simulated device and hand,
// plus its "USB side": a service thread that reads the host's reports from a transport
// Connection, turns them into runtime commands (DeviceSession), and sends the runtime's
// acks, state and dynamics' reports back as HID input reports (docs/protocol.md).
//
//   host process                         device process (`feel device --sim`) or in-process
//   ------------                         ---------------------------------------------------
//   feel::host::Device --Connection--> Peripheral: service thread -> DeviceSession
//                                                    -> SPSC queues -> 1 kHz RealtimeLoop
//
// One host at a time, like a USB device: a second connection while a host is attached gets
// a `busy` frame and is closed (one that arrives while the last host's teardown runs waits
// for it, up to 250 ms). When the host goes away (disconnect, or no frame for the safety
// watchdog's time, which detaches it), the device is reset: every effect stopped and freed;
// the next host finds a reset device. Guarantees and their figures: docs/peripheral.md.
//
// Threads. The constructor builds and starts the runtime's loop; attach() and serve() start
// service threads; stop() and the destructor join them. Every public call is for one owner
// thread (a CLI's main, a test), except stats(), capabilities() and host_attached(), which
// any thread may call. Nothing here runs on the real-time loop.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "feel/runtime/capabilities.hpp"
#include "feel/runtime/device_runtime.hpp"
#include "feel/sim/hand.hpp"
#include "feel/transport/transport.hpp"

namespace feel::peripheral {

struct PeripheralOptions {
    std::string profile = "iforce2";   // a device profile name (feel devices)
    std::string hand = "firm";         // none, loose, firm, stiff, kinematic (sim::Grip)
    std::string motion = "hold:0";     // the hand's target motion (feel render --motion)
    int32_t loop_rate_hz = 0;          // 0: the profile's default; else 100..20000
    runtime::DeviceRuntimeOptions runtime{};  // SCHED_FIFO / mlockall wishes
    // The service thread that sends the loop's reports to the host: 1..99 runs it under
    // SCHED_FIFO at that priority where the process may (feel/transport/thread_priority.hpp;
    // below the loop's, runtime.fifo_priority); 0: an ordinary thread.
    int32_t service_fifo_priority = 0;
    // false: the transport says when the host goes (USB: unplug, bus reset, unbind end the
    // connection), so silence is not loss: no host-link watchdog, neither the detach of a
    // silent host nor the runtime's fade. A standard PID host (hid-pidff) sends nothing
    // while its effects play and has no keep-alive.
    bool host_watchdog = true;
    // true: the device plays only the effect types HID PID 1.0 has (constant, ramp, the
    // five periodic waves, spring, damper, inertia, friction, custom force), as a standard
    // PID wheel or stick does; it refuses every other type (walls, barriers, textures,
    // sweeps, smart pop, vector force, angle conditions, Dynamics) with not_supported, its
    // Device Info says so, and it runs no reflexes. A feel host then renders those types
    // itself (host emulation, docs/real-devices.md). The session's own vendor reports
    // (sequence, Command Status, Device Info, Device Status, force streaming) stay; for a
    // device with PID's reports alone, see standard_pid_only.
    bool pid_effects_only = false;
    // true: the device is a plain USB HID PID device, with no vendor report at all
    // (protocol/standard_pid.hpp): its descriptor holds only PID's reports with only PID's
    // fields and the joystick's Input report, it plays PID's eleven effect types (as
    // pid_effects_only, without custom forces), runs no reflexes, and sends nothing but
    // Joystick Input, PID State and the PID feature replies (no Command Status, Device
    // Info, Device Status, dynamics' reports). A host drives it through PID's reports alone
    // (hid-pidff, feel::host::PidDevice). attach() translates the host's standard reports
    // to feel's and back (HostReports::presented); the USB gadget does so at its endpoints.
    bool standard_pid_only = false;
};

// What a connection given to Peripheral::attach() carries: the reports of the device as it
// presents itself (the standard PID form when standard_pid_only: the Peripheral
// translates), or feel's own form already (a transport that translates at its own edge, as
// the USB gadget does so that its log reads feel's reports).
enum class HostReports : uint8_t { presented, feel_form };

// The effect types of HID PID 1.0 (effect_type_bit() of each).
[[nodiscard]] uint64_t pid_effect_types() noexcept;

struct PeripheralStats {
    runtime::DeviceRuntimeStats runtime{};
    uint64_t hosts_served = 0;       // connections attached since construction
    uint64_t reports_received = 0;   // host reports decoded
    uint64_t reports_refused = 0;    // of those, answered with an error status
    uint64_t frames_sent = 0;
    uint64_t reports_dropped = 0;    // state reports a slow host missed (send_or_drop)
    uint64_t hosts_silent = 0;       // hosts detached for sending nothing for the watchdog time
    uint64_t hosts_dropped = 0;      // hosts dropped for bad frames, a stalled partial frame or not reading
    bool host_attached = false;
};

class Peripheral {
public:
    // Builds the device and starts its loop. Throws std::invalid_argument naming the option
    // that is wrong (an unknown profile lists the known ones).
    explicit Peripheral(const PeripheralOptions& options);
    // Detaches the host (its connection is closed), stops the service threads and the loop.
    ~Peripheral();
    Peripheral(const Peripheral&) = delete;
    Peripheral& operator=(const Peripheral&) = delete;

    // Serves one host over this connection on a service thread until the host disconnects
    // or stop(). While a host is attached, a new connection gets `busy` and is closed.
    void attach(std::unique_ptr<transport::Connection> host, HostReports form = HostReports::presented);
    // Accepts hosts from the listener on a thread of its own until stop(), attaching each.
    void serve(std::unique_ptr<transport::Listener> listener);
    // Stops accepting, detaches the host, joins the threads; the loop keeps running until
    // destruction. Harmless when already stopped.
    void stop();

    [[nodiscard]] bool host_attached() const noexcept;
    // PeripheralOptions::standard_pid_only: the device presents itself as a plain PID device.
    [[nodiscard]] bool standard_pid_only() const noexcept;
    [[nodiscard]] const runtime::Capabilities& capabilities() const noexcept;
    [[nodiscard]] PeripheralStats stats() const noexcept;
    // Where serve() listens (valid after serve()).
    [[nodiscard]] transport::Address address() const;

    // The simulated hand presses buttons (bit i = button i+1) or pushes hat switches off
    // center (bit h-1 = hat h); the loop sees it at its next tick. Any thread. False, and
    // nothing changes, for a control the profile lacks.
    bool set_buttons(uint32_t pressed) noexcept;
    bool set_hats(uint32_t pushed) noexcept;
    // The simulated hand's live target (SimBackend::set_hand_target): the hand pulls the
    // handle toward these normalized positions instead of following its motion. Any thread.
    bool set_hand_target(int32_t x, int32_t y, int32_t z) noexcept;
    // The device time (µs) at which the loop took the newest live target, -1 before the
    // first (SimBackend::hand_target_taken_us). Any thread.
    [[nodiscard]] int64_t hand_target_taken_us() const noexcept;
    // Another grip for the simulated hand (SimBackend::set_grip). Any thread.
    void set_grip(sim::Grip grip) noexcept;

    // The device's runtime, e.g. for a test to reach the simulated device while the loop is
    // stopped (runtime().stop(); ...; runtime().start()).
    [[nodiscard]] runtime::DeviceRuntime& runtime() noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Opens an in-process simulated device and returns the host's end of its connection: the
// Peripheral lives as long as the returned connection (the connection owns it). What
// feel::host::Device::open("sim:PROFILE") uses.
[[nodiscard]] std::unique_ptr<transport::Connection> open_in_process(const PeripheralOptions& options);

}  // namespace feel::peripheral
