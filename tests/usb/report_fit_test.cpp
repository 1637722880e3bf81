// Every report fits the pipe it travels on (docs/protocol.md, "Which pipe"): an input
// report one interrupt IN packet, an output report one interrupt OUT packet, at full speed
// and at high speed; a report that fits no packet is a feature report, which travels on
// the control pipe (SET_REPORT / GET_REPORT, wLength up to 4096 on a feel device).
//
// The sizes are the report descriptor's, read by the HID descriptor parser (each report's
// bits plus its Report ID byte, HID 1.11 §8.4), and the packet sizes the endpoint
// descriptors' wMaxPacketSize that feel hands FunctionFS (USB 2.0 §9.6.6): neither is the
// codec's own report_size().
#include <gtest/gtest.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "ffs_descriptors.hpp"

namespace feel::usb::detail {
namespace {

struct Endpoints {
    uint16_t in_packet = 0, out_packet = 0;
};

// The interrupt endpoints' wMaxPacketSize per speed (0 full, 1 high), found by walking the
// FunctionFS blob's descriptors: a 20-byte v2 header, then each speed's descriptors.
std::vector<Endpoints> endpoint_packets() {
    const std::vector<uint8_t> blob = function_descriptors(100);
    std::vector<Endpoints> speeds;
    std::size_t at = 20;
    for (int speed = 0; speed < 2; ++speed) {
        Endpoints e;
        for (int d = 0; d < 4 && at + 1 < blob.size(); ++d) {
            const uint8_t length = blob[at];
            if (blob[at + 1] == 5 && blob[at + 3] == 3) {  // ENDPOINT, interrupt
                const auto packet = static_cast<uint16_t>(blob[at + 4] | (blob[at + 5] << 8));
                ((blob[at + 2] & 0x80) != 0 ? e.in_packet : e.out_packet) = packet;
            }
            at += length;
        }
        speeds.push_back(e);
    }
    return speeds;
}

TEST(ReportFit, EveryInputAndOutputReportFitsOneInterruptPacketAtBothSpeeds) {
    const std::vector<Endpoints> speeds = endpoint_packets();
    ASSERT_EQ(speeds.size(), 2u);
    EXPECT_EQ(speeds[0].in_packet, 64);  // full speed's largest interrupt packet (USB 2.0 §5.7.3)
    EXPECT_EQ(speeds[0].out_packet, 64);
    EXPECT_GE(speeds[1].in_packet, 64);

    // The full joystick layout (six axes, 32 buttons, four hats) is the largest any profile
    // declares, and the rest of the descriptor is every device's.
    const std::span<const uint8_t> descriptor = protocol::report_descriptor();
    const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(descriptor);
    ASSERT_TRUE(parse.ok()) << parse.error;
    ASSERT_TRUE(parse.descriptor.uses_report_ids);

    int inputs = 0, outputs = 0, oversize_features = 0;
    for (const protocol::hid::DescriptorReport& r : parse.descriptor.reports) {
        const uint32_t bytes = 1 + (r.bit_length + 7) / 8;  // the Report ID byte, then the fields
        const std::string what = "report id " + std::to_string(r.id) + " of " + std::to_string(bytes) + " bytes";
        switch (r.kind) {
            case protocol::hid::MainItemKind::input:
                ++inputs;
                for (const Endpoints& e : speeds) EXPECT_LE(bytes, e.in_packet) << what << " (input)";
                break;
            case protocol::hid::MainItemKind::output:
                ++outputs;
                for (const Endpoints& e : speeds) EXPECT_LE(bytes, e.out_packet) << what << " (output)";
                break;
            case protocol::hid::MainItemKind::feature:
                // The control pipe: SET_REPORT / GET_REPORT carry up to 4096 bytes here.
                EXPECT_LE(bytes, 4096u) << what << " (feature)";
                if (bytes > speeds[0].in_packet) ++oversize_features;
                break;
        }
    }
    EXPECT_EQ(inputs, 7);    // Joystick Input, PID State, Command Status, Device Status,
                             // Dynamic Report, Command Error Text, Effect States
    EXPECT_EQ(outputs, 24);  // every host-to-device report but the four features
    EXPECT_EQ(oversize_features, 1);  // Device Info, 361 bytes
}

}  // namespace
}  // namespace feel::usb::detail
