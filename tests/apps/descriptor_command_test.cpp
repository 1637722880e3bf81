// feel descriptor: the bytes it prints are the descriptor a device of that profile answers
// GET_DESCRIPTOR with, and an independent HID parser reads in them exactly the profile's
// inputs (axes, buttons, hat switches) next to the PID reports.
#include <sstream>
#include <string>
#include <vector>

#include "cli_fixture.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "feel/sim/device_profile.hpp"

namespace feel::cli::testing {
namespace {

class Descriptor : public CliTest {};

std::vector<uint8_t> bytes_of_hex(const std::string& text) {
    std::vector<uint8_t> bytes;
    std::istringstream in(text);
    for (std::string token; in >> token;) bytes.push_back(static_cast<uint8_t>(std::stoul(token, nullptr, 16)));
    return bytes;
}

// The Joystick Input report's data usages, element by element.
std::vector<uint32_t> joystick_usages(const std::vector<uint8_t>& descriptor) {
    const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(descriptor);
    EXPECT_TRUE(parse.ok()) << parse.error;
    const protocol::hid::DescriptorReport* joy = parse.descriptor.find(
        protocol::hid::MainItemKind::input, static_cast<uint8_t>(protocol::ReportId::joystick_input));
    std::vector<uint32_t> usages;
    if (joy == nullptr) return usages;
    for (const protocol::hid::DescriptorField& f : joy->fields) {
        if (f.is_constant()) continue;
        for (uint32_t k = 0; k < f.report_count; ++k) usages.push_back(f.usage_of(k));
    }
    return usages;
}

TEST_F(Descriptor, HexIsTheProfilesDescriptor) {
    for (const sim::DeviceProfile& profile : sim::device_profiles()) {
        SCOPED_TRACE(std::string(profile.name));
        const Result r = run_cli({"descriptor", "--profile", std::string(profile.name)});
        ASSERT_EQ(r.code, kExitOk) << r.err;
        const std::vector<uint8_t> bytes = bytes_of_hex(r.out);
        // HID Usage Tables: the profile's axes are Generic Desktop X (0x30).., each button a
        // Button usage, each hat a Hat Switch (0x39); nothing else is an input.
        std::vector<uint32_t> expected;
        for (int a = 0; a < profile.axis_count; ++a) {
            expected.push_back(0x00010030u + static_cast<uint32_t>(profile.axes[a].axis));
        }
        for (int b = 1; b <= profile.button_count; ++b) expected.push_back(0x00090000u + static_cast<uint32_t>(b));
        for (int h = 0; h < profile.hat_count; ++h) expected.push_back(0x00010039u);
        EXPECT_EQ(joystick_usages(bytes), expected);
    }
}

TEST_F(Descriptor, CAndDecodedFormatsNameTheItems) {
    const Result c = run_cli({"descriptor", "--profile", "joystick", "--format", "c"});
    ASSERT_EQ(c.code, kExitOk) << c.err;
    EXPECT_NE(c.out.find("static const unsigned char feel_report_descriptor["), std::string::npos);
    EXPECT_NE(c.out.find("0x05, 0x01, "), std::string::npos) << "Usage Page (Generic Desktop)";
    const Result d = run_cli({"descriptor", "--profile", "joystick", "--format", "decoded"});
    ASSERT_EQ(d.code, kExitOk) << d.err;
    EXPECT_EQ(d.out.rfind("Usage Page (Generic Desktop)\nUsage (0x04)\nCollection (Application)\n", 0), 0u)
        << d.out.substr(0, 200);
    EXPECT_NE(d.out.find("Usage Page (Physical Interface Device)"), std::string::npos);
    EXPECT_NE(d.out.find("Usage (0x56)"), std::string::npos) << "Direction Enable";
    EXPECT_EQ(d.out.substr(d.out.size() - std::string("End Collection\n").size()), "End Collection\n");
}

TEST_F(Descriptor, RefusesAnUnknownProfileOrFormat) {
    Result r = run_cli({"descriptor", "--profile", "nope"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("--profile \"nope\" is not a known device (available: joystick"), std::string::npos) << r.err;
    r = run_cli({"descriptor", "--format", "json"});
    EXPECT_EQ(r.code, kExitUsage);
    EXPECT_NE(r.err.find("--format \"json\" is not a format (allowed: hex, c, decoded)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace feel::cli::testing
