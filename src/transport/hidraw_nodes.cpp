// The hidraw nodes sysfs lists, a usb: address resolved to one of them, and the udev rule
// that opens a device to its user (feel/transport/hidraw.hpp).
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string_view>
#include <system_error>

#include "feel/transport/hidraw.hpp"

namespace feel::transport {
namespace {

namespace fs = std::filesystem;

constexpr uint32_t kBusUsb = 0x03;  // linux/input.h BUS_USB

std::string read_text(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<uint8_t> read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

uint32_t hex_value(std::string_view text) {
    uint32_t value = 0;
    std::from_chars(text.data(), text.data() + text.size(), value, 16);
    return value;
}

// The uevent's HID_ID=0003:0000046D:0000C294, HID_NAME=..., HID_UNIQ=...
void read_uevent(const std::string& uevent, HidrawNode& node) {
    std::istringstream lines(uevent);
    for (std::string line; std::getline(lines, line);) {
        const std::size_t eq = line.find('=');
        if (eq == std::string::npos) continue;
        const std::string_view key(line.data(), eq);
        const std::string_view value(line.data() + eq + 1, line.size() - eq - 1);
        if (key == "HID_NAME") node.name = std::string(value);
        if (key == "HID_UNIQ") node.serial = std::string(value);
        if (key == "HID_ID") {
            const std::size_t a = value.find(':');
            const std::size_t b = value.find(':', a == std::string_view::npos ? a : a + 1);
            if (a == std::string_view::npos || b == std::string_view::npos) continue;
            node.bus = hex_value(value.substr(0, a));
            node.vendor_id = static_cast<uint16_t>(hex_value(value.substr(a + 1, b - a - 1)));
            node.product_id = static_cast<uint16_t>(hex_value(value.substr(b + 1)));
        }
    }
}

int node_number(const std::string& name) {
    int n = -1;
    const std::string_view digits = std::string_view(name).substr(std::string_view("hidraw").size());
    std::from_chars(digits.data(), digits.data() + digits.size(), n);
    return n;
}

std::string ids(uint16_t vendor_id, uint16_t product_id) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04x:%04x", vendor_id, product_id);
    return buf;
}

}  // namespace

std::vector<HidrawNode> list_hidraw_nodes(const HidrawRoots& roots) {
    std::vector<std::pair<int, HidrawNode>> found;
    std::error_code ec;
    const fs::path class_dir = fs::path(roots.sysfs) / "class" / "hidraw";
    for (fs::directory_iterator it(class_dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.rfind("hidraw", 0) != 0) continue;
        HidrawNode node;
        node.node = (fs::path(roots.dev) / name).string();
        const fs::path device = it->path() / "device";
        read_uevent(read_text(device / "uevent"), node);
        node.report_descriptor = read_bytes(device / "report_descriptor");
        if (node.name.empty() && node.report_descriptor.empty() && node.vendor_id == 0) continue;
        found.emplace_back(node_number(name), std::move(node));
    }
    std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<HidrawNode> out;
    out.reserve(found.size());
    for (auto& [number, node] : found) out.push_back(std::move(node));
    return out;
}

std::string find_usb_node(const Address& address, const HidrawRoots& roots) {
    const std::vector<HidrawNode> nodes = list_hidraw_nodes(roots);
    std::string others;
    for (const HidrawNode& n : nodes) {
        if (n.bus != kBusUsb) continue;
        if (n.vendor_id == address.vendor_id && n.product_id == address.product_id &&
            (address.serial.empty() || n.serial == address.serial)) {
            return n.node;
        }
        others += (others.empty() ? "" : ", ") + ids(n.vendor_id, n.product_id) +
                  (n.serial.empty() ? "" : ":" + n.serial);
    }
    throw TransportError(TransportError::Kind::refused,
                         "no USB HID device " + address.to_string().substr(4) + " is connected (" +
                             (others.empty() ? std::string("no USB HID device at all") : "USB HID devices present: " + others) +
                             "; `feel devices` lists the force-feedback ones)");
}

std::string hidraw_udev_rule(uint16_t vendor_id, uint16_t product_id) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "KERNEL==\"hidraw*\", ATTRS{idVendor}==\"%04x\", ATTRS{idProduct}==\"%04x\", MODE=\"0660\", "
                  "TAG+=\"uaccess\"",
                  vendor_id, product_id);
    return buf;
}

}  // namespace feel::transport
