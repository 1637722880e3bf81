// feel device --sim --usb (usb_device_command.hpp, docs/usb-device.md).
#include "usb_device_command.hpp"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <thread>

#include "cli.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/usb/usb_device.hpp"

namespace feel::cli {

using namespace std::chrono_literals;

uint16_t parse_usb_id(const char* flag, const std::string& text) {
    std::size_t used = 0;
    unsigned long value = 0;
    bool ok = !text.empty() && text[0] != '-' && text[0] != '+';
    if (ok) {
        try {
            value = std::stoul(text, &used, 0);  // 0x prefix: hex, else decimal
        } catch (const std::exception&) {
            ok = false;
        }
    }
    if (!ok || used != text.size() || value > 0xFFFF) {
        throw UsageError(std::string(flag) + " = \"" + text +
                         "\" is not a USB ID (allowed 0x0000..0xFFFF, hex with 0x or decimal)");
    }
    return static_cast<uint16_t>(value);
}

int run_usb_device(const DeviceArgs& device, const UsbDeviceArgs& usb, std::ostream& out, std::ostream& /*err*/,
                   std::atomic<bool>& stop) {
    if (!device.sim) {
        throw UsageError("only simulated devices exist yet: run `feel device --sim --usb`");
    }
    if (!device.listen.empty()) {
        throw UsageError("--listen and --usb exclude each other: a USB device's host comes over USB");
    }
    if (!usb.ffs.empty() && !usb.udc.empty()) {
        throw UsageError("--udc and --ffs exclude each other: with --ffs, whoever set up the FunctionFS "
                         "instance binds it to a UDC");
    }
    peripheral::PeripheralOptions options = peripheral_options(device);
    options.host_watchdog = false;  // the bus reports the host's going (FunctionFS DISABLE)
    usb::GadgetOptions gadget_options;
    gadget_options.udc = usb.udc;
    gadget_options.vendor_id = parse_usb_id("--vid", usb.vid);
    gadget_options.product_id = parse_usb_id("--pid", usb.pid);
    gadget_options.manufacturer = usb.manufacturer;
    gadget_options.product = usb.product;
    gadget_options.serial = usb.serial;

    std::ofstream log_file;
    if (!usb.log.empty()) {
        log_file.open(usb.log, std::ios::out | std::ios::trunc);
        if (!log_file) throw std::runtime_error("cannot write the device log " + usb.log);
    }
    std::ostream* log = usb.log.empty() ? nullptr : &log_file;

    const auto started = std::chrono::steady_clock::now();
    peripheral::Peripheral peripheral(options);
    std::optional<usb::ConfigfsGadget> gadget;
    if (usb.ffs.empty()) gadget.emplace(gadget_options);
    const std::string ffs_dir = gadget ? gadget->ffs_dir() : usb.ffs;
    usb::FunctionFsServer server(peripheral, ffs_dir, usb::FunctionOptions{}, log);
    if (gadget) gadget->bind();

    const runtime::Capabilities& caps = peripheral.capabilities();
    char ids[16];
    std::snprintf(ids, sizeof ids, "%04x:%04x", gadget_options.vendor_id, gadget_options.product_id);
    out << "feel device: " << caps.device << " (" << caps.class_name << ") on USB "
        << (gadget ? std::string(ids) + " via " + gadget->udc() : "FunctionFS " + ffs_dir) << ", loop "
        << peripheral.runtime().config().loop_rate_hz << " Hz" << std::endl;

    while (!stop.load(std::memory_order_relaxed)) std::this_thread::sleep_for(20ms);

    if (gadget) gadget->unbind();  // the host sees the device unplugged
    server.stop();
    peripheral.stop();
    const usb::FunctionStats u = server.stats();
    const peripheral::PeripheralStats s = peripheral.stats();
    gadget.reset();  // unmounts FunctionFS and removes the gadget
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    char uptime[32];
    std::snprintf(uptime, sizeof uptime, "%.1f", seconds);
    out << "feel device: stopped after " << uptime << " s: " << u.hosts << " USB host session"
        << (u.hosts == 1 ? "" : "s") << ", " << u.setups << " control requests (" << u.stalled << " stalled), "
        << u.output_reports << " output reports, " << u.input_reports << " input reports sent ("
        << u.input_dropped << " dropped unread), " << s.reports_received << " reports decoded ("
        << s.reports_refused << " refused); loop " << s.runtime.pipeline.ticks << " ticks, "
        << s.runtime.loop.overruns << " overruns" << std::endl;
    return kExitOk;
}

}  // namespace feel::cli
