// feel::usb — feel's device as a real USB HID PID device, on the Linux USB gadget stack
// (docs/usb-device.md).
//
// Two pieces, used in this order by `feel device --sim --usb`:
//
//   ConfigfsGadget     the gadget's set-up in configfs (libcomposite): vendor and product
//                      IDs, strings, one configuration with one FunctionFS function, the
//                      FunctionFS instance mounted; bind() attaches it to a USB device
//                      controller (UDC), and the destructor undoes everything.
//   FunctionFsServer   serves that function in userspace: it writes the interface's
//                      descriptors (full and high speed) to ep0, answers the control
//                      requests (GET_DESCRIPTOR for the HID report descriptor, GET_REPORT and
//                      SET_REPORT, SET_IDLE), reads output reports from the interrupt OUT
//                      endpoint and writes input reports to the interrupt IN endpoint. Each
//                      time a USB host configures the device it attaches a connection to the
//                      Peripheral, so the host's reports reach the same DeviceSession that
//                      `feel device --sim --listen` serves; when the host goes (unplugged,
//                      reset, the gadget unbound) the connection closes and the Peripheral
//                      resets the device, which stops every force.
//
// `--ffs DIR` (a FunctionFS instance someone else set up and binds) uses the server alone.
//
// USB requests are input from a host like any other: a request the device does not serve is
// stalled and counted, a report that does not decode is answered by the session's error
// status, nothing crashes, and the queues are bounded (input reports the host does not read
// are dropped oldest first, and counted).
//
// Threads. The server runs one I/O thread (ep0 events, the endpoints' asynchronous I/O);
// the Peripheral's service thread reaches it through the connection. Construction, bind,
// stop and destruction are for one owner thread; stats() any thread. Linux only.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "feel/peripheral/peripheral.hpp"

namespace feel::usb {

// Test-only default IDs: pid.codes' vendor 0x1209 reserves products 0x0001..0x000F for
// private testing. A device sold to anyone needs IDs of its own (docs/usb-device.md).
inline constexpr uint16_t kTestVendorId = 0x1209;
inline constexpr uint16_t kTestProductId = 0x0001;

struct GadgetOptions {
    std::string name = "feel";                    // the gadget's directory under usb_gadget/
    std::string udc;                              // empty: the first in /sys/class/udc
    uint16_t vendor_id = kTestVendorId;
    uint16_t product_id = kTestProductId;
    uint16_t device_release_bcd = 0x0100;         // bcdDevice
    std::string manufacturer = "feel";
    std::string product = "feel force-feedback joystick";
    std::string serial = "0001";
    std::string configfs_root = "/sys/kernel/config";
    std::string udc_class_dir = "/sys/class/udc";
    std::string mount_dir;                        // empty: /run/feel/ffs-<name>
};

class ConfigfsGadget {
public:
    // Creates the gadget and mounts its FunctionFS instance. Throws std::runtime_error
    // naming what is missing (configfs not mounted, libcomposite or usb_f_fs not loaded, a
    // gadget of that name already there, not root) and removes what it made.
    explicit ConfigfsGadget(const GadgetOptions& options);
    // Unbinds (if bound), unmounts FunctionFS and removes the gadget's directories.
    ~ConfigfsGadget();
    ConfigfsGadget(const ConfigfsGadget&) = delete;
    ConfigfsGadget& operator=(const ConfigfsGadget&) = delete;

    // The mounted FunctionFS instance, for FunctionFsServer.
    [[nodiscard]] const std::string& ffs_dir() const noexcept;
    // Binds to the UDC named in the options, else the first one. Call after the server
    // wrote its descriptors. Throws std::runtime_error naming the UDCs there are.
    void bind();
    // Detaches from the UDC (the host sees an unplug). Harmless when not bound.
    void unbind() noexcept;
    [[nodiscard]] const std::string& udc() const noexcept;

    // The UDCs of this machine (names in /sys/class/udc), sorted.
    [[nodiscard]] static std::vector<std::string> controllers(const std::string& udc_class_dir);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct FunctionOptions {
    std::string interface_name = "feel HID PID";  // the interface's string
};

struct FunctionStats {
    uint64_t hosts = 0;              // times a host configured the device
    uint64_t setups = 0;             // control requests seen
    uint64_t stalled = 0;            // of those, stalled (not served, or refused)
    uint64_t output_reports = 0;     // reports from the interrupt OUT endpoint
    uint64_t input_reports = 0;      // reports written to the interrupt IN endpoint
    uint64_t input_dropped = 0;      // input reports dropped because the host did not read
};

class FunctionFsServer {
public:
    // Opens `ffs_dir`/ep0 and writes the function's descriptors and strings, then starts
    // the I/O thread. `log`, when given, gets one line per host report and per refusal
    // (docs/usb-device.md, "The device log"); it must outlive the server. Throws
    // std::runtime_error naming the file and the reason.
    FunctionFsServer(peripheral::Peripheral& device, const std::string& ffs_dir,
                     const FunctionOptions& options = {}, std::ostream* log = nullptr);
    ~FunctionFsServer();
    FunctionFsServer(const FunctionFsServer&) = delete;
    FunctionFsServer& operator=(const FunctionFsServer&) = delete;

    // Stops the I/O thread and closes the endpoints; the attached host is detached.
    void stop() noexcept;
    [[nodiscard]] FunctionStats stats() const noexcept;
    [[nodiscard]] bool host_configured() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace feel::usb
