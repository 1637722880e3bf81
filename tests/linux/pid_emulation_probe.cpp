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
//   emu play NAME start=MONO stop=MONO blocks=X,Y updates=U levels=L
//   emu reads NAME MONO MONO ...       (the host's clock readings: one per update)
//   emu done sensations=3 errors=0
// MONO: CLOCK_MONOTONIC in seconds (the clock the device's log is stamped with).
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

// The host's clock: the steady clock, each reading also kept as CLOCK_MONOTONIC.
struct ClockLog {
    std::mutex mu;
    std::vector<double> readings;
    bool on = false;
};

// The host's end of the link, recording what PidDevice reads and sends while `on`: each
// Set Constant Force with the send time and the Input report received last before it (the
// report the level was computed from: PidDevice renders every report it reads and sends
// once it has read all that is queued).
class RecordingLink final : public transport::Connection {
public:
    explicit RecordingLink(std::unique_ptr<transport::Connection> inner) : inner_(std::move(inner)) {}
    struct Sent {
        double sent, read;
        std::vector<uint8_t> level_report, input_report;
    };
    void send(const transport::Frame& f) override {
        if (f.kind == transport::FrameKind::output_report) {
            std::lock_guard lock(mu_);
            if (on_) sent_.push_back({monotonic_s(), last_read_, f.payload, last_input_});
        }
        inner_->send(f);
    }
    std::optional<transport::Frame> receive(std::chrono::milliseconds timeout) override {
        std::optional<transport::Frame> f = inner_->receive(timeout);
        if (f && f->kind == transport::FrameKind::input_report) {
            std::lock_guard lock(mu_);
            last_read_ = monotonic_s();
            last_input_ = f->payload;
        }
        return f;
    }
    void close() noexcept override { inner_->close(); }
    [[nodiscard]] std::string peer() const override { return inner_->peer(); }
    void record(bool on) {
        std::lock_guard lock(mu_);
        on_ = on;
        if (on) sent_.clear();
    }
    std::vector<Sent> sent() {
        std::lock_guard lock(mu_);
        return sent_;
    }

private:
    std::unique_ptr<transport::Connection> inner_;
    std::mutex mu_;
    bool on_ = false;
    double last_read_ = 0;
    std::vector<uint8_t> last_input_;
    std::vector<Sent> sent_;
};

struct Sensation {
    const char* name;
    EffectParams params;
};

}  // namespace

int main(int argc, char** argv) {
    const std::string node = argc > 1 ? argv[1] : "/dev/hidraw0";
    describe_descriptor(node);
    auto clock_log = std::make_shared<ClockLog>();
    const auto epoch = std::chrono::steady_clock::now();
    std::unique_ptr<transport::Connection> connection;
    try {
        connection = transport::connect(transport::Address::parse("hidraw:" + node), std::chrono::milliseconds(2000));
    } catch (const std::exception& e) {
        std::printf("emu error open: %s\n", e.what());
        return 1;
    }
    auto recording = std::make_unique<RecordingLink>(std::move(connection));
    RecordingLink* link = recording.get();
    host::OpenOptions options;
    options.emulation_profile = "iforce2";  // the gadget's profile: the host's engine assumes its mechanism
    host::Result<host::PidDevice> device = host::PidDevice::attach(
        std::move(recording), "hidraw:" + node, options, [clock_log, epoch] {
            const auto now = std::chrono::steady_clock::now();
            {
                std::lock_guard lock(clock_log->mu);
                if (clock_log->on) clock_log->readings.push_back(monotonic_s());
            }
            return std::chrono::duration_cast<std::chrono::microseconds>(now - epoch).count();
        });
    if (!device) {
        std::printf("emu error open: %s\n", device.status().message.c_str());
        return 1;
    }
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
            std::lock_guard lock(clock_log->mu);
            clock_log->readings.clear();
            clock_log->on = true;
        }
        link->record(true);
        const double start = monotonic_s();
        if (!device->start(*handle).ok()) ++errors;
        host::Result<host::EffectStatusInfo> status = device->status(*handle);
        if (!status || status->state != runtime::ReportedEffectState::emulated) {
            std::printf("emu error status %s: not emulated while it plays\n", s.name);
            ++errors;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(1500));
        const double stop = monotonic_s();
        link->record(false);
        if (!device->stop(*handle).ok()) ++errors;
        std::vector<double> readings;
        {
            std::lock_guard lock(clock_log->mu);
            clock_log->on = false;
            readings.swap(clock_log->readings);
        }
        const host::PidEmulationStats after = device->emulation_stats();
        std::printf("emu play %s start=%.6f stop=%.6f blocks=%d,%d updates=%lld levels=%lld\n", s.name, start, stop,
                    after.link_blocks.size() > 0 ? after.link_blocks[0] : 0,
                    after.link_blocks.size() > 1 ? after.link_blocks[1] : 0,
                    static_cast<long long>(after.updates - before.updates),
                    static_cast<long long>(after.levels_sent - before.levels_sent));
        // Each level sent, with the position the host rendered it from (the device's layout).
        const protocol::pid::PidLayout& layout = device->layout();
        for (const RecordingLink::Sent& sent : link->sent()) {
            const auto block = protocol::pid::read_field(layout, protocol::pid::PidReport::set_constant_force,
                                                         sent.level_report, 0x000F0022);  // Effect Block Index
            const auto level = protocol::pid::read_field(layout, protocol::pid::PidReport::set_constant_force,
                                                         sent.level_report, 0x000F0070);  // Magnitude
            protocol::pid::JoystickReading reading;
            if (!block || !level || !protocol::pid::read_joystick(layout, sent.input_report, reading)) continue;
            std::printf("emu level %s sent=%.6f read=%.6f block=%lld magnitude=%lld x=%.0f y=%.0f\n", s.name, sent.sent,
                        sent.read, static_cast<long long>(*block), static_cast<long long>(*level),
                        static_cast<double>(reading.position[0]), static_cast<double>(reading.position[1]));
        }
        std::printf("emu reads %s", s.name);
        for (double r : readings) std::printf(" %.6f", r);
        std::printf("\n");
        if (!device->free_effect(*handle).ok()) ++errors;
        ++played;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the force back to 0 between sensations
    }
    device->close();
    std::printf("emu done sensations=%d errors=%d\n", played, errors);
    return errors == 0 ? 0 : 1;
}
