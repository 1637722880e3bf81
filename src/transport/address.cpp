// Addresses ("sim:PROFILE", "unix:PATH", "tcp:HOST:PORT"), frame kind names and the default
// socket directory.
//
// Parsing is strict and every refusal says what is wrong and which forms are allowed: an
// address is typed by people on command lines (--device, --listen), and "connection
// refused" for a typo'd port is a poor answer. A bare word is a profile name (sim:WORD) so
// that `--device iforce1` works; a bare word that looks like a path or a host is refused
// with a hint instead of being taken for a profile nobody has.
#include <sys/un.h>
#include <unistd.h>

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "feel/transport/transport.hpp"

namespace feel::transport {
namespace {

constexpr std::string_view kAllowedForms =
    "allowed sim:PROFILE, unix:PATH, tcp:HOST:PORT with PORT 1..65535, hidraw:/dev/hidrawN or "
    "usb:VID:PID[:SERIAL] with VID and PID 4 hex digits";

[[noreturn]] void refuse(std::string_view text, std::string_view why) {
    std::string message = "\"";
    message += text;
    message += "\" is not an address: ";
    message += why;
    message += " (";
    message += kAllowedForms;
    message += ")";
    throw std::invalid_argument(message);
}

bool is_profile_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_' || c == '.';
}

// HOST:PORT with HOST possibly an IPv6 literal in brackets ("[::1]:5000").
Address parse_tcp(std::string_view text, std::string_view rest, bool allow_port_zero) {
    std::string_view host;
    std::string_view port_text;
    bool has_port_separator = false;
    if (!rest.empty() && rest.front() == '[') {
        const std::size_t close = rest.find(']');
        if (close == std::string_view::npos) refuse(text, "the IPv6 host's ']' is missing");
        host = rest.substr(1, close - 1);
        const std::string_view after = rest.substr(close + 1);
        if (!after.empty()) {
            if (after.front() != ':') refuse(text, "expected ':PORT' after the IPv6 host");
            has_port_separator = true;
            port_text = after.substr(1);
        }
    } else {
        const std::size_t colon = rest.rfind(':');
        if (colon == std::string_view::npos) {
            host = rest;
        } else {
            host = rest.substr(0, colon);
            port_text = rest.substr(colon + 1);
            has_port_separator = true;
            if (host.find(':') != std::string_view::npos)
                refuse(text, "an IPv6 host must be written in brackets, e.g. tcp:[::1]:5000");
        }
    }
    if (host.empty()) refuse(text, "the host is empty");
    if (!has_port_separator || port_text.empty()) refuse(text, "the port is missing");
    unsigned long port = 0;
    const auto [end, error] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
    if (error != std::errc{} || end != port_text.data() + port_text.size()) {
        if (error == std::errc::result_out_of_range) refuse(text, "the port is out of range");
        refuse(text, "the port \"" + std::string(port_text) + "\" is not a number");
    }
    if (port > 65535) refuse(text, "the port " + std::string(port_text) + " is out of range");
    if (port == 0 && !allow_port_zero) refuse(text, "the port 0 is not a port a host can connect to");
    Address address;
    address.kind = Address::Kind::tcp;
    address.host = std::string(host);
    address.port = static_cast<uint16_t>(port);
    return address;
}

uint16_t parse_usb_id(std::string_view text, std::string_view id, std::string_view what) {
    unsigned value = 0;
    const auto [end, error] = std::from_chars(id.data(), id.data() + id.size(), value, 16);
    if (id.size() != 4 || error != std::errc{} || end != id.data() + id.size())
        refuse(text, "the " + std::string(what) + " \"" + std::string(id) + "\" is not 4 hex digits");
    return static_cast<uint16_t>(value);
}

// usb:VID:PID[:SERIAL]
Address parse_usb(std::string_view text, std::string_view rest) {
    const std::size_t colon = rest.find(':');
    if (colon == std::string_view::npos) refuse(text, "the product ID is missing (usb:VID:PID)");
    Address address;
    address.kind = Address::Kind::usb;
    address.vendor_id = parse_usb_id(text, rest.substr(0, colon), "vendor ID");
    const std::string_view after = rest.substr(colon + 1);
    const std::size_t serial_colon = after.find(':');
    address.product_id = parse_usb_id(text, after.substr(0, serial_colon), "product ID");
    if (serial_colon != std::string_view::npos) {
        address.serial = std::string(after.substr(serial_colon + 1));
        if (address.serial.empty()) refuse(text, "the serial number after the last ':' is empty");
    }
    return address;
}

Address parse_address(std::string_view text, bool allow_port_zero) {
    if (text.empty()) refuse(text, "it is empty");
    const std::size_t colon = text.find(':');
    if (colon == std::string_view::npos) {
        // A bare word: a profile name.
        if (text == "sim" || text == "unix" || text == "tcp" || text == "hidraw" || text == "usb")
            refuse(text, "the ':' after the scheme is missing");
        if (text.find('/') != std::string_view::npos)
            refuse(text, "a socket path needs the unix: scheme, e.g. unix:" + std::string(text));
        for (const char c : text) {
            if (!is_profile_char(c))
                refuse(text, "a bare word is read as a profile name, which may hold only letters, digits, "
                             "'-', '_' and '.'");
        }
        Address address;
        address.kind = Address::Kind::sim;
        address.profile = std::string(text);
        return address;
    }
    const std::string_view scheme = text.substr(0, colon);
    const std::string_view rest = text.substr(colon + 1);
    if (scheme == "sim") {
        if (rest.empty()) refuse(text, "the profile name is empty");
        Address address;
        address.kind = Address::Kind::sim;
        address.profile = std::string(rest);
        return address;
    }
    if (scheme == "unix") {
        if (rest.empty()) refuse(text, "the socket path is empty");
        // A Unix socket's address holds at most sizeof(sun_path) - 1 bytes of path.
        constexpr std::size_t kMaxPath = sizeof(sockaddr_un::sun_path) - 1;
        if (rest.size() > kMaxPath) {
            refuse(text, "the socket path is " + std::to_string(rest.size()) + " bytes long (allowed 1.." +
                             std::to_string(kMaxPath) + " bytes)");
        }
        Address address;
        address.kind = Address::Kind::unix_socket;
        address.path = std::string(rest);
        return address;
    }
    if (scheme == "tcp") {
        // tcp:HOST:PORT?token=TOKEN: the one query a tcp address takes.
        const std::size_t query = rest.find('?');
        if (query == std::string_view::npos) return parse_tcp(text, rest, allow_port_zero);
        const std::string_view parameter = rest.substr(query + 1);
        constexpr std::string_view kTokenKey = "token=";
        if (parameter.substr(0, kTokenKey.size()) != kTokenKey)
            refuse(text, "the only query a tcp address takes is ?token=TOKEN");
        const std::string_view token = parameter.substr(kTokenKey.size());
        if (const std::string problem = check_token(token); !problem.empty()) refuse(text, "the token " + problem);
        Address address = parse_tcp(text, rest.substr(0, query), allow_port_zero);
        address.token = std::string(token);
        return address;
    }
    if (scheme == "hidraw") {
        if (rest.empty()) refuse(text, "the hidraw node's path is empty (e.g. hidraw:/dev/hidraw0)");
        if (allow_port_zero) refuse(text, "a hidraw device is a device to open, not a place to listen");
        Address address;
        address.kind = Address::Kind::hidraw;
        address.path = std::string(rest);
        return address;
    }
    if (scheme == "usb") {
        if (allow_port_zero) refuse(text, "a USB device is a device to open, not a place to listen");
        return parse_usb(text, rest);
    }
    refuse(text, "the scheme \"" + std::string(scheme) + "\" is unknown");
}

}  // namespace

Address Address::parse(std::string_view text) { return parse_address(text, false); }

Address Address::parse_listen(std::string_view text) { return parse_address(text, true); }

std::string Address::to_string() const {
    switch (kind) {
        case Kind::sim:
            return "sim:" + profile;
        case Kind::unix_socket:
            return "unix:" + path;
        case Kind::tcp:
            if (host.find(':') != std::string::npos) return "tcp:[" + host + "]:" + std::to_string(port);
            return "tcp:" + host + ":" + std::to_string(port);
        case Kind::hidraw:
            return "hidraw:" + path;
        case Kind::usb: {
            char ids[16];
            std::snprintf(ids, sizeof ids, "%04x:%04x", vendor_id, product_id);
            return "usb:" + std::string(ids) + (serial.empty() ? "" : ":" + serial);
        }
    }
    return "sim:" + profile;
}

std::string_view frame_kind_name(FrameKind kind) noexcept {
    switch (kind) {
        case FrameKind::output_report: return "output_report";
        case FrameKind::input_report: return "input_report";
        case FrameKind::set_feature: return "set_feature";
        case FrameKind::get_feature: return "get_feature";
        case FrameKind::feature_reply: return "feature_reply";
        case FrameKind::get_descriptor: return "get_descriptor";
        case FrameKind::descriptor_reply: return "descriptor_reply";
        case FrameKind::busy: return "busy";
        case FrameKind::hello: return "hello";
    }
    return "unknown";
}

std::string default_socket_dir() {
    const char* runtime_dir = std::getenv("XDG_RUNTIME_DIR");
    if (runtime_dir != nullptr && runtime_dir[0] != '\0') return std::string(runtime_dir) + "/feel";
    return "/tmp/feel-" + std::to_string(::getuid());
}

}  // namespace feel::transport
