// Addresses: the three forms, their printing, and a clear refusal for every malformed one.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <string>

#include "feel/transport/transport.hpp"

namespace feel::transport {
namespace {

// The message of the std::invalid_argument that parsing `text` throws ("" if none).
std::string parse_error(std::string_view text, bool listen = false) {
    try {
        (void)(listen ? Address::parse_listen(text) : Address::parse(text));
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(Address, ParsesTheThreeForms) {
    const Address sim = Address::parse("sim:iforce1");
    EXPECT_EQ(sim.kind, Address::Kind::sim);
    EXPECT_EQ(sim.profile, "iforce1");

    const Address unix_socket = Address::parse("unix:/run/user/1000/feel/sim.sock");
    EXPECT_EQ(unix_socket.kind, Address::Kind::unix_socket);
    EXPECT_EQ(unix_socket.path, "/run/user/1000/feel/sim.sock");

    const Address tcp = Address::parse("tcp:localhost:5000");
    EXPECT_EQ(tcp.kind, Address::Kind::tcp);
    EXPECT_EQ(tcp.host, "localhost");
    EXPECT_EQ(tcp.port, 5000);

    const Address v6 = Address::parse("tcp:[::1]:65535");
    EXPECT_EQ(v6.host, "::1");
    EXPECT_EQ(v6.port, 65535);
    EXPECT_EQ(Address::parse("tcp:127.0.0.1:1").port, 1);
}

TEST(Address, ATcpAddressMayCarryTheDevicesTokenWhichIsNeverPrinted) {
    const Address a = Address::parse("tcp:10.0.0.5:5000?token=Xy-9_z");
    EXPECT_EQ(a.host, "10.0.0.5");
    EXPECT_EQ(a.port, 5000);
    EXPECT_EQ(a.token, "Xy-9_z");
    EXPECT_EQ(a.to_string(), "tcp:10.0.0.5:5000");
    EXPECT_EQ(Address::parse("tcp:[::1]:7?token=t").token, "t");
    for (const char* bad : {"tcp:h:1?token=", "tcp:h:1?key=abc", "tcp:h:1?token=a b", "tcp:h:1?"}) {
        try {
            (void)Address::parse(bad);
            ADD_FAILURE() << bad << " was taken";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("token"), std::string::npos) << e.what();
        }
    }
}

TEST(Address, ABareProfileNameIsASimAddress) {
    const Address a = Address::parse("iforce1");
    EXPECT_EQ(a.kind, Address::Kind::sim);
    EXPECT_EQ(a.profile, "iforce1");
    EXPECT_EQ(a.to_string(), "sim:iforce1");
}

TEST(Address, PrintsWhatItParses) {
    for (const char* text : {"sim:iforce2", "unix:/tmp/feel-1000/sim.sock", "unix:relative.sock", "tcp:127.0.0.1:8",
                             "tcp:example.org:65535", "tcp:[::1]:5000"}) {
        EXPECT_EQ(Address::parse(text).to_string(), text);
        EXPECT_EQ(Address::parse(Address::parse(text).to_string()), Address::parse(text));
    }
}

TEST(Address, RefusesEveryMalformedFormNamingTheProblem) {
    struct Case {
        const char* text;
        const char* why;
    };
    const Case cases[] = {
        {"", "it is empty"},
        {"serial:0", "the scheme \"serial\" is unknown"},
        {"usb:0", "the product ID is missing"},
        {"http://localhost:80", "the scheme \"http\" is unknown"},
        {"sim:", "the profile name is empty"},
        {"unix:", "the socket path is empty"},
        {"tcp:localhost", "the port is missing"},
        {"tcp:localhost:", "the port is missing"},
        {"tcp:", "the host is empty"},
        {"tcp::5000", "the host is empty"},
        {"tcp:localhost:0", "the port 0"},
        {"tcp:localhost:65536", "out of range"},
        {"tcp:localhost:99999999999999999999", "out of range"},
        {"tcp:localhost:http", "the port \"http\" is not a number"},
        {"tcp:localhost:50a", "the port \"50a\" is not a number"},
        {"tcp:localhost:-1", "the port \"-1\" is not a number"},
        {"tcp:::1:5000", "in brackets"},
        {"tcp:[::1:5000", "']' is missing"},
        {"tcp:[::1]5000", "':PORT'"},
        {"tcp:[::1]", "the port is missing"},
        {"tcp", "the ':' after the scheme is missing"},
        {"unix", "the ':' after the scheme is missing"},
        {"/tmp/feel.sock", "unix:/tmp/feel.sock"},
        {"my profile", "profile name"},
    };
    for (const Case& c : cases) {
        const std::string message = parse_error(c.text);
        ASSERT_FALSE(message.empty()) << "\"" << c.text << "\" was accepted";
        EXPECT_NE(message.find(c.why), std::string::npos) << c.text << ": " << message;
        // Every refusal quotes the text and lists the allowed forms.
        EXPECT_NE(message.find("\"" + std::string(c.text) + "\" is not an address"), std::string::npos) << message;
        EXPECT_NE(message.find("sim:PROFILE, unix:PATH, tcp:HOST:PORT with PORT 1..65535, hidraw:/dev/hidrawN or usb:VID:PID"), std::string::npos)
            << message;
    }
}

TEST(Address, RefusesAUnixPathLongerThanASocketAddressHolds) {
    // sockaddr_un holds 108 bytes of path on Linux, its terminating NUL included.
    const std::string longest = "unix:/" + std::string(106, 'a');   // 107 bytes of path
    EXPECT_EQ(parse_error(longest.c_str()), "");
    const std::string too_long = "unix:/" + std::string(107, 'a');  // 108 bytes
    const std::string message = parse_error(too_long.c_str());
    EXPECT_NE(message.find("the socket path is 108 bytes long (allowed 1..107 bytes)"), std::string::npos) << message;
}

TEST(Address, ListenAddressesMayAskForAnyFreePort) {
    EXPECT_EQ(Address::parse_listen("tcp:127.0.0.1:0").port, 0);
    EXPECT_EQ(Address::parse_listen("tcp:127.0.0.1:7").port, 7);
    EXPECT_NE(parse_error("tcp:127.0.0.1:65536", true).find("out of range"), std::string::npos);
    EXPECT_NE(parse_error("tcp:127.0.0.1", true).find("the port is missing"), std::string::npos);
}

TEST(FrameKind, EveryKindHasAName) {
    EXPECT_EQ(frame_kind_name(FrameKind::output_report), "output_report");
    EXPECT_EQ(frame_kind_name(FrameKind::input_report), "input_report");
    EXPECT_EQ(frame_kind_name(FrameKind::set_feature), "set_feature");
    EXPECT_EQ(frame_kind_name(FrameKind::get_feature), "get_feature");
    EXPECT_EQ(frame_kind_name(FrameKind::feature_reply), "feature_reply");
    EXPECT_EQ(frame_kind_name(FrameKind::get_descriptor), "get_descriptor");
    EXPECT_EQ(frame_kind_name(FrameKind::descriptor_reply), "descriptor_reply");
    EXPECT_EQ(frame_kind_name(FrameKind::busy), "busy");
    EXPECT_EQ(frame_kind_name(FrameKind::hello), "hello");
    EXPECT_EQ(frame_kind_name(static_cast<FrameKind>(0)), "unknown");
    EXPECT_FALSE(is_frame_kind(0));
    for (int k = 1; k <= kFrameKindCount; ++k) EXPECT_TRUE(is_frame_kind(static_cast<uint8_t>(k)));
    EXPECT_FALSE(is_frame_kind(kFrameKindCount + 1));
    EXPECT_FALSE(is_frame_kind(255));
}

TEST(DefaultSocketDir, IsUnderTheRuntimeDirElseTmpPerUser) {
    const char* saved = std::getenv("XDG_RUNTIME_DIR");
    const std::string saved_value = saved != nullptr ? saved : "";
    ::setenv("XDG_RUNTIME_DIR", "/run/user/4242", 1);
    EXPECT_EQ(default_socket_dir(), "/run/user/4242/feel");
    ::unsetenv("XDG_RUNTIME_DIR");
    EXPECT_EQ(default_socket_dir(), "/tmp/feel-" + std::to_string(::getuid()));
    ::setenv("XDG_RUNTIME_DIR", "", 1);
    EXPECT_EQ(default_socket_dir(), "/tmp/feel-" + std::to_string(::getuid()));
    if (saved != nullptr) {
        ::setenv("XDG_RUNTIME_DIR", saved_value.c_str(), 1);
    } else {
        ::unsetenv("XDG_RUNTIME_DIR");
    }
}

TEST(Address, ParsesTheHidrawAndUsbForms) {
    const Address hidraw = Address::parse("hidraw:/dev/hidraw3");
    EXPECT_EQ(hidraw.kind, Address::Kind::hidraw);
    EXPECT_EQ(hidraw.path, "/dev/hidraw3");
    EXPECT_EQ(hidraw.to_string(), "hidraw:/dev/hidraw3");

    const Address usb = Address::parse("usb:1209:FFB0");
    EXPECT_EQ(usb.kind, Address::Kind::usb);
    EXPECT_EQ(usb.vendor_id, 0x1209);
    EXPECT_EQ(usb.product_id, 0xFFB0);
    EXPECT_TRUE(usb.serial.empty());
    EXPECT_EQ(usb.to_string(), "usb:1209:ffb0");
    const Address with_serial = Address::parse("usb:045e:001b:A1B2");
    EXPECT_EQ(with_serial.serial, "A1B2");
    EXPECT_EQ(with_serial.to_string(), "usb:045e:001b:A1B2");

    EXPECT_NE(parse_error("hidraw:").find("path is empty"), std::string::npos);
    EXPECT_NE(parse_error("usb:1209").find("product ID is missing"), std::string::npos);
    EXPECT_NE(parse_error("usb:12G9:ffb0").find("vendor ID \"12G9\" is not 4 hex digits"), std::string::npos);
    EXPECT_NE(parse_error("usb:1209:ffb").find("product ID \"ffb\" is not 4 hex digits"), std::string::npos);
    EXPECT_NE(parse_error("usb:1209:ffb0:").find("serial number"), std::string::npos);
    EXPECT_NE(parse_error("hidraw:/dev/hidraw0", true).find("not a place to listen"), std::string::npos);
    EXPECT_NE(parse_error("usb:1209:ffb0", true).find("not a place to listen"), std::string::npos);
}

}  // namespace
}  // namespace feel::transport
