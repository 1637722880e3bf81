// A device never trusts its host: malformed, truncated, out-of-order and meaningless
// reports are each answered with an error status naming what is wrong, and leave the
// device exactly as it was (its blocks, its engine, its pool).
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "feel/units.hpp"
#include "session_rig.hpp"

namespace feel::peripheral::test {
namespace {

using protocol::EffectOperation;
using protocol::ReportId;

bool same_view(const std::optional<BlockView>& a, const std::optional<BlockView>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    return a->block == b->block && a->type == b->type && a->committed == b->committed && a->effect == b->effect &&
           a->committed_params == b->committed_params && a->shadow == b->shadow;
}

// Everything a hostile report could corrupt.
struct Snapshot {
    int32_t allocated = 0;
    int32_t committed = 0;
    std::vector<std::optional<BlockView>> blocks;
    int32_t resident = 0;
    EffectState sine_state = EffectState::free;
    protocol::PidPoolReport pool{};
};

class HostileHost : public ::testing::Test {
protected:
    // Block 1: a sine, committed and playing. Block 2: a spring allocated, one axis of its
    // conditions received, not committed. Block 3: a force profile with 32 of its 64
    // samples received.
    void SetUp() override {
        ASSERT_EQ(rig.create(EffectType::sine), 1);
        rig.ok(periodic(rig.next_sequence(), 1, 2500, 20'000));
        rig.ok(set_effect(rig.next_sequence(), 1, EffectType::sine));
        rig.ok(operation(rig.next_sequence(), 1, EffectOperation::start, protocol::kLoopInfinite));
        ASSERT_EQ(rig.create(EffectType::spring), 2);
        rig.ok(spring_axis(rig.next_sequence(), 2, 0, 1500));
        ASSERT_EQ(rig.create(EffectType::force_profile, 64), 3);
        rig.ok(data(0, 24));  // a Custom Force Data report carries up to 24 samples
        rig.ok(data(24, 8));
        rig.run(3);
    }

    protocol::CustomForceDataReport data(uint16_t offset, uint8_t count, uint16_t block = 3) {
        protocol::CustomForceDataReport d;
        d.sequence = rig.next_sequence();
        d.block = block;
        d.offset = offset;
        d.count = count;
        for (int i = 0; i < count; ++i) d.samples[i] = static_cast<int16_t>(i * 10);
        return d;
    }

    Snapshot snapshot() {
        Snapshot s;
        s.allocated = rig.session().allocated_blocks();
        s.committed = rig.session().committed_blocks();
        for (int b = 1; b <= rig.session().block_capacity(); ++b) s.blocks.push_back(rig.session().block(static_cast<uint16_t>(b)));
        s.resident = rig.pipeline().resident_effects();
        s.sine_state = rig.pipeline().engine().state(rig.session().block(1)->effect);
        s.pool = rig.get<protocol::PidPoolReport>(ReportId::pid_pool);
        return s;
    }

    void expect_unchanged(const Snapshot& before, const char* what) {
        const Snapshot after = snapshot();
        EXPECT_EQ(after.allocated, before.allocated) << what;
        EXPECT_EQ(after.committed, before.committed) << what;
        ASSERT_EQ(after.blocks.size(), before.blocks.size());
        for (std::size_t i = 0; i < after.blocks.size(); ++i) {
            EXPECT_TRUE(same_view(after.blocks[i], before.blocks[i])) << what << ": block " << i + 1 << " changed";
        }
        EXPECT_EQ(after.resident, before.resident) << what;
        EXPECT_EQ(after.sine_state, before.sine_state) << what;
        EXPECT_EQ(after.pool.ram_pool_available, before.pool.ram_pool_available) << what;
        EXPECT_EQ(after.pool.free_effects, before.pool.free_effects) << what;
        EXPECT_EQ(after.pool.free_samples, before.pool.free_samples) << what;
    }

    // Offers a raw frame and returns the one CommandStatus it got.
    protocol::CommandAnswer raw(Frame f) {
        const std::size_t seen = rig.statuses.size();
        rig.offer(std::move(f));
        rig.run(3);
        EXPECT_EQ(rig.statuses.size(), seen + 1) << "one frame, one answer";
        return rig.statuses.size() > seen ? rig.statuses[seen] : protocol::CommandAnswer{};
    }

    SessionRig rig;
};

TEST_F(HostileHost, TypeBlockForAnUnallocatedBlock) {
    const Snapshot before = snapshot();
    const auto s = rig.command(spring_axis(rig.next_sequence(), 5, 0, 1000));
    EXPECT_EQ(s.code, ErrorCode::invalid_handle);
    EXPECT_STREQ(s.field, "set_condition.block");
    EXPECT_EQ(s.block, 5);
    EXPECT_NE(std::string(s.rule).find("not allocated"), std::string::npos) << s.rule;
    expect_unchanged(before, "Set Condition for block 5");

    // Beyond the device's 32 blocks: the range is named.
    const auto far = rig.command(spring_axis(rig.next_sequence(), 40, 0, 1000));
    EXPECT_EQ(far.code, ErrorCode::invalid_parameter);
    EXPECT_TRUE(far.has_range);
    EXPECT_EQ(far.value, 40);
    EXPECT_EQ(far.allowed_min, 1);
    EXPECT_EQ(far.allowed_max, 32);
    expect_unchanged(before, "Set Condition for block 40");
}

TEST_F(HostileHost, SetEffectBeforeCreateNewEffect) {
    const Snapshot before = snapshot();
    const auto s = rig.command(set_effect(rig.next_sequence(), 6, EffectType::spring));
    EXPECT_EQ(s.code, ErrorCode::invalid_handle);
    EXPECT_STREQ(s.field, "set_effect.block");
    expect_unchanged(before, "Set Effect for block 6");
}

TEST_F(HostileHost, TypeBlockThatDoesNotFitTheEffect) {
    const Snapshot before = snapshot();
    const auto s = rig.command(spring_axis(rig.next_sequence(), 1, 0, 1000));  // a condition on the sine
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(s.field, "set_condition");
    EXPECT_NE(std::string(s.rule).find("sine"), std::string::npos) << s.rule;
    expect_unchanged(before, "Set Condition on a sine");

    protocol::SetSweepReport sweep;  // angles for a wave that does not sweep
    sweep.sequence = rig.next_sequence();
    sweep.block = 1;
    EXPECT_EQ(rig.command(sweep).code, ErrorCode::invalid_parameter);

    // Set Effect naming another type than the block's.
    const auto t = rig.command(set_effect(rig.next_sequence(), 1, EffectType::square));
    EXPECT_EQ(t.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(t.field, "set_effect.type");
    expect_unchanged(before, "Set Effect of another type");
}

TEST_F(HostileHost, CustomForceDataOutOfOrder) {
    const Snapshot before = snapshot();
    const auto gap = rig.command(data(64, 24));  // 32 received: the next offset is 32
    EXPECT_EQ(gap.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(gap.field, "custom_force_data.offset");
    EXPECT_TRUE(gap.has_range);
    EXPECT_EQ(gap.value, 64);
    EXPECT_EQ(gap.allowed_max, 32);
    const auto again = rig.command(data(16, 8));  // overlapping what came
    EXPECT_EQ(again.code, ErrorCode::invalid_parameter);
    const auto elsewhere = rig.command(data(32, 8, 1));  // samples for the sine
    EXPECT_EQ(elsewhere.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(elsewhere.field, "custom_force_data");
    expect_unchanged(before, "Custom Force Data out of order");

    // The stage was not disturbed: the rest in order completes the profile.
    rig.ok(data(32, 24));
    rig.ok(data(56, 8));
    protocol::SetCustomForceReport cf;
    cf.sequence = rig.next_sequence();
    cf.block = 3;
    cf.sample_period_us = 1000;
    cf.sample_count = 64;
    rig.ok(cf);
    rig.ok(set_effect(rig.next_sequence(), 3, EffectType::force_profile));
    EXPECT_TRUE(rig.session().block(3)->committed);
}

TEST_F(HostileHost, ForceProfileCommittedWithoutItsSamples) {
    protocol::SetCustomForceReport cf;
    cf.sequence = rig.next_sequence();
    cf.block = 3;
    cf.sample_period_us = 1000;
    cf.sample_count = 64;
    rig.ok(cf);
    const auto s = rig.command(set_effect(rig.next_sequence(), 3, EffectType::force_profile));
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(s.field, "custom_force_data");
    EXPECT_EQ(s.value, 32);  // received
    EXPECT_EQ(s.allowed_min, 64);
    EXPECT_FALSE(rig.session().block(3)->committed);
    EXPECT_EQ(rig.pipeline().resident_effects(), 1);
}

TEST_F(HostileHost, BlockFreeTwice) {
    protocol::BlockFreeReport f;
    f.sequence = rig.next_sequence();
    f.block = 2;
    rig.ok(f);
    const Snapshot before = snapshot();
    f.sequence = rig.next_sequence();
    const auto s = rig.command(f);
    EXPECT_EQ(s.code, ErrorCode::invalid_handle);
    EXPECT_STREQ(s.field, "block_free.block");
    EXPECT_EQ(s.sequence, f.sequence);
    expect_unchanged(before, "Block Free twice");
}

TEST_F(HostileHost, OperationsOnABlockNotDownloaded) {
    const Snapshot before = snapshot();
    const auto start = rig.command(operation(rig.next_sequence(), 2, EffectOperation::start));
    EXPECT_EQ(start.code, ErrorCode::invalid_handle);
    EXPECT_NE(std::string(start.rule).find("not downloaded"), std::string::npos) << start.rule;
    protocol::EffectStatusRequestReport q;
    q.sequence = rig.next_sequence();
    q.block = 2;
    EXPECT_EQ(rig.command(q).code, ErrorCode::invalid_handle);
    protocol::ReflexReport r;
    r.sequence = rig.next_sequence();
    r.block = 2;
    EXPECT_EQ(rig.command(r).code, ErrorCode::invalid_handle);
    expect_unchanged(before, "operations on block 2");
}

TEST_F(HostileHost, GarbageBytes) {
    const Snapshot before = snapshot();
    // An id that names no report: sequence 0 (unreadable), the decoder's error.
    auto s = raw(Frame{FrameKind::output_report, {0xEE, 0x01, 0x02, 0x03}});
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(s.sequence, 0u);
    EXPECT_STREQ(s.field, "report.id");
    // Nothing at all.
    s = raw(Frame{FrameKind::output_report, {}});
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(s.sequence, 0u);
    // A known id with bytes that are not its report: the sequence is read back, the
    // command named.
    s = raw(Frame{FrameKind::output_report, {0x03, 0x2A, 0x00, 0x00, 0x00, 0xFF}});
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(s.sequence, 42u);
    EXPECT_EQ(s.command, ReportId::set_condition);
    expect_unchanged(before, "garbage bytes");
}

TEST_F(HostileHost, TruncatedAndOutOfRangeReports) {
    const Snapshot before = snapshot();
    protocol::SetEffectReport e = set_effect(77, 1, EffectType::sine);
    e.gain = 3000;
    std::vector<uint8_t> bytes = protocol::encode(e);
    bytes.pop_back();
    auto s = raw(Frame{FrameKind::output_report, bytes});
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(s.sequence, 77u);
    EXPECT_EQ(s.command, ReportId::set_effect);
    EXPECT_STREQ(s.field, "report.length");

    // A deadband of 20000 (the field's range is 0..10000), patched into valid bytes: the
    // last two bytes before the offset mode.
    bytes = protocol::encode(spring_axis(78, 2, 0, 1000));
    const std::size_t deadband = bytes.size() - 3;
    bytes[deadband] = 0x20;
    bytes[deadband + 1] = 0x4E;  // 20000 little-endian
    s = raw(Frame{FrameKind::output_report, bytes});
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_EQ(s.sequence, 78u);
    EXPECT_STREQ(s.field, "set_condition.deadband");
    EXPECT_TRUE(s.has_range);
    EXPECT_EQ(s.value, 20000);
    EXPECT_EQ(s.allowed_max, 10000);
    expect_unchanged(before, "truncated and out-of-range reports");
}

TEST_F(HostileHost, ReportsInTheWrongFrame) {
    const Snapshot before = snapshot();
    // An input report sent to the device, an output report as a feature, a feature the
    // host may only get, feature gets of reports that are not features.
    protocol::JoystickInputReport j;
    auto s = raw(Frame{FrameKind::output_report, protocol::encode(j)});
    EXPECT_STREQ(s.field, "frame.kind");
    s = raw(Frame{FrameKind::set_feature, protocol::encode(set_effect(90, 1, EffectType::sine))});
    EXPECT_STREQ(s.field, "frame.kind");
    EXPECT_EQ(s.sequence, 90u);
    protocol::PidPoolReport pool;
    s = raw(Frame{FrameKind::set_feature, protocol::encode(pool)});
    EXPECT_STREQ(s.field, "frame.kind");
    protocol::CreateNewEffectReport c;
    c.sequence = 91;
    c.type = EffectType::sine;
    s = raw(Frame{FrameKind::output_report, protocol::encode(c)});
    EXPECT_STREQ(s.field, "frame.kind");
    EXPECT_EQ(s.sequence, 91u);
    s = raw(Frame{FrameKind::get_feature, {static_cast<uint8_t>(ReportId::set_effect)}});
    EXPECT_STREQ(s.field, "get_feature.report_id");
    s = raw(Frame{FrameKind::get_feature, {0x12, 0x12}});
    EXPECT_STREQ(s.field, "get_feature.length");
    s = raw(Frame{FrameKind::feature_reply, {0x12}});
    EXPECT_STREQ(s.field, "frame.kind");
    s = raw(Frame{FrameKind::get_descriptor, {1}});
    EXPECT_STREQ(s.field, "get_descriptor.length");
    expect_unchanged(before, "reports in the wrong frame");
}

TEST_F(HostileHost, ManyFramesAtOnceStayBounded) {
    // A host that floods: the inbox takes kInboxFrames, then refuses; nothing grows.
    int taken = 0;
    for (int i = 0; i < 1000; ++i) {
        protocol::KeepAliveReport k;
        k.sequence = static_cast<uint32_t>(i);
        if (rig.session().offer(output(k))) ++taken;
    }
    EXPECT_EQ(taken, static_cast<int>(kInboxFrames));
    EXPECT_FALSE(rig.session().accepting());
    const std::size_t seen = rig.statuses.size();
    rig.run(20);
    EXPECT_EQ(rig.statuses.size(), seen + kInboxFrames);
    EXPECT_TRUE(rig.session().idle());
}

TEST(DeviceLimits, DeviceFullAfterMaxEffects) {
    SessionRig rig("iforce1");
    for (int i = 1; i <= 16; ++i) ASSERT_EQ(rig.create(EffectType::sine), i);
    protocol::CreateNewEffectReport c;
    c.sequence = rig.next_sequence();
    c.type = EffectType::sine;
    const auto s = rig.command(c, true);
    EXPECT_EQ(s.code, ErrorCode::device_full);
    const auto load = rig.get<protocol::BlockLoadReport>(ReportId::block_load);
    EXPECT_EQ(load.status, protocol::BlockLoadStatus::full);
    EXPECT_EQ(load.block, 0);
    // Freeing one makes room for one.
    protocol::BlockFreeReport f;
    f.sequence = rig.next_sequence();
    f.block = 7;
    rig.ok(f);
    EXPECT_EQ(rig.create(EffectType::sine), 7);
}

TEST(DeviceLimits, DynamicOnAnIforce1IsNotSupported) {
    SessionRig rig("iforce1");
    protocol::CreateNewEffectReport c;
    c.sequence = rig.next_sequence();
    c.type = EffectType::dynamic_recoil;
    const auto s = rig.command(c, true);
    EXPECT_EQ(s.code, ErrorCode::not_supported);
    EXPECT_STREQ(s.field, "create_new_effect.type");
    EXPECT_NE(std::string(s.rule).find("I-FORCE 1.x"), std::string::npos) << s.rule;
    EXPECT_EQ(rig.get<protocol::BlockLoadReport>(ReportId::block_load).status, protocol::BlockLoadStatus::error);
    EXPECT_EQ(rig.session().allocated_blocks(), 0);
}

TEST(DeviceLimits, EngineRefusalNamesFieldAndRangeAndRollsBack) {
    SessionRig rig;
    const uint16_t block = rig.create(EffectType::sine);
    // A period of 0 ms is a valid time on the wire but a wave of no frequency for the engine.
    rig.ok(periodic(rig.next_sequence(), block, 500, 0));
    const auto s = rig.command(set_effect(rig.next_sequence(), block, EffectType::sine));
    EXPECT_EQ(s.code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(s.field, "periodic.period_us");
    EXPECT_TRUE(s.has_range);
    EXPECT_EQ(s.value, 0);
    EXPECT_EQ(s.allowed_min, range::kPeriodUs.min);
    EXPECT_EQ(s.allowed_max, range::kPeriodUs.max);
    EXPECT_EQ(rig.pipeline().resident_effects(), 0);
    // The refused transaction is gone: the block is as Create New Effect left it.
    const auto view = rig.session().block(block);
    ASSERT_TRUE(view.has_value());
    EXPECT_FALSE(view->committed);
    EXPECT_EQ(view->shadow, view->committed_params);
    const auto again = rig.command(set_effect(rig.next_sequence(), block, EffectType::sine));
    EXPECT_STREQ(again.field, "set_periodic");  // its Set Periodic must come again

    // A refused update leaves the committed effect as it was and the shadow with it.
    rig.ok(periodic(rig.next_sequence(), block, 3000, 20'000));
    rig.ok(set_effect(rig.next_sequence(), block, EffectType::sine));
    const EffectParams committed = rig.session().block(block)->committed_params;
    rig.ok(periodic(rig.next_sequence(), block, 3000, 0));
    EXPECT_EQ(rig.command(set_effect(rig.next_sequence(), block, EffectType::sine)).code,
              ErrorCode::invalid_parameter);
    EXPECT_EQ(rig.session().block(block)->committed_params, committed);
    EXPECT_EQ(rig.session().block(block)->shadow, committed);
    EffectParams engine;
    ASSERT_TRUE(rig.pipeline().engine().params(rig.session().block(block)->effect, engine).ok());
    EXPECT_EQ(engine.periodic.magnitude, 3000);
}

TEST(DeviceLimits, DeviceResetFreesEveryBlock) {
    SessionRig rig;
    for (int i = 0; i < 3; ++i) {
        const uint16_t b = rig.create(EffectType::sine);
        rig.ok(periodic(rig.next_sequence(), b, 1000, 10'000));
        rig.ok(set_effect(rig.next_sequence(), b, EffectType::sine));
    }
    rig.create(EffectType::spring);
    protocol::DeviceControlReport reset;
    reset.sequence = rig.next_sequence();
    reset.control = protocol::DeviceControlOp::device_reset;
    rig.ok(reset);
    EXPECT_EQ(rig.session().allocated_blocks(), 0);
    EXPECT_EQ(rig.pipeline().resident_effects(), 0);
    const auto pool = rig.get<protocol::PidPoolReport>(ReportId::pid_pool);
    EXPECT_EQ(pool.free_effects, 32);
    EXPECT_EQ(pool.ram_pool_available, pool.ram_pool_size);
}

TEST(DeviceLimits, ForceSamplesAreAnsweredOnlyWhenRefused) {
    SessionRig rig;
    protocol::DownloadForceSampleReport d;
    d.sequence = 500;
    d.axis_count = 2;
    d.force[0] = 1000;
    rig.offer(output(d));
    rig.run(3);
    EXPECT_TRUE(rig.statuses.empty());
    d.sequence = 501;
    d.axis_count = 3;  // the device has two axes
    rig.offer(output(d));
    rig.run(3);
    ASSERT_EQ(rig.statuses.size(), 1u);
    EXPECT_EQ(rig.statuses[0].sequence, 501u);
    EXPECT_EQ(rig.statuses[0].command, ReportId::download_force_sample);
    EXPECT_EQ(rig.statuses[0].code, ErrorCode::invalid_parameter);
    EXPECT_STREQ(rig.statuses[0].field, "stream.axis_count");
}

TEST(DeviceLimits, HostGoneResetsTheDevice) {
    SessionRig rig;
    const uint16_t b = rig.create(EffectType::sine);
    rig.ok(periodic(rig.next_sequence(), b, 1000, 10'000));
    rig.ok(set_effect(rig.next_sequence(), b, EffectType::sine));
    rig.ok(operation(rig.next_sequence(), b, EffectOperation::start, protocol::kLoopInfinite));
    protocol::DeviceGainReport g;
    g.sequence = rig.next_sequence();
    g.gain = 2000;
    rig.ok(g);
    // A frame still queued when the host goes is dropped with it.
    rig.offer(output(operation(rig.next_sequence(), b, EffectOperation::stop)));
    const std::size_t answered = rig.statuses.size();
    rig.session().host_gone();
    rig.run(60);  // the sine fades out over host_fade_out_us (50 ms) before the reset
    EXPECT_EQ(rig.statuses.size(), answered);
    EXPECT_TRUE(rig.session().idle());
    EXPECT_EQ(rig.session().allocated_blocks(), 0);
    EXPECT_EQ(rig.pipeline().resident_effects(), 0);
    EXPECT_EQ(rig.pipeline().engine().gain(), kFullScale);
    EXPECT_EQ(rig.create(EffectType::sine), 1);
}

TEST(DeviceLimits, HostGoneFadesTheForcesOutThenFreesEverything) {
    SessionRig rig;
    EffectParams push;
    push.type = EffectType::constant;
    push.duration_us = kInfiniteUs;
    push.axis_count = 1;
    push.axes[0] = Axis::x;
    push.constant.magnitude = 6000;
    const uint16_t b = download(rig, push);
    rig.ok(operation(rig.next_sequence(), b, EffectOperation::start, 255));
    rig.run(3);
    ASSERT_EQ(rig.pipeline().motor_force()[0], 6000.0f);
    const int64_t fade_us = rig.pipeline().config().safety.host_fade_out_us;
    ASSERT_EQ(fade_us, 50'000);
    const int64_t tick_us = 1'000'000 / rig.pipeline().config().loop_rate_hz;
    rig.session().host_gone();
    // The release reaches the loop at the next tick; from there the force falls linearly
    // to 0 over host_fade_out_us (docs/runtime.md, "Host-link watchdog"), with no step
    // larger than one tick's share of it, and only then is the device reset.
    rig.run(1);
    float previous = rig.pipeline().motor_force()[0];
    EXPECT_EQ(previous, 6000.0f);
    const int64_t ticks = fade_us / tick_us;
    for (int64_t k = 1; k <= ticks; ++k) {
        rig.run(1);
        const float f = rig.pipeline().motor_force()[0];
        const double expected = 6000.0 * std::max(0.0, 1.0 - static_cast<double>(k * tick_us) / static_cast<double>(fade_us));
        ASSERT_NEAR(f, expected, 1.0) << "tick " << k << " of the fade";
        ASSERT_LE(previous - f, 6000.0f * static_cast<float>(tick_us) / static_cast<float>(fade_us) + 1.0f);
        previous = f;
        if (k < ticks) {
            ASSERT_EQ(rig.pipeline().resident_effects(), 1) << "freed during the fade, at tick " << k;
        }
    }
    EXPECT_EQ(previous, 0.0f);
    rig.run(5);
    EXPECT_TRUE(rig.session().idle());
    EXPECT_EQ(rig.pipeline().resident_effects(), 0);
    EXPECT_EQ(rig.session().allocated_blocks(), 0);
}

}  // namespace
}  // namespace feel::peripheral::test
