// The USB side of `feel device --usb` against a hostile host (src/usb): SETUP packets for
// classify_setup(), interrupt OUT packets for the ReportAssembler, and the reports it
// completes through PidCommitOrder, as the FunctionFS server chains them.
//
// Input: a script of steps [op u8][payload]: op 0 a SETUP packet (8 bytes), op 1 an OUT
// packet ([length u8][bytes], at most 64), op 2 time passing ([ms u8]). Checks: a stalled
// request always says why; a served request keeps the host's wLength; every report the
// assembler completes reaches the session side unless it is a Set Effect, which is held
// and then forwarded; nothing the commit order forwards is a frame it never received.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <vector>

#include "../src/usb/hid_requests.hpp"
#include "../src/usb/pid_commit_order.hpp"
#include "../src/usb/report_assembler.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    using namespace feel::usb::detail;
    ReportAssembler assembler(64);
    PidCommitOrder order;
    auto now = PidCommitOrder::Clock::time_point{} + std::chrono::seconds(1);
    std::set<std::vector<uint8_t>> received;
    auto check = [&](const std::vector<feel::transport::Frame>& out) {
        for (const auto& f : out) {
            if (!received.count(f.payload)) std::abort();  // forwarded a frame it never got
        }
    };
    std::size_t at = 0;
    while (at < size) {
        const uint8_t op = data[at++] % 3;
        if (op == 0) {
            if (size - at < 8) break;
            SetupPacket s;
            s.request_type = data[at];
            s.request = data[at + 1];
            s.value = static_cast<uint16_t>(data[at + 2] | (data[at + 3] << 8));
            s.index = static_cast<uint16_t>(data[at + 4] | (data[at + 5] << 8));
            s.length = static_cast<uint16_t>(data[at + 6] | (data[at + 7] << 8));
            at += 8;
            const ControlAction a = classify_setup(s);
            if (a.kind == ControlAction::Kind::stall && a.reason.empty()) std::abort();
            if (a.kind != ControlAction::Kind::stall && a.kind != ControlAction::Kind::acknowledge &&
                a.length != s.length) {
                std::abort();
            }
        } else if (op == 1) {
            if (at >= size) break;
            const std::size_t wanted = data[at] % 65;
            ++at;
            const std::size_t n = std::min<std::size_t>(wanted, size - at);
            if (assembler.add({data + at, n})) {
                feel::transport::Frame f{feel::transport::FrameKind::output_report, assembler.take()};
                received.insert(f.payload);
                check(order.on_frame(std::move(f), now));
            }
            at += n;
        } else {
            if (at >= size) break;
            now += std::chrono::milliseconds(data[at++]);
            check(order.on_time(now));
        }
    }
    return 0;
}
