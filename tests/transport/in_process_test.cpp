// The in-process pair: frames both ways in order, close semantics, a blocked receive woken.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "feel/transport/transport.hpp"
#include "frame_of.hpp"

namespace feel::transport {
namespace {

using namespace std::chrono_literals;

TransportError::Kind in_process_receive_error(Connection& c, std::chrono::milliseconds timeout = 1000ms) {
    try {
        (void)c.receive(timeout);
    } catch (const TransportError& e) {
        return e.kind();
    }
    ADD_FAILURE() << "receive did not throw";
    return TransportError::Kind::timeout;
}

TEST(InProcess, FramesArriveWholeAndInOrderBothWays) {
    ConnectionPair pair = in_process_pair("sim:iforce2");
    for (uint8_t i = 0; i < 100; ++i) pair.host->send(frame_of(FrameKind::output_report, {i, uint8_t(i + 1)}));
    pair.device->send(frame_of(FrameKind::input_report, {42}));
    for (uint8_t i = 0; i < 100; ++i) {
        const auto f = pair.device->receive(100ms);
        ASSERT_TRUE(f.has_value());
        EXPECT_EQ(*f, frame_of(FrameKind::output_report, {i, uint8_t(i + 1)}));
    }
    const auto back = pair.host->receive(100ms);
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, frame_of(FrameKind::input_report, {42}));
    EXPECT_EQ(pair.host->peer(), "sim:iforce2");
    EXPECT_EQ(pair.device->peer(), "sim:iforce2");
}

TEST(InProcess, CarriesEmptyAndLargestPayloadsAndRefusesLarger) {
    ConnectionPair pair = in_process_pair();
    pair.host->send(frame_of(FrameKind::get_descriptor, {}));
    pair.device->send(frame_of(FrameKind::descriptor_reply, std::vector<uint8_t>(kMaxFramePayload, 0xA5)));
    EXPECT_EQ(pair.device->receive(100ms)->payload.size(), 0u);
    EXPECT_EQ(pair.host->receive(100ms)->payload, std::vector<uint8_t>(kMaxFramePayload, 0xA5));
    EXPECT_THROW(pair.host->send(frame_of(FrameKind::output_report, std::vector<uint8_t>(kMaxFramePayload + 1))),
                 std::invalid_argument);
}

TEST(InProcess, ReceiveTimesOutWithNothing) {
    ConnectionPair pair = in_process_pair();
    const auto begin = std::chrono::steady_clock::now();
    EXPECT_FALSE(pair.device->receive(30ms).has_value());
    EXPECT_GE(std::chrono::steady_clock::now() - begin, 30ms);
}

TEST(InProcess, ThePeerReadsWhatWasSentBeforeTheCloseThenDisconnected) {
    ConnectionPair pair = in_process_pair();
    pair.host->send(frame_of(FrameKind::output_report, {1}));
    pair.host->send(frame_of(FrameKind::output_report, {2}));
    pair.host->close();
    EXPECT_EQ(pair.device->receive(100ms)->payload, std::vector<uint8_t>{1});
    EXPECT_EQ(pair.device->receive(100ms)->payload, std::vector<uint8_t>{2});
    EXPECT_EQ(in_process_receive_error(*pair.device), TransportError::Kind::disconnected);
    // Sending into a closed pair, from either end.
    EXPECT_THROW(pair.device->send(frame_of(FrameKind::input_report, {3})), TransportError);
    EXPECT_THROW(pair.host->send(frame_of(FrameKind::output_report, {3})), TransportError);
    EXPECT_EQ(in_process_receive_error(*pair.host), TransportError::Kind::disconnected);
    pair.host->close();  // harmless twice
}

TEST(InProcess, DestroyingOneEndDisconnectsTheOther) {
    ConnectionPair pair = in_process_pair();
    pair.host.reset();
    EXPECT_EQ(in_process_receive_error(*pair.device), TransportError::Kind::disconnected);
}

TEST(InProcess, CloseWakesABlockedReceiveAtOnce) {
    for (const bool close_own_end : {true, false}) {
        ConnectionPair pair = in_process_pair();
        TransportError::Kind kind = TransportError::Kind::timeout;
        std::chrono::steady_clock::duration waited{};
        std::thread receiver([&] {
            const auto begin = std::chrono::steady_clock::now();
            kind = in_process_receive_error(*pair.device, 10'000ms);
            waited = std::chrono::steady_clock::now() - begin;
        });
        std::this_thread::sleep_for(20ms);
        (close_own_end ? pair.device : pair.host)->close();
        receiver.join();
        EXPECT_EQ(kind, TransportError::Kind::disconnected);
        EXPECT_LT(waited, 5'000ms);
    }
}

TEST(InProcess, WaitingForEverIsAllowed) {
    // milliseconds::max() must not overflow the clock into an immediate timeout.
    ConnectionPair pair = in_process_pair();
    std::thread sender([&] {
        std::this_thread::sleep_for(20ms);
        pair.host->send(frame_of(FrameKind::output_report, {9}));
    });
    const auto f = pair.device->receive(std::chrono::milliseconds::max());
    sender.join();
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->payload, std::vector<uint8_t>{9});
    EXPECT_FALSE(pair.device->receive(-5ms).has_value());  // a negative timeout is 0
}

TEST(InProcess, OneThreadSendsWhileAnotherReceives) {
    ConnectionPair pair = in_process_pair();
    constexpr int kFrames = 5000;
    std::thread sender([&] {
        for (int i = 0; i < kFrames; ++i)
            pair.host->send(frame_of(FrameKind::output_report, {uint8_t(i & 0xFF), uint8_t(i >> 8)}));
    });
    for (int i = 0; i < kFrames; ++i) {
        const auto f = pair.device->receive(5000ms);
        ASSERT_TRUE(f.has_value());
        ASSERT_EQ(f->payload[0] | (f->payload[1] << 8), i);
    }
    sender.join();
}

}  // namespace
}  // namespace feel::transport
