// PidCommitOrder: hid-pidff's order (Set Effect first, parameter blocks after, updates of
// single blocks) becomes feel's transaction order (parameter blocks, then Set Effect).
#include <gtest/gtest.h>

#include "feel/protocol/codec.hpp"
#include "pid_commit_order.hpp"

namespace feel::usb::detail {
namespace {

using transport::Frame;
using transport::FrameKind;
using Clock = PidCommitOrder::Clock;

Frame out(const protocol::AnyReport& r) { return Frame{FrameKind::output_report, protocol::encode(r)}; }

protocol::AnyReport set_effect(uint16_t block) {
    protocol::SetEffectReport r;
    r.block = block;
    return r;
}
protocol::AnyReport periodic(uint16_t block) {
    protocol::SetPeriodicReport r;
    r.block = block;
    return r;
}
protocol::AnyReport envelope(uint16_t block) {
    protocol::SetEnvelopeReport r;
    r.block = block;
    return r;
}
protocol::AnyReport operation(uint16_t block) {
    protocol::EffectOperationReport r;
    r.block = block;
    return r;
}

uint8_t id_of(const Frame& f) { return f.payload.at(0); }

TEST(PidCommitOrder, SetEffectMovesBehindTheBlocksThatFollowIt) {
    PidCommitOrder order;
    const auto t0 = Clock::time_point{} + std::chrono::seconds(10);
    EXPECT_TRUE(order.on_frame(out(set_effect(1)), t0).empty());
    const auto a = order.on_frame(out(periodic(1)), t0);
    const auto b = order.on_frame(out(envelope(1)), t0);
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(b.size(), 1u);
    EXPECT_EQ(id_of(a[0]), static_cast<uint8_t>(protocol::ReportId::set_periodic));
    // Playing the effect commits it first.
    const auto c = order.on_frame(out(operation(1)), t0 + std::chrono::milliseconds(1));
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(id_of(c[0]), static_cast<uint8_t>(protocol::ReportId::set_effect));
    EXPECT_EQ(c[0].payload, protocol::encode(set_effect(1)));
    EXPECT_EQ(id_of(c[1]), static_cast<uint8_t>(protocol::ReportId::effect_operation));
    EXPECT_EQ(order.next_deadline(), Clock::time_point::max());
}

TEST(PidCommitOrder, AnUpdateOfOneBlockIsCommittedWithTheLastSetEffectOnceItSettles) {
    PidCommitOrder order;
    const auto t0 = Clock::time_point{} + std::chrono::seconds(10);
    (void)order.on_frame(out(set_effect(2)), t0);
    (void)order.on_frame(out(periodic(2)), t0);
    EXPECT_EQ(order.on_time(t0 + std::chrono::milliseconds(10)).size(), 0u);
    EXPECT_EQ(order.next_deadline(), t0 + PidCommitOrder::kSettle);
    EXPECT_EQ(order.on_time(t0 + PidCommitOrder::kSettle).size(), 1u);
    // Later: hid-pidff changes the magnitude alone.
    const auto t1 = t0 + std::chrono::seconds(1);
    EXPECT_EQ(order.on_frame(out(periodic(2)), t1).size(), 1u);
    const auto commits = order.on_time(t1 + PidCommitOrder::kSettle);
    ASSERT_EQ(commits.size(), 1u);
    EXPECT_EQ(commits[0].payload, protocol::encode(set_effect(2)));
}

TEST(PidCommitOrder, BlocksAreKeptApartAndOtherFramesPassUntouched) {
    PidCommitOrder order;
    const auto t0 = Clock::time_point{} + std::chrono::seconds(10);
    (void)order.on_frame(out(set_effect(1)), t0);
    (void)order.on_frame(out(set_effect(2)), t0);
    // A feature report (the next Create New Effect) overtaking block 1's last report.
    const Frame feature{FrameKind::set_feature, {0x11, 0, 0}};
    EXPECT_EQ(order.on_frame(feature, t0).size(), 1u);
    const auto c = order.on_frame(out(operation(2)), t0);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c[0].payload, protocol::encode(set_effect(2)));  // block 1 still waits
    const Frame garbage{FrameKind::output_report, {0xEE}};
    EXPECT_EQ(order.on_frame(garbage, t0).size(), 1u);         // the session refuses it
}

}  // namespace
}  // namespace feel::usb::detail
