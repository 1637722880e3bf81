// hidraw_probe: feel's USB device driven through the kernel's hidraw, whatever hid-pidff
// thinks of it. It exercises every path of the FunctionFS backend through real USB
// transfers: GET_REPORT(Feature) on ep0 (Device Info, then Block Load), SET_REPORT(Feature)
// on ep0 (Create New Effect), output reports on the interrupt OUT endpoint (a constant
// force, its Set Effect, start), and input reports on the interrupt IN endpoint (the
// CommandStatus answers), and prints what came back for the checker:
//
//   hidraw get device_info bytes=N decoded=1 device=iforce2
//   hidraw get block_load bytes=N block=B status=1
//   hidraw status command=C block=B code=K field=...
//
// The reports are made with feel's own encoder (a host speaking feel's protocol); what is
// tested is that they cross the kernel's USB stack both ways intact.
#include <fcntl.h>
#include <linux/hidraw.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"

namespace {

using namespace feel::protocol;

int get_feature(int fd, ReportId id, AnyReport& out) {
    std::vector<uint8_t> buf(report_size(static_cast<uint8_t>(id)), 0);
    buf[0] = static_cast<uint8_t>(id);
    const int n = ::ioctl(fd, HIDIOCGFEATURE(buf.size()), buf.data());
    if (n <= 0) return n;
    buf.resize(static_cast<std::size_t>(n));
    return decode(buf, out) ? -1000 : n;
}

bool send_output(int fd, const AnyReport& r) {
    const std::vector<uint8_t> bytes = encode(r);
    return ::write(fd, bytes.data(), bytes.size()) == static_cast<ssize_t>(bytes.size());
}

// A refusal's text comes in Command Error Text reports before its CommandStatus.
CommandAnswerJoiner error_text;

// Prints the statuses that come within `milliseconds`; returns early once the status of
// command `until_command` has come (none: -1).
void read_statuses(int fd, int milliseconds, int until_command = -1) {
    std::vector<uint8_t> buf(4096);
    timespec start{}, now{};
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (;;) {
        clock_gettime(CLOCK_MONOTONIC, &now);
        const long elapsed = (now.tv_sec - start.tv_sec) * 1000 + (now.tv_nsec - start.tv_nsec) / 1000000;
        if (elapsed >= milliseconds) return;
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, static_cast<int>(milliseconds - elapsed)) <= 0) return;
        const ssize_t n = ::read(fd, buf.data(), buf.size());
        if (n <= 0) return;
        AnyReport r;
        if (decode({buf.data(), static_cast<std::size_t>(n)}, r)) continue;
        if (const auto* t = std::get_if<CommandErrorTextReport>(&r)) error_text.add(*t);
        if (const auto* s = std::get_if<CommandStatusReport>(&r)) {
            const CommandAnswer answer = error_text.finish(*s);
            const std::string field(answer.field_text());
            std::printf("hidraw status command=%u block=%u code=%u field=%s\n", static_cast<unsigned>(s->command),
                        s->block, static_cast<unsigned>(s->code), field.empty() ? "-" : field.c_str());
            if (static_cast<int>(s->command) == until_command) return;
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const char* path = argc > 1 ? argv[1] : "/dev/hidraw0";
    const int fd = ::open(path, O_RDWR | O_NONBLOCK);
    if (fd < 0) {
        std::perror(path);
        return 1;
    }
    AnyReport info;
    const int n = get_feature(fd, ReportId::device_info, info);
    std::printf("hidraw get device_info bytes=%d decoded=%d device=%s\n", n, n > 0 ? 1 : 0,
                n > 0 ? std::get<DeviceInfoReport>(info).device : "-");

    CreateNewEffectReport create;
    create.sequence = 1;
    create.type = feel::EffectType::constant;
    const std::vector<uint8_t> bytes = encode(create);
    const int set = ::ioctl(fd, HIDIOCSFEATURE(bytes.size()), bytes.data());
    std::printf("hidraw set create_new_effect result=%d\n", set);
    AnyReport load;
    const int got = get_feature(fd, ReportId::block_load, load);
    const uint16_t block = got > 0 ? std::get<BlockLoadReport>(load).block : 0;
    std::printf("hidraw get block_load bytes=%d block=%u status=%u\n", got, block,
                got > 0 ? static_cast<unsigned>(std::get<BlockLoadReport>(load).status) : 0u);
    read_statuses(fd, 300);
    if (block == 0) return 1;

    SetConstantForceReport force;
    force.sequence = 2;
    force.block = block;
    force.magnitude = 6000;
    SetEffectReport effect;
    effect.sequence = 3;
    effect.block = block;
    effect.type = feel::EffectType::constant;
    effect.duration_us = 500000;
    EffectOperationReport start;
    start.sequence = 4;
    start.block = block;
    // In this order: feel's transaction (the type block, then Set Effect), then play.
    const bool wrote_force = send_output(fd, force);
    const bool wrote_effect = send_output(fd, effect);
    const bool wrote_start = send_output(fd, start);
    std::printf("hidraw write set_constant_force=%d set_effect=%d effect_operation=%d\n", wrote_force, wrote_effect,
                wrote_start);
    // Until the last one's answer (Effect Operation, command 10), however long the load on
    // the machine running the VM makes it: a deadline, not a fixed wait (1.5 s was too short
    // once, on a VM whose loop ran 38 % of its ticks late).
    read_statuses(fd, 15000, 10);

    // A host flooding the device: Device Gain reports as fast as the interrupt OUT endpoint
    // takes them, for 3 s, while the device logs its loop rate (the checker compares).
    timespec t0{}, t{};
    clock_gettime(CLOCK_MONOTONIC, &t0);
    long updates = 0;
    std::vector<uint8_t> drain(4096);
    for (;;) {
        clock_gettime(CLOCK_MONOTONIC, &t);
        if (static_cast<double>(t.tv_sec - t0.tv_sec) + static_cast<double>(t.tv_nsec - t0.tv_nsec) * 1e-9 >= 3.0) break;
        DeviceGainReport gain;
        gain.sequence = static_cast<uint32_t>(100 + updates);
        gain.gain = static_cast<uint16_t>(5000 + updates % 5000);
        if (!send_output(fd, gain)) break;
        ++updates;
        while (::read(fd, drain.data(), drain.size()) > 0) {
        }
    }
    std::printf("flood start=%ld.%06ld end=%ld.%06ld updates=%ld\n", static_cast<long>(t0.tv_sec), t0.tv_nsec / 1000,
                static_cast<long>(t.tv_sec), t.tv_nsec / 1000, updates);
    ::close(fd);
    return 0;
}
