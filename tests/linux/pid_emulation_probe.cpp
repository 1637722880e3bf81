// pid_emulation_probe: host emulation on a plain USB HID PID gadget, in the VM
// (tests/linux/pid_host_case.sh). The gadget is `feel device --sim --usb
// --standard-pid-only`: its report descriptor has PID's reports alone, so feel's host
// (feel::host::PidDevice over hidraw) plays a wall, a texture and a recoil by rendering them
// on the positions the Input report carries and streaming the force as Set Constant Force.
// tests/linux/check_pid_emulation.cpp compares the force the device applied (its log) with
// the device-side rendering of the same sensations.
//
//   pid_emulation_probe /dev/hidrawN
//
// Prints, for the checker:
//   emu descriptor bytes=N reports=R vendor_usages=0     (read from sysfs, parsed here)
//   emu caps feel_device=0 types=11 emulated=WALL,TEXTURE,RECOIL problem=""
//   emu play NAME start=MONO stop=MONO blocks=X,Y updates=U levels=L updates_before=B updates_started=S
//   emu update NAME arrival=MONO sense=MONO x=X y=Y stalled=0   (each render: what it read)
//   emu level NAME sent=MONO arrival=MONO sense=MONO block=B magnitude=M x=X y=Y
//                                      (each Set Constant Force, with the report it came from)
//   emu done sensations=3 errors=0
// MONO: CLOCK_MONOTONIC in seconds (the clock the device's log is stamped with). A sense
// time is the host's reconstruction (src/host/emulation/sense_clock.hpp) on that clock: the
// report's sensing plus the link's least delay.
#include <time.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "emulation_sensations.hpp"
#include "feel/host/pid_device.hpp"
#include "feel/protocol/descriptor_parser.hpp"
#include "feel/protocol/pid_layout.hpp"
#include "feel/transport/transport.hpp"

namespace {

using namespace feel;

double monotonic_s() {
    timespec ts{};
    ::clock_gettime(CLOCK_MONOTONIC, &ts);
    return static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec) * 1e-9;
}

// The descriptor the kernel got from the gadget (sysfs), parsed: how many of its usages are
// off the standard pages (a vendor page is 0xFF00 and above).
void describe_descriptor(const std::string& node) {
    const std::string name = node.substr(node.rfind('/') + 1);
    std::ifstream in("/sys/class/hidraw/" + name + "/device/report_descriptor", std::ios::binary);
    const std::vector<uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const protocol::hid::DescriptorParse parse = protocol::hid::parse_report_descriptor(bytes);
    int vendor = 0;
    for (const auto& r : parse.descriptor.reports)
        for (const auto& f : r.fields) {
            for (uint32_t u : f.usages) vendor += (u >> 16) >= 0xFF00 ? 1 : 0;
            for (uint32_t c : f.collections) vendor += (c >> 16) >= 0xFF00 ? 1 : 0;
        }
    std::printf("emu descriptor bytes=%zu parsed=%d reports=%zu vendor_usages=%d\n", bytes.size(), parse.ok() ? 1 : 0,
                parse.descriptor.reports.size(), vendor);
}

// What the host rendered from, per render (PidDevice::observe_emulation), while `on`.
struct RenderLog {
    std::mutex mu;
    bool on = false;
    std::vector<host::PidEmulationUpdate> updates;
    std::vector<double> sent_at;  // CLOCK_MONOTONIC after the render's levels went
};

struct Sensation {
    const char* name;
    EffectParams params;
};

}  // namespace

int main(int argc, char** argv) {
    const std::string node = argc > 1 ? argv[1] : "/dev/hidraw0";
    describe_descriptor(node);
    const auto epoch = std::chrono::steady_clock::now();
    std::unique_ptr<transport::Connection> connection;
    try {
        connection = transport::connect(transport::Address::parse("hidraw:" + node), std::chrono::milliseconds(2000));
    } catch (const std::exception& e) {
        std::printf("emu error open: %s\n", e.what());
        return 1;
    }
    host::OpenOptions options;
    options.emulation_profile = "iforce2";  // the gadget's profile: the host's engine assumes its mechanism
    host::Result<host::PidDevice> device = host::PidDevice::attach(
        std::move(connection), "hidraw:" + node, options, [epoch] {
            const auto now = std::chrono::steady_clock::now();
            return std::chrono::duration_cast<std::chrono::microseconds>(now - epoch).count();
        });
    if (!device) {
        std::printf("emu error open: %s\n", device.status().message.c_str());
        return 1;
    }
    // The host clock (µs since epoch, the steady clock) as CLOCK_MONOTONIC, seconds.
    const double epoch_mono = std::chrono::duration<double>(epoch.time_since_epoch()).count();
    auto render_log = std::make_shared<RenderLog>();
    device->observe_emulation([render_log](const host::PidEmulationUpdate& u) {
        std::lock_guard lock(render_log->mu);
        if (!render_log->on) return;
        render_log->updates.push_back(u);
        render_log->sent_at.push_back(monotonic_s());
    });
    const host::PidCaps& caps = device->capabilities();
    int types = 0;
    for (const auto& e : caps.effect_types) types += e.usable ? 1 : 0;
    const auto emulated = [&](EffectType t) { return (caps.emulated_types & effect_type_bit(t)) != 0 ? 1 : 0; };
    std::printf("emu caps feel_device=%d types=%d wall=%d texture=%d recoil=%d problem=\"%s\"\n", caps.feel_device ? 1 : 0,
                types, emulated(EffectType::axis_wall), emulated(EffectType::texture),
                emulated(EffectType::dynamic_recoil), caps.emulation_problem.c_str());

    std::vector<Sensation> sensations;
    for (const std::string_view name : test::vm::kSensations) sensations.push_back({name.data(), test::vm::sensation(name)});
    int errors = 0;
    int played = 0;
    for (const Sensation& s : sensations) {
        host::Result<uint16_t> handle = device->create_effect(s.params);
        if (!handle || !device->emulated(*handle)) {
            std::printf("emu error create %s: %s\n", s.name,
                        handle ? "the device plays it itself" : handle.status().message.c_str());
            ++errors;
            continue;
        }
        const host::PidEmulationStats before = device->emulation_stats();
        {
            std::lock_guard lock(render_log->mu);
            render_log->updates.clear();
            render_log->sent_at.clear();
            render_log->on = true;
        }
        const double start = monotonic_s();
        if (!device->start(*handle).ok()) ++errors;
        const host::PidEmulationStats started = device->emulation_stats();
        host::Result<host::EffectStatusInfo> status = device->status(*handle);
        if (!status || status->state != runtime::ReportedEffectState::emulated) {
            std::printf("emu error status %s: not emulated while it plays\n", s.name);
            ++errors;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));
        const double stop = monotonic_s();
        {
            std::lock_guard lock(render_log->mu);
            render_log->on = false;
        }
        if (!device->stop(*handle).ok()) ++errors;
        const host::PidEmulationStats after = device->emulation_stats();
        // started: the renders before start() returned (the effect plays from the first
        // render after `updates_before`, at the latest from the one after `updates_started`).
        std::printf("emu play %s start=%.6f stop=%.6f blocks=%d,%d updates=%lld levels=%lld updates_before=%lld "
                    "updates_started=%lld\n",
                    s.name, start, stop, after.link_blocks.size() > 0 ? after.link_blocks[0] : 0,
                    after.link_blocks.size() > 1 ? after.link_blocks[1] : 0,
                    static_cast<long long>(after.updates - before.updates),
                    static_cast<long long>(after.levels_sent - before.levels_sent),
                    static_cast<long long>(before.updates), static_cast<long long>(started.updates));
        // What the host rendered from: every render of the recording (its report's arrival
        // and sense time, positions) and each level it sent after it.
        std::lock_guard lock(render_log->mu);
        for (std::size_t i = 0; i < render_log->updates.size(); ++i) {
            const host::PidEmulationUpdate& u = render_log->updates[i];
            std::printf("emu update %s arrival=%.6f sense=%.6f x=%.0f y=%.0f stalled=%d\n", s.name,
                        epoch_mono + static_cast<double>(u.arrival_us) * 1e-6,
                        epoch_mono + static_cast<double>(u.sense_us) * 1e-6, static_cast<double>(u.position[0]),
                        static_cast<double>(u.position[1]), u.stalled ? 1 : 0);
            for (const auto& [block, level] : u.sent) {
                std::printf("emu level %s sent=%.6f arrival=%.6f sense=%.6f block=%d magnitude=%d x=%.0f y=%.0f\n",
                            s.name, render_log->sent_at[i], epoch_mono + static_cast<double>(u.arrival_us) * 1e-6,
                            epoch_mono + static_cast<double>(u.sense_us) * 1e-6, block, level,
                            static_cast<double>(u.position[0]), static_cast<double>(u.position[1]));
            }
        }
        if (!device->free_effect(*handle).ok()) ++errors;
        ++played;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the force back to 0 between sensations
    }
    device->close();
    std::printf("emu done sensations=%d errors=%d\n", played, errors);
    return errors == 0 ? 0 : 1;
}
