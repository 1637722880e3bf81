// What a control request on ep0 asks of a HID function, decided from its SETUP packet alone
// (HID 1.11 §7.1 and §7.2). A pure function, so that every request a host can send is
// tested without a USB stack.
//
//   GET_DESCRIPTOR (standard, interface)  wValue 0x22nn: the report descriptor
//                                         wValue 0x21nn: the HID class descriptor
//   GET_REPORT (class, interface)         wValue hi = 3 (Feature): a feature report the
//                                         device session answers; the reply starts with
//                                         the report id and is cut at wLength (usbhid asks
//                                         with wLength rounded up to 64)
//   SET_REPORT (class, interface)         wValue hi = 2 (Output) or 3 (Feature), wLength
//                                         1..kMaxFramePayload: the data stage is the report
//   SET_IDLE (class, interface)           acknowledged: feel sends input reports when they
//                                         change or at its report rate, whatever the idle
//                                         rate (HID 1.11 §7.2.4 allows a device to do so)
//
// Everything else is stalled with a reason for the log: GET_REPORT of an Input or Output
// report (feel's input reports travel on the interrupt endpoint), GET_IDLE, GET_PROTOCOL and
// SET_PROTOCOL (not a boot device), requests to another interface or recipient, vendor
// requests, a SET_REPORT without data, a wrong direction.
#pragma once

#include <cstdint>
#include <string>

namespace feel::usb::detail {

// The SETUP packet, fields in host order (FunctionFS hands it little-endian).
struct SetupPacket {
    uint8_t request_type = 0;  // bmRequestType
    uint8_t request = 0;       // bRequest
    uint16_t value = 0;        // wValue
    uint16_t index = 0;        // wIndex
    uint16_t length = 0;       // wLength
};

struct ControlAction {
    enum class Kind : uint8_t {
        stall,              // refuse: `reason` says why
        acknowledge,        // a no-data request to accept (SET_IDLE)
        report_descriptor,  // reply with the report descriptor, at most `length` bytes
        hid_descriptor,     // reply with the HID class descriptor, at most `length` bytes
        get_feature,        // the session's feature report `report_id`, at most `length` bytes
        set_output,         // read `length` bytes: an output report
        set_feature,        // read `length` bytes: a feature report
    };
    Kind kind = Kind::stall;
    uint8_t report_id = 0;
    uint16_t length = 0;
    std::string reason;
    // True when the request's data stage goes device-to-host (how a stall is done: I/O in
    // the other direction).
    bool device_to_host = false;
};

// The interface number the function's requests must name (wIndex), FunctionFS's function
// being one interface.
[[nodiscard]] ControlAction classify_setup(const SetupPacket& setup, uint8_t interface_number = 0);

}  // namespace feel::usb::detail
