// Force streaming runs in the loop's tick: it must never allocate. A hooked global allocator
// counts every allocation while (1) a ForceStream is fed and read through everything it
// does (60 Hz and 1 kHz streams, bursts, a long hold, clear) and (2) the pipeline takes a
// stream of stream_force commands (good and refused) with an effect playing, through pause,
// gain, stop-all and the host watchdog, and the host drains the acks.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <optional>
#include <span>

#include "feel/runtime/force_stream.hpp"
#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "support/counting_allocator.hpp"

namespace feel::runtime {
namespace {

TEST(ForceStreamAllocation, TheCounterSeesAllocations) {
    counting = true;
    auto* probe = new int(7);
    counting = false;
    EXPECT_GT(allocations.exchange(0), 0);
    delete probe;
}

TEST(ForceStreamAllocation, TheFilterNeverAllocates) {
    ForceStream stream(6, 1000);
    float out[kMaxAxes];
    float sum = 0;
    counting = true;
    for (int64_t t = 0; t < 20'000; ++t) {
        const bool fast = t >= 5000 && t < 8000;
        const bool send = fast || t % 17 == 0 || t % 97 == 1;  // 60 Hz with early frames
        if (send && t < 15'000) {
            const int16_t f[6] = {static_cast<int16_t>(t % 20001 - 10000), 1, -1, 2, -2, 3};
            stream.push(t, f);
            if (t % 500 == 0) stream.push(t, f);  // two in one tick
        }
        if (t == 18'000) stream.clear();
        stream.output(t, out);
        add_streamed_force(out, 6, 7000, t % 1000 < 900, out);
        sum += out[0];
    }
    counting = false;
    EXPECT_EQ(allocations.exchange(0), 0);
    EXPECT_TRUE(sum == sum);  // used
}

TEST(ForceStreamAllocation, ThePipelineStreamsWithoutAllocating) {
    const sim::DeviceProfile& profile = *sim::find_device_profile("joystick");
    RuntimeConfig config = runtime_config_for(profile);
    config.safety.fade_in_us = 0;
    config.safety.host_timeout_us = 200'000;
    RuntimePipeline pipeline(config, std::make_unique<SimBackend>(profile, sim::Grip::firm,
                                                                  sim::TargetMotion::hold_at({0})));
    HostLink host(pipeline.commands(), pipeline.reports());
    EffectParams push;
    push.type = EffectType::constant;
    push.duration_us = kInfiniteUs;
    push.axis_count = 1;
    push.constant.magnitude = 6000;
    ASSERT_TRUE(host.create(push).has_value());
    pipeline.tick(0);
    Report report;
    EffectId id{};
    while (host.poll(report)) {
        if (report.kind == ReportKind::ack) id = report.ack.effect;
    }
    ASSERT_TRUE(id.valid());
    ASSERT_TRUE(host.start_effect(id).has_value());

    int64_t sent = 1;  // the start above, acked in the first tick below
    int64_t acks = 0;
    int64_t refused = 0;
    const auto count = [&sent](std::optional<uint32_t> sequence) { sent += sequence.has_value() ? 1 : 0; };
    counting = true;
    for (int64_t n = 1; n < 6000; ++n) {
        const bool silent = n >= 4000 && n < 4500;  // the watchdog trips in there
        if (!silent && (n < 2000 ? n % 17 == 0 : true)) {
            const int16_t force[2] = {static_cast<int16_t>((n * 37) % 20001 - 10000), static_cast<int16_t>(n % 5000)};
            count(host.stream_force(force));
        }
        if (!silent && n % 301 == 0) {
            const int16_t bad[2] = {0, 12000};
            count(host.stream_force(bad));
            count(host.stream_force(std::span<const int16_t>(bad, 1)));
        }
        if (n == 2500) count(host.control(DeviceControl::pause));
        if (n == 2700) count(host.control(DeviceControl::resume));
        if (n == 3000) count(host.set_gain(4000));
        if (n == 3500) count(host.control(DeviceControl::stop_all));
        pipeline.tick(n);
        while (host.poll(report)) {
            if (report.kind != ReportKind::ack) continue;
            ++acks;
            if (!report.ack.error.ok()) ++refused;
        }
    }
    counting = false;
    EXPECT_EQ(allocations.exchange(0), 0);
    EXPECT_EQ(acks, sent);  // every command, refused or not, answered
    EXPECT_GT(sent, 3600);
    EXPECT_EQ(refused, 2 * (5999 / 301 - 1));  // one multiple of 301 (4214) falls in the silence
    EXPECT_EQ(pipeline.counters().host_losses, 1);
}

}  // namespace
}  // namespace feel::runtime
