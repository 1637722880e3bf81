// feel::protocol — the reports a host and a feel device exchange (docs/protocol.md).
//
// feel speaks USB HID PID 1.0 (the Physical Interface Device class, the DirectInput model
// of §6) for everything the standard covers, and vendor-defined reports for what it lacks:
// textures, walls, barriers, sweeps, Dynamics, reflexes, IDF, interim and final reports,
// per-command status. Each report below is one HID report; its byte layout is fixed by the
// report descriptor (codec.hpp: report_descriptor()), and encode()/decode() turn these
// structs into exactly those bytes and back.
//
// A report is plain data. Fields carry feel's units (units.hpp: ±10000 normalized,
// microseconds, hundredths of a degree); each states its wire range, which is the Logical
// Minimum/Maximum the descriptor declares and decode() enforces. A value outside it is an
// error naming the field and the range; it is never clamped.
//
// Effects are named by their PID Effect Block Index, 1..max_effects (0 is "no block").
// The device keeps one block per effect; the host gets the index from the Block Load that
// answers its Create New Effect.
//
// Every host-to-device report carries a `sequence` (a vendor usage in the report): the
// device answers each output report and each feature report set with one CommandStatus
// input report carrying the same number, except DownloadForceSample (force streaming, up to
// 1 kHz), which is answered only when refused. Sequence 0 is allowed and echoed.
#pragma once

#include <cstdint>
#include <variant>

#include "feel/axis.hpp"
#include "feel/effect.hpp"
#include "feel/effect_type.hpp"
#include "feel/runtime/idf.hpp"
#include "feel/status.hpp"

namespace feel::protocol {

// Report IDs. One ID names one report whatever its kind, so a stray byte can never be read
// as another kind's report.
enum class ReportId : uint8_t {
    // Output reports (host -> device), HID PID 1.0.
    set_effect = 0x01,             // Set Effect Report
    set_envelope = 0x02,           // Set Envelope Report
    set_condition = 0x03,          // Set Condition Report (one per axis)
    set_periodic = 0x04,           // Set Periodic Report
    set_constant_force = 0x05,     // Set Constant Force Report
    set_ramp_force = 0x06,         // Set Ramp Force Report
    set_custom_force = 0x07,       // Set Custom Force Report
    custom_force_data = 0x08,      // Custom Force Data Report
    download_force_sample = 0x09,  // Download Force Sample (force streaming, §2.4)
    effect_operation = 0x0A,       // Effect Operation Report
    block_free = 0x0B,             // PID Block Free Report
    device_control = 0x0C,         // PID Device Control
    device_gain = 0x0D,            // Device Gain Report
    // Output reports, feel vendor page.
    set_texture = 0x20,            // texture block (§6.6.j)
    set_wall = 0x21,               // wall block (§6.6.h)
    set_barrier = 0x22,            // barrier block (§6.6.g)
    set_sweep = 0x23,              // sweep angles and sense (§6.6.i)
    set_dynamic = 0x24,            // the named dynamics' block (§6.6.f, §8.4)
    set_control_law = 0x25,        // a control law block, one per axis (§8.4)
    reflex = 0x26,                 // assign or remove an effect's reflex (§1.2.c)
    idf_settings = 0x27,           // the player's IDF choice (§1.2.d)
    report_rate = 0x28,            // the device's state report rate
    keep_alive = 0x29,             // "the host is here" (the device's host watchdog)
    effect_status_request = 0x2A,  // asks for an effect's status (answered in CommandStatus)
    // Feature reports, HID PID 1.0.
    create_new_effect = 0x11,      // set: allocate a block for an effect type
    block_load = 0x12,             // get: the block the last Create New Effect allocated
    pid_pool = 0x13,               // get: the device's effect memory
    // Feature reports, feel vendor page.
    device_info = 0x30,            // get: the device's capabilities (§6.1, §7.4)
    // Input reports (device -> host).
    joystick_input = 0x40,         // HID Generic Desktop joystick: axes, buttons, hats
    pid_state = 0x41,              // PID State Report (one effect's playing flag)
    command_status = 0x42,         // vendor: the outcome of one command
    device_status = 0x43,          // vendor: forces, safety, effect states, loop figures
    dynamic_report = 0x44,         // vendor: a dynamic's interim or final report (§5.2), by axes
    command_error_text = 0x45,     // vendor: a refusal's field and rule, before its CommandStatus
    effect_states = 0x46,          // vendor: the effects' states and counts, in pages
};

// The largest input or output report travels in one full-speed interrupt packet (64
// bytes, USB 2.0 §5.7.3), whatever the transport: the reports are laid out for it
// (docs/protocol.md, "Which pipe"). Feature reports travel on the control pipe.
inline constexpr int kInterruptPacketBytes = 64;

enum class ReportKind : uint8_t { output, feature, input };

// ---------------------------------------------------------------------------------------
// Output reports, HID PID.

// Durations on the wire: microseconds, 0..65'000'000, or kWireInfinite (PID's "infinite",
// DirectInput's INFINITE) where the field allows it.
inline constexpr uint32_t kWireInfinite = 0xFFFFFFFFu;

// Effect Operation's loop count (16 bits on a feel device): 0 plays the effect's own
// iteration count, 1..255 that many, kLoopInfinite (the field's null, 0xFFFF) until
// stopped. Set Effect's iterations: 1..255 or kLoopInfinite. A standard PID device's loop
// count is 8 bits, where 255 is "infinite" (docs/protocol.md).
inline constexpr uint16_t kLoopEffectOwn = 0;
inline constexpr uint16_t kLoopInfinite = 0xFFFF;

// Set Effect: the Effect Structure of §6.3. Sent last, after the type-specific blocks: it
// commits the effect (the first Set Effect of a block downloads it, later ones update it).
struct SetEffectReport {
    uint32_t sequence = 0;
    uint16_t block = 1;                        // 1..65535
    EffectType type = EffectType::constant;    // PID Effect Type (vendor usages beyond PID's)
    uint32_t duration_us = kWireInfinite;      // 1..65e6 or kWireInfinite
    uint32_t start_delay_us = 0;               // 0..65e6
    uint32_t trigger_repeat_interval_us = 0;   // 0..65e6, 0 = no repeat
    uint16_t gain = 10000;                     // 0..10000
    uint16_t iterations = 1;                   // vendor: 1..255, or kLoopInfinite
    TriggerKind trigger_kind = TriggerKind::none;  // vendor: none, button, hat
    uint8_t trigger_index = 0;                 // PID Trigger Button: 0 none, button 1..32, hat 1..4
    uint8_t axis_count = 1;                    // vendor: 1..6, in feel's order; 0 not given (standard host)
    Axis axes[kMaxAxes] = {Axis::x, Axis::y, Axis::z, Axis::rx, Axis::ry, Axis::rz};  // 0..5
    // PID Axes Enable: bit a for feel::Axis a (Generic Desktop X, Y, Z, Rx, Ry, Rz), the
    // axes the effect acts on; 0 not given. feel's host sets the bits of `axes`.
    uint8_t axes_enable = 0;
    DirectionKind direction_kind = DirectionKind::none;  // PID Direction Enable + vendor form
    // Polar and spherical: PID Direction's Ordinals, 0..35999; cartesian and moments: a
    // vendor vector, ±10000 per component (see feel::Direction). Slots a form does not
    // use do not travel and decode as 0.
    int32_t direction[3] = {0, 0, 0};
    bool has_envelope = false;                 // the block's Set Envelope applies (wire: vendor no_envelope)

    friend bool operator==(const SetEffectReport&, const SetEffectReport&) = default;
};

struct SetEnvelopeReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    uint16_t impulse_level = 0;  // PID Attack Level, 0..10000
    uint32_t settle_time_us = 0; // PID Attack Time, 0..65e6
    uint16_t fade_level = 0;     // PID Fade Level, 0..10000
    uint32_t fade_time_us = 0;   // PID Fade Time, 0..65e6

    friend bool operator==(const SetEnvelopeReport&, const SetEnvelopeReport&) = default;
};

struct SetConditionReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    uint8_t axis_index = 0;      // PID Parameter Block Offset: the effect's axis, 0..5
    int16_t center_offset = 0;   // PID CP Offset, -10000..10000
    int16_t pos_coefficient = 0; // -10000..10000
    int16_t neg_coefficient = 0; // -10000..10000
    uint16_t pos_saturation = 10000;  // 0..10000
    uint16_t neg_saturation = 10000;  // 0..10000
    uint16_t deadband = 0;       // 0..10000
    OffsetMode offset_mode = OffsetMode::absolute;  // vendor: relative = SpringAtCurrentLocation

    friend bool operator==(const SetConditionReport&, const SetConditionReport&) = default;
};

struct SetPeriodicReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    int16_t magnitude = 0;   // -10000..10000 (periodics 0..10000, sweeps signed)
    int16_t offset = 0;      // -10000..10000
    uint16_t phase = 0;      // 0..35999
    uint32_t period_us = 1;  // 1..65e6

    friend bool operator==(const SetPeriodicReport&, const SetPeriodicReport&) = default;
};

struct SetConstantForceReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    int16_t magnitude = 0;  // -10000..10000

    friend bool operator==(const SetConstantForceReport&, const SetConstantForceReport&) = default;
};

struct SetRampForceReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    int16_t start = 0;  // -10000..10000
    int16_t end = 0;    // -10000..10000

    friend bool operator==(const SetRampForceReport&, const SetRampForceReport&) = default;
};

struct SetCustomForceReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    uint8_t channels = 1;           // 1..6
    uint32_t sample_period_us = 1;  // 1..65e6
    uint16_t sample_count = 1;      // 1..65535 (PID Custom Force Data's count, in samples)

    friend bool operator==(const SetCustomForceReport&, const SetCustomForceReport&) = default;
};

// Samples per Custom Force Data report.
inline constexpr int kSamplesPerDataReport = 24;  // so the report fits a 64-byte packet

// Custom Force Data: samples of the block's force profile, sent in order before its Set
// Custom Force and Set Effect (offset 0 starts a new profile).
struct CustomForceDataReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    uint16_t offset = 0;  // PID Custom Force Data Offset, in samples, 0..65534
    uint8_t count = 1;    // samples used, 1..kSamplesPerDataReport
    int16_t samples[kSamplesPerDataReport] = {};  // -10000..10000, interleaved by channel

    friend bool operator==(const CustomForceDataReport&, const CustomForceDataReport&) = default;
};

// Download Force Sample: one sample of the host's force stream (§2.4). The device smooths
// the stream and holds its last value (docs/protocol.md, "Force streaming").
struct DownloadForceSampleReport {
    uint32_t sequence = 0;
    uint8_t axis_count = 1;            // 1..6, the device's axes in order
    int16_t force[kMaxAxes] = {};      // -10000..10000, physical sign

    friend bool operator==(const DownloadForceSampleReport&, const DownloadForceSampleReport&) = default;
};

enum class EffectOperation : uint8_t { start = 1, start_solo = 2, stop = 3 };  // PID Op Effect *

struct EffectOperationReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    EffectOperation operation = EffectOperation::start;
    uint16_t loop_count = kLoopEffectOwn;  // 0..255 or kLoopInfinite, see kLoopEffectOwn

    friend bool operator==(const EffectOperationReport&, const EffectOperationReport&) = default;
};

struct BlockFreeReport {
    uint32_t sequence = 0;
    uint16_t block = 1;

    friend bool operator==(const BlockFreeReport&, const BlockFreeReport&) = default;
};

// PID Device Control: DC Enable Actuators .. DC Device Continue (runtime::DeviceControl).
enum class DeviceControlOp : uint8_t {
    enable_actuators = 1, disable_actuators = 2, stop_all_effects = 3, device_reset = 4,
    device_pause = 5, device_continue = 6,
};

struct DeviceControlReport {
    uint32_t sequence = 0;
    DeviceControlOp control = DeviceControlOp::stop_all_effects;

    friend bool operator==(const DeviceControlReport&, const DeviceControlReport&) = default;
};

struct DeviceGainReport {
    uint32_t sequence = 0;
    uint16_t gain = 10000;  // 0..10000

    friend bool operator==(const DeviceGainReport&, const DeviceGainReport&) = default;
};

// ---------------------------------------------------------------------------------------
// Output reports, feel vendor page.

struct SetTextureReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    TextureBlock texture{};  // each field 1..10000

    friend bool operator==(const SetTextureReport&, const SetTextureReport&) = default;
};

struct SetWallReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    WallBlock wall{};  // ranges of effect.hpp

    friend bool operator==(const SetWallReport&, const SetWallReport&) = default;
};

struct SetBarrierReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    BarrierBlock barrier{};  // ranges of effect.hpp

    friend bool operator==(const SetBarrierReport&, const SetBarrierReport&) = default;
};

struct SetSweepReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    uint16_t start_angle = 0;  // 0..35999
    uint16_t end_angle = 0;    // 0..35999
    SweepSense sense = SweepSense::clockwise;

    friend bool operator==(const SetSweepReport&, const SetSweepReport&) = default;
};

// The named dynamics' block. `dynamic.control_law` is not sent here (Set Control Law
// carries it, one report per axis) and decodes as default blocks.
struct SetDynamicReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    DynamicBlock dynamic{};  // ranges of effect.hpp

    friend bool operator==(const SetDynamicReport&, const SetDynamicReport&) = default;
};

struct SetControlLawReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    uint8_t axis_index = 0;  // 0..5
    ControlLawBlock law{};   // ranges of effect.hpp

    friend bool operator==(const SetControlLawReport&, const SetControlLawReport&) = default;
};

// Arms (assign) or disarms (remove) the block's reflex from its trigger fields (§1.2.c).
struct ReflexReport {
    uint32_t sequence = 0;
    uint16_t block = 1;
    bool assign = true;

    friend bool operator==(const ReflexReport&, const ReflexReport&) = default;
};

struct IdfSettingsReport {
    uint32_t sequence = 0;
    runtime::IdfSettings settings{};

    friend bool operator==(const IdfSettingsReport& a, const IdfSettingsReport& b) noexcept {
        return a.sequence == b.sequence && a.settings.periodic == b.settings.periodic &&
               a.settings.impulse == b.settings.impulse;
    }
};

struct ReportRateReport {
    uint32_t sequence = 0;
    uint16_t rate_hz = 250;  // 100..1000 (the device refuses more than its loop rate)

    friend bool operator==(const ReportRateReport&, const ReportRateReport&) = default;
};

struct KeepAliveReport {
    uint32_t sequence = 0;

    friend bool operator==(const KeepAliveReport&, const KeepAliveReport&) = default;
};

struct EffectStatusRequestReport {
    uint32_t sequence = 0;
    uint16_t block = 1;

    friend bool operator==(const EffectStatusRequestReport&, const EffectStatusRequestReport&) = default;
};

// ---------------------------------------------------------------------------------------
// Feature reports.

// Set: allocates a block for an effect of this type (PID Create New Effect).
struct CreateNewEffectReport {
    uint32_t sequence = 0;
    EffectType type = EffectType::constant;
    uint16_t sample_count = 0;  // PID Byte Count, in samples: force_profile's, else 0

    friend bool operator==(const CreateNewEffectReport&, const CreateNewEffectReport&) = default;
};

enum class BlockLoadStatus : uint8_t { success = 1, full = 2, error = 3 };  // PID Block Load *

// Get: the answer to the last Create New Effect.
struct BlockLoadReport {
    uint16_t block = 0;                        // the new block (0 unless success)
    BlockLoadStatus status = BlockLoadStatus::error;
    uint32_t ram_pool_available = 0;           // PID RAM Pool Available, bytes

    friend bool operator==(const BlockLoadReport&, const BlockLoadReport&) = default;
};

// Get: the device's effect memory (PID Pool Report, plus feel's sample store).
struct PidPoolReport {
    uint32_t ram_pool_size = 0;           // bytes of effect parameter memory
    uint16_t simultaneous_effects_max = 0;
    bool device_managed_pool = true;      // PID Device Managed Pool: the device allocates
    bool shared_parameter_blocks = false; // PID Shared Parameter Blocks
    uint32_t ram_pool_available = 0;      // PID RAM Pool Available: bytes free
    uint16_t free_effects = 0;            // vendor: blocks free
    uint32_t sample_memory = 0;           // vendor: force-profile samples in all
    uint32_t free_samples = 0;            // vendor: samples free

    friend bool operator==(const PidPoolReport&, const PidPoolReport&) = default;
};

// Text fields are NUL-padded, not necessarily NUL-terminated when full.
inline constexpr int kNameBytes = 24;

struct AxisInfo {
    Axis axis = Axis::x;
    uint8_t rotary = 0;              // 0 linear (m, N), 1 rotary (rad, N·m)
    // The physical figures are 0 for the entries beyond the device's axis_count.
    uint32_t half_travel_micro = 0;  // half travel in µm or µrad, 1..2^31-1
    uint32_t max_force_milli = 0;    // force at ±10000, mN or mN·m, 1..2^31-1
    uint32_t sensor_counts = 0;      // 2..2^24

    friend bool operator==(const AxisInfo&, const AxisInfo&) = default;
};

// Get: what the device is and can do (runtime::Capabilities on the wire).
struct DeviceInfoReport {
    char device[kNameBytes] = {};         // profile name, e.g. "iforce2"
    char description[192] = {};           // one line about the hardware
    uint8_t device_class = 0;             // sim::DeviceClass: 1 I-FORCE 1.x, 2 I-FORCE 2.0
    uint8_t axis_count = 0;               // 1..6
    AxisInfo axes[kMaxAxes] = {};
    uint8_t button_count = 0;             // 0..32
    uint8_t hat_count = 0;                // 0..4
    bool dead_man_switch = false;
    uint16_t max_force = 10000;           // 0..10000, the force the motors can give
    uint64_t supported_types = 0;         // bit per EffectType (effect_type_bit)
    uint16_t effect_slots = 0;
    uint32_t pool_bytes = 0;
    uint32_t sample_memory = 0;
    bool local_reflexes = false;
    bool interim_reports = false;
    uint16_t loop_rate_hz = 0;
    uint16_t max_loop_rate_hz = 0;
    uint16_t interim_report_centihz = 0;  // interim report rate, hundredths of Hz
    uint16_t report_rate_hz = 0;          // the state report rate now
    char firmware_version[kNameBytes] = {};
    uint8_t vendor_revision = 2;          // runtime::kProtocolVendorRevision

    friend bool operator==(const DeviceInfoReport&, const DeviceInfoReport&) = default;
};

// ---------------------------------------------------------------------------------------
// Input reports.

// The joystick's input: Generic Desktop X, Y, Z, Rx, Ry, Rz, buttons, hat switches.
struct JoystickInputReport {
    int16_t position[kMaxAxes] = {};  // -10000..10000: the reported position (IDF, clipping)
    uint32_t buttons = 0;             // bit i = button i+1
    uint8_t hats = 0;                 // bit h-1 = hat h pushed off center

    friend bool operator==(const JoystickInputReport&, const JoystickInputReport&) = default;
};

// PID State: the device's flags and one effect's playing state (sent when it changes).
struct PidStateReport {
    bool device_paused = false;
    bool actuators_enabled = true;
    bool safety_switch = false;       // the dead-man switch: true = hand on the handle
    bool actuator_override = false;   // vendor meaning: hands-off or host-lost fade in force
    bool actuator_power = true;
    bool effect_playing = false;
    uint16_t block = 0;               // 0 when the report names no effect

    friend bool operator==(const PidStateReport&, const PidStateReport&) = default;
};

// Command Status's `command` for a frame whose first byte names no report (that byte is in
// the status's `value`, field "report.id"). HID reserves report id 0, so no report has it.
inline constexpr ReportId kNoReportId = ReportId{0};

// The outcome of one command (vendor). For an error: the value and the allowed range
// exactly as the device's engine refused it; the field's name and the rule's sentence come
// in CommandErrorTextReports sent just before it (protocol/command_answer.hpp joins them),
// so the answer fits one interrupt packet.
struct CommandStatusReport {
    uint32_t sequence = 0;
    ReportId command = ReportId::keep_alive;  // the report that was answered, or kNoReportId
    uint16_t block = 0;                        // the effect concerned, 0 if none
    ErrorCode code = ErrorCode::ok;
    int64_t value = 0;
    int64_t allowed_min = 0;
    int64_t allowed_max = 0;
    bool has_range = false;
    // The effect's status after the command (effect commands and status requests).
    uint8_t effect_state = 0;                  // runtime::ReportedEffectState
    uint16_t iterations = 0;                   // 0..255, or kLoopInfinite
    uint8_t completed_iterations = 0;
    uint32_t elapsed_us = 0;                   // since the start, saturating
    uint8_t last_end = 0;                      // feel::PlayEnd of the last play

    friend bool operator==(const CommandStatusReport&, const CommandStatusReport&) = default;
};

// A refusal's text (vendor), in parts of kErrorTextPartBytes, sent right before the refusal's
// CommandStatus with the same sequence and command: part 0 is the field's name
// ("set_effect.gain"), parts 1 and 2 the rule's sentence (bytes 0..47, 48..95), each
// NUL-padded. Parts 1 and 2 come only when the rule reaches into them.
inline constexpr int kErrorTextPartBytes = 48;
inline constexpr int kErrorFieldBytes = kErrorTextPartBytes;      // part 0
inline constexpr int kErrorRuleBytes = 2 * kErrorTextPartBytes;   // parts 1 and 2
struct CommandErrorTextReport {
    uint32_t sequence = 0;
    ReportId command = ReportId::keep_alive;  // as in the CommandStatus it precedes
    uint8_t part = 0;                          // 0 field, 1 and 2 the rule
    char text[kErrorTextPartBytes] = {};

    friend bool operator==(const CommandErrorTextReport&, const CommandErrorTextReport&) = default;
};

// The device's state at the report rate (vendor): what `feel monitor` shows. The effects'
// states follow in EffectStatesReport pages.
struct DeviceStatusReport {
    uint64_t t_us = 0;                 // device time of the tick described
    uint32_t report_number = 0;
    int16_t force[kMaxAxes] = {};      // the motors' force, -10000..10000
    int32_t velocity[kMaxAxes] = {};   // the handle's velocity, position units/s
    uint16_t fade_level = 0;           // safety fade 0..10000 (1.0 = 10000)
    uint8_t safety_flags = 0;          // bit 0 held, 1 hands_off, 2 host_lost, 3 paused, 4 actuators_enabled
    uint16_t gain = 10000;
    uint16_t loop_rate_hz = 0;         // the loop's nominal rate
    uint32_t overruns = 0;             // loop overruns since the device started
    uint32_t measured_rate_millihz = 0;// ticks per second measured over the last second, mHz

    friend bool operator==(const DeviceStatusReport&, const DeviceStatusReport&) = default;
};

// The effects' states (vendor), sent after each DeviceStatus with its report number, in
// pages of kEffectsPerStatusReport effects (at least one page, also with no effect).
inline constexpr int kEffectsPerStatusReport = 14;
struct EffectStatesReport {
    uint32_t report_number = 0;        // the DeviceStatus this belongs to
    uint16_t playing_effects = 0;
    uint16_t resident_effects = 0;
    uint64_t dropped_reports = 0;      // input reports the device dropped (a host not reading)
    uint8_t page = 0, pages = 1, effect_count = 0;  // 0..255, 1..255, 0..kEffectsPerStatusReport
    uint16_t effect_block[kEffectsPerStatusReport] = {};
    uint8_t effect_state[kEffectsPerStatusReport] = {};  // runtime::ReportedEffectState

    friend bool operator==(const EffectStatesReport&, const EffectStatesReport&) = default;
};

// A dynamic's interim or final report (vendor, §5.2, §6.6.f), kDynamicAxesPerReport axes
// at a time: an effect with more axes sends several, first_axis 0 first, all with the
// same t_us.
inline constexpr int kDynamicAxesPerReport = 4;
struct DynamicReportReport {
    uint16_t block = 0;
    uint8_t final_report = 0;          // 0 interim, 1 final
    uint64_t t_us = 0;
    uint8_t axis_count = 0;            // the effect's axes, 0..6
    uint8_t first_axis = 0;            // the effect axis of slot 0 here: 0 or 4
    // Mass minus handle, hundredths of a position unit, and hundredths of units/s, for
    // effect axes first_axis .. first_axis + 3.
    int32_t position_centi[kDynamicAxesPerReport] = {};
    int32_t velocity_centi[kDynamicAxesPerReport] = {};
    int32_t handle_velocity_centi[kDynamicAxesPerReport] = {};

    friend bool operator==(const DynamicReportReport&, const DynamicReportReport&) = default;
};

// Any report.
using AnyReport = std::variant<
    SetEffectReport, SetEnvelopeReport, SetConditionReport, SetPeriodicReport,
    SetConstantForceReport, SetRampForceReport, SetCustomForceReport, CustomForceDataReport,
    DownloadForceSampleReport, EffectOperationReport, BlockFreeReport, DeviceControlReport,
    DeviceGainReport, SetTextureReport, SetWallReport, SetBarrierReport, SetSweepReport,
    SetDynamicReport, SetControlLawReport, ReflexReport, IdfSettingsReport, ReportRateReport,
    KeepAliveReport, EffectStatusRequestReport, CreateNewEffectReport, BlockLoadReport,
    PidPoolReport, DeviceInfoReport, JoystickInputReport, PidStateReport, CommandStatusReport,
    DeviceStatusReport, DynamicReportReport, CommandErrorTextReport, EffectStatesReport>;

}  // namespace feel::protocol
