// classify_setup(): a SETUP packet to what the HID function does with it (hid_requests.hpp).
#include "hid_requests.hpp"

#include <cstdio>

#include "feel/transport/transport.hpp"

namespace feel::usb::detail {
namespace {

constexpr uint8_t kDirIn = 0x80;
constexpr uint8_t kTypeMask = 0x60;
constexpr uint8_t kTypeStandard = 0x00;
constexpr uint8_t kTypeClass = 0x20;
constexpr uint8_t kRecipientMask = 0x1F;
constexpr uint8_t kRecipientInterface = 0x01;

constexpr uint8_t kGetDescriptor = 0x06;
constexpr uint8_t kHidGetReport = 0x01;
constexpr uint8_t kHidGetIdle = 0x02;
constexpr uint8_t kHidGetProtocol = 0x03;
constexpr uint8_t kHidSetReport = 0x09;
constexpr uint8_t kHidSetIdle = 0x0A;
constexpr uint8_t kHidSetProtocol = 0x0B;

constexpr uint8_t kReportInput = 1;
constexpr uint8_t kReportOutput = 2;
constexpr uint8_t kReportFeature = 3;

std::string hex(unsigned v, int digits) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%0*X", digits, v);
    return buf;
}

ControlAction stall(const SetupPacket& s, std::string reason) {
    ControlAction a;
    a.kind = ControlAction::Kind::stall;
    a.device_to_host = (s.request_type & kDirIn) != 0;
    a.reason = "bmRequestType " + hex(s.request_type, 2) + " bRequest " + hex(s.request, 2) + " wValue " +
               hex(s.value, 4) + " wIndex " + hex(s.index, 4) + " wLength " + std::to_string(s.length) + ": " +
               std::move(reason);
    return a;
}

const char* report_type_name(uint8_t type) {
    switch (type) {
        case kReportInput: return "Input";
        case kReportOutput: return "Output";
        case kReportFeature: return "Feature";
        default: return "unknown";
    }
}

}  // namespace

ControlAction classify_setup(const SetupPacket& s, uint8_t interface_number) {
    const bool in = (s.request_type & kDirIn) != 0;
    const uint8_t type = s.request_type & kTypeMask;
    if ((s.request_type & kRecipientMask) != kRecipientInterface) {
        return stall(s, "the HID function serves only requests to its interface (recipient 1)");
    }
    if ((s.index & 0xFF) != interface_number) {
        return stall(s, "names interface " + std::to_string(s.index & 0xFF) + ", the HID function is interface " +
                            std::to_string(interface_number));
    }
    const auto high = static_cast<uint8_t>(s.value >> 8);
    const auto low = static_cast<uint8_t>(s.value & 0xFF);

    if (type == kTypeStandard) {
        if (s.request != kGetDescriptor || !in) {
            return stall(s, "the only standard request to the interface served is GET_DESCRIPTOR (IN)");
        }
        ControlAction a;
        a.device_to_host = true;
        a.length = s.length;
        if (high == 0x22 && low == 0) {
            a.kind = ControlAction::Kind::report_descriptor;
        } else if (high == 0x21 && low == 0) {
            a.kind = ControlAction::Kind::hid_descriptor;
        } else {
            return stall(s, "descriptor type " + hex(high, 2) + " index " + std::to_string(low) +
                                " is not one of this interface's (allowed 0x22 Report or 0x21 HID, index 0)");
        }
        return a;
    }
    if (type != kTypeClass) return stall(s, "vendor requests are not served (allowed standard or class)");

    switch (s.request) {
        case kHidGetReport: {
            if (!in) return stall(s, "GET_REPORT must be device-to-host");
            if (high != kReportFeature) {
                return stall(s, std::string("GET_REPORT of an ") + report_type_name(high) +
                                    " report: only Feature reports (type 3) are got on ep0; input reports "
                                    "travel on the interrupt IN endpoint");
            }
            if (s.length == 0) return stall(s, "GET_REPORT with wLength 0 has no room for the report id");
            ControlAction a;
            a.kind = ControlAction::Kind::get_feature;
            a.device_to_host = true;
            a.report_id = low;
            a.length = s.length;
            return a;
        }
        case kHidSetReport: {
            if (in) return stall(s, "SET_REPORT must be host-to-device");
            if (high != kReportOutput && high != kReportFeature) {
                return stall(s, std::string("SET_REPORT of an ") + report_type_name(high) +
                                    " report (allowed Output, type 2, or Feature, type 3)");
            }
            if (s.length == 0 || s.length > transport::kMaxFramePayload) {
                return stall(s, "SET_REPORT wLength " + std::to_string(s.length) + " is out of range (allowed 1.." +
                                    std::to_string(transport::kMaxFramePayload) + ")");
            }
            ControlAction a;
            a.kind = high == kReportOutput ? ControlAction::Kind::set_output : ControlAction::Kind::set_feature;
            a.report_id = low;
            a.length = s.length;
            return a;
        }
        case kHidSetIdle: {
            if (in || s.length != 0) return stall(s, "SET_IDLE is host-to-device with no data");
            ControlAction a;
            a.kind = ControlAction::Kind::acknowledge;
            return a;
        }
        case kHidGetIdle: return stall(s, "GET_IDLE is not served: feel reports at its report rate");
        case kHidGetProtocol:
        case kHidSetProtocol: return stall(s, "GET/SET_PROTOCOL are for boot devices; a joystick is not one");
        default: return stall(s, "is not a HID class request (HID 1.11 §7.2)");
    }
}

}  // namespace feel::usb::detail
