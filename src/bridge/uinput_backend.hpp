// The Linux side of `feel bridge`: a virtual input device made through /dev/uinput.
//
// Platform code, nothing else: it declares the device (axes, buttons, EV_FF bits, how many
// effects), hands the bridge loop what the kernel asks (UI_FF_UPLOAD and UI_FF_ERASE
// requests, EV_FF plays, gain and autocenter) and sends the device's state as EV_ABS and
// EV_KEY events. The kernel's force-feedback core (drivers/input/ff-core.c) checks a game's
// effect against the EV_FF bits and picks its id before uinput passes it here; uinput waits
// (up to 30 s) for the reply of each request, so requests are answered as they come.
#pragma once

#include <linux/input.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace feel::bridge {

struct UinputSpec {
    std::string name = "feel force-feedback joystick";
    uint16_t vendor_id = 0x1209;   // pid.codes' test IDs, as feel's USB device
    uint16_t product_id = 0x0001;
    std::vector<uint16_t> axes;     // ABS_* codes, each -10000..10000
    std::vector<uint16_t> buttons;  // KEY/BTN_* codes
    std::vector<uint16_t> ff_bits;  // FF_* codes
    uint32_t max_effects = 16;      // 1..FF_MAX_EFFECTS (96)
};

// One thing the kernel asked.
struct UinputRequest {
    enum class Kind : uint8_t { upload, erase, play, gain, autocenter };
    Kind kind = Kind::play;
    uint32_t request_id = 0;  // upload, erase: what the reply names
    uint16_t code = 0;        // play: the effect id
    int32_t value = 0;        // play: the count (0: stop); gain, autocenter: 0..0xFFFF
};

class UinputDevice {
public:
    // Opens /dev/uinput (or `path`) and creates the device. Throws std::runtime_error
    // saying what to do: the module not loaded (modprobe uinput), no permission (a udev
    // rule, docs/real-devices.md), or what the kernel refused.
    explicit UinputDevice(const UinputSpec& spec, const std::string& path = "/dev/uinput");
    ~UinputDevice();  // destroys the device (games see it unplugged)
    UinputDevice(const UinputDevice&) = delete;
    UinputDevice& operator=(const UinputDevice&) = delete;

    // The event node games open, e.g. /dev/input/event5 (from sysfs; empty if unknown).
    [[nodiscard]] const std::string& event_node() const noexcept { return event_node_; }
    // Waits up to timeout_ms for the kernel; returns what it asked (possibly nothing).
    [[nodiscard]] std::vector<UinputRequest> wait(int timeout_ms);

    // UI_BEGIN_FF_UPLOAD: the effect the game uploads (its id set by the kernel).
    [[nodiscard]] std::optional<ff_effect> begin_upload(uint32_t request_id);
    // UI_END_FF_UPLOAD with the result: 0 or a negative errno.
    void end_upload(uint32_t request_id, const ff_effect& effect, int result);
    // UI_BEGIN_FF_ERASE: the effect id to erase.
    [[nodiscard]] std::optional<int16_t> begin_erase(uint32_t request_id);
    void end_erase(uint32_t request_id, int16_t id, int result);

    // Input events: EV_ABS / EV_KEY values, then one SYN_REPORT for the batch.
    void emit(uint16_t type, uint16_t code, int32_t value);
    void sync();

private:
    int fd_ = -1;
    std::string event_node_;
    std::vector<input_event> pending_;
};

}  // namespace feel::bridge
