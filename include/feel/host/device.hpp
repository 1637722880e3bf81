// feel::host — the host API: what a game links to talk to a feel device.
//
// In the spirit of DirectInput (§7) and SDL haptic: enumerate devices, open one, read its
// capabilities, enumerate the effects it plays, create effects as RAII handles, download,
// start, stop, ask their status, change their parameters; set the device gain, send device
// commands, poll the input state, subscribe to dynamics' reports, stream forces.
//
//   auto dev = feel::host::Device::open("sim:iforce2");     // or "unix:PATH", "tcp:HOST:PORT"
//   if (!dev) { log(dev.status().message); return; }
//   auto spring = dev->create_effect(feel::iforce::x_spring(1000, 1000, 0, 10000, 10000, 0));
//   spring->start();                                       // plays until stopped
//
// The host validates every effect against the device's capabilities and ranges before any
// byte leaves (a portable core that checks once, over the wire protocol of
// docs/protocol.md); the device checks again and its answer is final.
//
// Host emulation (§1.2.c). Where the device lacks a feature the host can provide, the host
// provides it and the effect's status says `emulated`. Today: trigger-button reflexes on a
// device without local reflexes (an I-FORCE 1.x-class profile): the effect goes down
// without its trigger, and the host watches the buttons and hats in the device's input
// reports and starts it itself on each press (and every trigger_repeat_interval_us while
// held). The latency is then up to one report period plus one round trip instead of zero
// ticks: about 4 ms (8 ms worst) in process, docs/host-api.md, "Host emulation".
//
// Threads. A Device and its Effects may be used from any one thread at a time (calls are
// serialized inside; each waits for the device's answer, up to OpenOptions::timeout). Each
// open device has one I/O thread that reads the device's reports, keeps the latest input
// state, runs host emulation and calls subscribers; callbacks run on that thread and must
// not call back into the Device (queue the work instead). Nothing here is real-time safe.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "feel/effect.hpp"
#include "feel/engine.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/host/result.hpp"
#include "feel/runtime/idf.hpp"
#include "feel/runtime/runtime_messages.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::transport {
class Connection;
}

namespace feel::host {

struct DeviceCore;    // shared by a Device and its Effects (private)
struct EffectRecord;  // what the host keeps of one effect (private)

// ---------------------------------------------------------------------------------------
// Discovery.

struct DeviceInfo {
    std::string address;      // what Device::open takes: "sim:iforce2", "unix:/run/user/1000/feel/sim.sock"
    std::string device;       // the profile name, e.g. "iforce2"
    std::string description;  // one line about the hardware
    std::string class_name;   // "I-FORCE 1.x", "I-FORCE 2.0"
    bool in_process = false;  // a simulated device this process would run itself
};

struct EnumerateOptions {
    bool in_process = true;   // list one in-process simulated device per profile
    // Directories whose Unix sockets are probed (a device answers its DeviceInfo).
    // Empty: transport::default_socket_dir().
    std::vector<std::string> socket_dirs;
    std::chrono::milliseconds timeout{300};  // per socket probed
};

// The devices a host could open: in-process simulated devices first, then the devices
// listening in the socket directories. Sockets that do not answer are skipped.
[[nodiscard]] std::vector<DeviceInfo> enumerate_devices(const EnumerateOptions& options = {});

// ---------------------------------------------------------------------------------------
// Capabilities (GetCapabilities §7.4, EnumEffects §6.2).

struct AxisCaps {
    Axis axis = Axis::x;
    bool rotary = false;      // linear: m and N; rotary: rad and N·m
    double half_travel = 0;   // m or rad at position ±10000
    double max_force = 0;     // N or N·m at force ±10000
    int32_t sensor_counts = 0;
};

struct DeviceCaps {
    std::string device, description, class_name, firmware_version, protocol_version;
    sim::DeviceClass device_class = sim::DeviceClass::iforce2;
    int32_t axis_count = 0;          // 1..6: x, y, z, rx, ry, rz in order
    AxisCaps axes[kMaxAxes] = {};
    int32_t button_count = 0;        // 0..32
    int32_t hat_count = 0;           // 0..4
    bool dead_man_switch = false;
    int32_t max_force = kFullScale;  // normalized force at each axis's max_force
    uint64_t supported_types = 0;    // effect_type_bit(t): types the device plays itself
    int32_t effect_slots = 0;
    int32_t pool_bytes = 0;
    int32_t sample_memory = 0;
    bool local_reflexes = false;     // false: the host emulates reflexes
    bool interim_reports = false;
    int32_t loop_rate_hz = 0;
    int32_t max_loop_rate_hz = 0;
    double interim_report_hz = 0;
    int32_t report_rate_hz = 0;      // state reports now

    [[nodiscard]] bool supports(EffectType t) const noexcept { return (supported_types & effect_type_bit(t)) != 0; }
};

// One entry of Device::effects(): a type the host can create on this device.
struct EffectSupport {
    EffectType type = EffectType::constant;
    EffectClass effect_class = EffectClass::wave;
};

// ---------------------------------------------------------------------------------------
// Input and reports.

// The device's latest state, from its input reports (no round trip to read it).
struct InputState {
    int64_t t_us = 0;                  // device time of the newest report, µs
    int32_t axis_count = 0;
    float position[kMaxAxes] = {};     // reported position (IDF, clipping), ±10000
    float velocity[kMaxAxes] = {};     // handle velocity, units/s
    uint32_t buttons = 0;              // bit i = button i+1
    uint32_t hats = 0;                 // bit h-1 = hat h off center
    float force[kMaxAxes] = {};        // what the motors got, ±10000
    bool handle_held = false;          // dead-man switch
    bool hands_off = false;            // the device detected a free handle: forces faded out
    bool host_lost = false;            // the device's host watchdog tripped
    float fade_level = 0;              // safety fade, 0..1
    bool paused = false;
    bool actuators_enabled = true;
    int32_t gain = kFullScale;
    int32_t playing_effects = 0;
    int32_t resident_effects = 0;
    int32_t loop_rate_hz = 0;          // the device loop's nominal rate
    double measured_loop_hz = 0;       // ticks per second over the device's last second
    uint64_t overruns = 0;             // device loop overruns since it started
    uint64_t dropped_reports = 0;      // reports the device could not send
    uint64_t reports_received = 0;     // input reports this host read
};

// A dynamic's interim or final report (§5.2), for one effect.
struct DynamicEvent {
    DynamicReport::Kind kind = DynamicReport::Kind::interim;
    int64_t t_us = 0;
    int32_t axis_count = 0;                  // the effect's axes, in its order
    float position[kMaxAxes] = {};           // mass minus handle, position units
    float velocity[kMaxAxes] = {};           // mass minus handle, units/s
    float handle_velocity[kMaxAxes] = {};    // the handle's, units/s
};
using DynamicCallback = std::function<void(const DynamicEvent&)>;

// Unsubscribes when destroyed (or reset()).
class Subscription {
public:
    Subscription() = default;
    Subscription(Subscription&&) noexcept;
    Subscription& operator=(Subscription&&) noexcept;
    ~Subscription();
    void reset() noexcept;
    [[nodiscard]] bool active() const noexcept { return id_ != 0; }

private:
    friend class Device;
    friend class Effect;
    Subscription(std::weak_ptr<DeviceCore> core, uint64_t id) : core_(std::move(core)), id_(id) {}
    std::weak_ptr<DeviceCore> core_;
    uint64_t id_ = 0;
};

// Every state round the device reports, in order (Device::subscribe_input): what a
// subscriber's queue held when it was taken.
struct InputBatch {
    std::vector<InputState> reports;  // oldest first
    // Rounds lost since the previous batch because the queue was full (the oldest go
    // first: `reports` then starts after a gap). 0 when nothing was lost.
    uint64_t dropped = 0;
    [[nodiscard]] bool overflowed() const noexcept { return dropped != 0; }
};

struct InputQueue;  // one subscriber's bounded queue (private)

// A per-report subscription to a device's input (Device::subscribe_input). The device's
// I/O thread appends every complete state round (joystick report and device status) to
// this subscriber's queue, a ring of fixed capacity allocated at subscription: memory
// never grows. When the ring is full the oldest round is dropped and counted; the next
// batch says how many went. Unsubscribes when destroyed (or reset()). Thread-safe: take()
// and wait() may be called from any thread, one or several (each round goes to exactly one
// of the callers); the I/O thread never waits for a subscriber.
class InputSubscription {
public:
    InputSubscription() = default;
    InputSubscription(InputSubscription&&) noexcept;
    InputSubscription& operator=(InputSubscription&&) noexcept;
    ~InputSubscription();
    void reset() noexcept;
    [[nodiscard]] bool active() const noexcept { return queue_ != nullptr; }

    // What is queued now; never blocks (beyond the queue's lock, held for a copy).
    [[nodiscard]] InputBatch take();
    // Blocks until at least one round is queued, then takes the queue as take() does.
    // Errors: timeout (nothing within `timeout`), disconnected (nothing queued and the
    // device is gone), invalid_handle (an empty subscription). A zero timeout never blocks.
    [[nodiscard]] Result<InputBatch> wait(std::chrono::milliseconds timeout);
    [[nodiscard]] size_t capacity() const noexcept;
    // Rounds dropped for a full queue since the subscription began.
    [[nodiscard]] uint64_t dropped_total() const;

private:
    friend class Device;
    InputSubscription(std::weak_ptr<DeviceCore> core, std::shared_ptr<InputQueue> queue)
        : core_(std::move(core)), queue_(std::move(queue)) {}
    std::weak_ptr<DeviceCore> core_;
    std::shared_ptr<InputQueue> queue_;
};

// What Effect::status() tells (GetEffectStatus, and more).
struct EffectStatusInfo {
    runtime::ReportedEffectState state = runtime::ReportedEffectState::stopped;
    bool emulated = false;          // the host plays (part of) it on the device's behalf
    int32_t iterations = 0;         // of the current or last play; kInfiniteIterations
    int32_t completed_iterations = 0;
    int64_t elapsed_us = 0;
    PlayEnd last_end = PlayEnd::none;
};

// ---------------------------------------------------------------------------------------
// Effects.

// One effect on a device: an RAII handle (destroying it frees the device's block). Move-
// only. A default-constructed or moved-from Effect is empty: its calls return invalid_handle.
class Effect {
public:
    Effect() = default;
    Effect(Effect&&) noexcept;
    Effect& operator=(Effect&&) noexcept;
    ~Effect();  // unload(), errors ignored

    [[nodiscard]] bool valid() const noexcept;
    [[nodiscard]] bool downloaded() const noexcept;
    [[nodiscard]] EffectType type() const noexcept;
    [[nodiscard]] const EffectParams& parameters() const noexcept;
    [[nodiscard]] uint16_t block() const noexcept;  // the device's effect block, 0 if none
    [[nodiscard]] bool emulated() const noexcept;   // part of it is host-emulated

    // Downloads it (again) after unload(). Device::create_effect downloads already.
    Status download();
    // Frees the device's block; the Effect keeps its parameters for a later download().
    Status unload();
    // iterations: runtime::kEffectIterations (0) for the effect's own count, 1..254, or
    // kInfiniteIterations. solo: stop every other effect first (DIES_SOLO).
    Status start(int32_t iterations = runtime::kEffectIterations, bool solo = false);
    Status stop();
    [[nodiscard]] Result<EffectStatusInfo> status();
    // Changes the fields named by field_mask (effect_field::k*), then restarts the effect
    // if `restart` (DIEP_START). A force profile's samples come with kTypeSpecific.
    Status set_parameters(const EffectParams& params, uint32_t field_mask = effect_field::kAll,
                          bool restart = false, std::span<const int16_t> samples = {});
    // This effect's interim and final reports (dynamics only).
    [[nodiscard]] Subscription subscribe(DynamicCallback callback);

private:
    friend class Device;
    friend struct DeviceCore;
    std::shared_ptr<DeviceCore> core_;
    std::shared_ptr<EffectRecord> record_;  // the core's record of this effect
};

// ---------------------------------------------------------------------------------------
// Devices.

struct OpenOptions {
    std::chrono::milliseconds timeout{2000};  // per command round trip; 1..60000 ms
    // unix:/tcp: how long open() keeps asking a device that is busy with another host,
    // 0..60000 ms (0: ask once). The default outlasts a leaving host's teardown and the
    // detaching of a silent one (the device's watchdog, 1 s, plus its reset).
    std::chrono::milliseconds busy_wait{1500};
    int32_t report_rate_hz = 0;               // 0: the device's; else 100..1000
    // sim: addresses only, the in-process device's hand and its target motion
    // (peripheral::PeripheralOptions).
    std::string sim_hand = "firm";
    std::string sim_motion = "hold:0";
    // sim: only, peripheral::PeripheralOptions::pid_effects_only: the in-process device
    // plays only HID PID 1.0's effect types, and the host renders the others (emulated).
    bool sim_pid_effects_only = false;
    // PidDevice only: the feel profile whose mechanism (damping, sensor step, wall
    // stiffness) host emulation's engine assumes; empty: the sim: address's profile, else
    // the engine's defaults. A real wheel's figures are not known to the host.
    std::string emulation_profile;
    // The I/O thread that receives the device's reports: 1..99 runs it under SCHED_FIFO at
    // that priority where the process may (feel/transport/thread_priority.hpp; keep it below
    // an in-process device loop's 80); 0: an ordinary thread. Off by default: a game's
    // threads' priorities are the game's decision. The Studio turns it on.
    int32_t io_fifo_priority = 0;
};

// An open device. A shared handle: copies refer to the same device, which closes when the
// last copy and the last Effect made from it are gone (or at close()).
class Device {
public:
    // Opens "sim:PROFILE" (in process), "unix:PATH" or "tcp:HOST:PORT"; a bare profile
    // name means sim:PROFILE. Reads the report descriptor and the capabilities.
    // Errors: invalid_parameter (bad address, unknown profile), disconnected (nothing
    // there, or still busy with another host after options.busy_wait), timeout, protocol.
    // A tcp: address may carry the device's token ("tcp:HOST:PORT?token=TOKEN"), else
    // $FEEL_DEVICE_TOKEN is presented when set.
    [[nodiscard]] static Result<Device> open(std::string_view address = "sim:iforce2",
                                             const OpenOptions& options = {});
    // Opens the device at the far end of a connection made elsewhere (a transport the
    // caller built, an in-process pair whose device end a Peripheral serves, a test's raw
    // pair). `name` is what address() and messages say. Same checks and errors as open().
    [[nodiscard]] static Result<Device> attach(std::unique_ptr<transport::Connection> connection,
                                               std::string name, const OpenOptions& options = {});

    [[nodiscard]] const DeviceCaps& capabilities() const noexcept;
    [[nodiscard]] std::string address() const;
    // EnumEffects: the types this device can create, in §6.4 order, of one class or all.
    [[nodiscard]] std::vector<EffectSupport> effects(std::optional<EffectClass> only = std::nullopt) const;

    // CreateEffect + Download. Validated on the host first (invalid_parameter names the
    // field and range; not_supported names the type and the device). An effect with a
    // trigger is armed as a reflex: on the device, or emulated by the host.
    [[nodiscard]] Result<Effect> create_effect(const EffectParams& params,
                                               std::span<const int16_t> samples = {});
    [[nodiscard]] Result<Effect> create_effect(const format::EffectSpec& spec);

    Status set_gain(int32_t gain);                    // 0..10000 (DIPROP_FFGAIN)
    Status command(runtime::DeviceControl control);   // SendForceFeedbackCommand
    [[nodiscard]] Result<PoolInfo> pool();
    Status set_idf(runtime::IdfSettings settings);
    Status set_report_rate(int32_t hz);               // 100..min(1000, loop rate)

    // The latest input state (no round trip).
    [[nodiscard]] InputState input() const;
    // Waits until a state report newer than the current one arrives (or timeout).
    [[nodiscard]] Result<InputState> wait_input(std::chrono::milliseconds timeout);
    // Every state round from now on, in order, in a queue of `capacity` rounds
    // (1..kMaxInputQueue; 1024 is 2 s at 500 Hz). For a reader that must not miss reports
    // (a plot, a recorder): wait_input() gives only the newest. invalid_parameter for a
    // capacity out of range, disconnected for a device that is gone.
    static constexpr size_t kMaxInputQueue = 16384;
    [[nodiscard]] Result<InputSubscription> subscribe_input(size_t capacity = 1024);

    // Force streaming (§2.4): one sample of the host's force, per device axis, ±10000,
    // physical sign; up to 1 kHz. The device smooths slower streams without overshoot and
    // holds the last sample. Fire and forget: a refused sample shows in the next call.
    Status stream_force(std::span<const int32_t> force);

    // Every effect's interim and final reports.
    [[nodiscard]] Subscription subscribe(DynamicCallback callback);

    [[nodiscard]] bool connected() const noexcept;
    // Frees every effect of this host, closes the connection and joins the I/O thread.
    // Effects still alive become invalid_handle. Harmless twice.
    void close();

private:
    friend class Effect;
    explicit Device(std::shared_ptr<DeviceCore> core) : core_(std::move(core)) {}
    std::shared_ptr<DeviceCore> core_;
};

}  // namespace feel::host
