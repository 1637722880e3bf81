// A host written against the raw transport for the Peripheral's tests: it sends reports and
// reads frames until the answer it waits for, keeping the last Device Status and Effect
// States it saw.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <optional>
#include <thread>
#include <variant>

#include "feel/peripheral/peripheral.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"
#include "session_rig.hpp"

namespace feel::peripheral::test {

using namespace std::chrono_literals;

// The host's side of a connection, reading frames until the one it waits for.
class Host {
public:
    explicit Host(std::unique_ptr<transport::Connection> c) : connection_(std::move(c)) {}

    transport::Connection& connection() { return *connection_; }

    protocol::CommandAnswer command(const protocol::AnyReport& r, bool feature = false) {
        const uint32_t sequence = std::visit([](const auto& x) -> uint32_t {
            if constexpr (requires { x.sequence; }) return x.sequence; else return 0;
        }, r);
        connection_->send(feature ? set_feature(r) : output(r));
        const auto deadline = std::chrono::steady_clock::now() + 5s;
        while (std::chrono::steady_clock::now() < deadline) {
            const std::optional<Frame> f = connection_->receive(100ms);
            if (!f || f->kind != FrameKind::input_report) continue;
            // Joystick Input is in the device's own layout (its profile's inputs): not read here.
            if (!f->payload.empty() && f->payload[0] == static_cast<uint8_t>(protocol::ReportId::joystick_input)) continue;
            protocol::AnyReport a;
            if (!protocol::decode(f->payload, a).ok()) {
                ADD_FAILURE() << "undecodable input report";
                continue;
            }
            if (const auto* t = std::get_if<protocol::CommandErrorTextReport>(&a)) error_text_.add(*t);
            if (const auto* s = std::get_if<protocol::CommandStatusReport>(&a)) {
                const protocol::CommandAnswer answer = error_text_.finish(*s);
                if (s->sequence == sequence) return answer;
            }
            keep_state(a);
        }
        ADD_FAILURE() << "no CommandStatus for sequence " << sequence;
        return {};
    }

    template <class R>
    R get(protocol::ReportId id) {
        connection_->send(get_feature(id));
        const auto deadline = std::chrono::steady_clock::now() + 5s;
        while (std::chrono::steady_clock::now() < deadline) {
            const std::optional<Frame> f = connection_->receive(100ms);
            if (!f) continue;
            protocol::AnyReport a;
            if (!protocol::decode(f->payload, a).ok()) continue;
            if (f->kind == FrameKind::feature_reply) {
                if (const R* r = std::get_if<R>(&a)) return *r;
            }
            keep_state(a);
        }
        ADD_FAILURE() << "no feature reply";
        return R{};
    }

    // Reads input reports for a while, keeping the last Device Status, and sends a
    // keep-alive every 100 ms as a host must (the device detaches a host silent for its
    // watchdog time).
    void listen_for(std::chrono::milliseconds span) {
        const auto deadline = std::chrono::steady_clock::now() + span;
        auto next_keep_alive = std::chrono::steady_clock::now();
        while (std::chrono::steady_clock::now() < deadline) {
            if (std::chrono::steady_clock::now() >= next_keep_alive) {
                connection_->send(output(protocol::KeepAliveReport{}));
                next_keep_alive += 100ms;
            }
            const std::optional<Frame> f = connection_->receive(10ms);
            if (!f) continue;
            protocol::AnyReport a;
            if (!protocol::decode(f->payload, a).ok()) continue;
            keep_state(a);
        }
    }

    // Create New Effect + Block Load + Set Condition (x) + Set Effect + start: a spring.
    uint16_t play_spring(uint32_t first_sequence) {
        protocol::CreateNewEffectReport c;
        c.sequence = first_sequence;
        c.type = EffectType::spring;
        EXPECT_EQ(command(c, true).code, ErrorCode::ok);
        const auto load = get<protocol::BlockLoadReport>(protocol::ReportId::block_load);
        EXPECT_EQ(load.status, protocol::BlockLoadStatus::success);
        EXPECT_EQ(command(spring_axis(first_sequence + 1, load.block, 0, 2000)).code, ErrorCode::ok);
        EXPECT_EQ(command(set_effect(first_sequence + 2, load.block, EffectType::spring)).code, ErrorCode::ok);
        EXPECT_EQ(command(operation(first_sequence + 3, load.block, protocol::EffectOperation::start)).code,
                  ErrorCode::ok);
        return load.block;
    }

    std::optional<protocol::DeviceStatusReport> last_status;
    std::optional<protocol::EffectStatesReport> last_effects;  // page 0

private:
    void keep_state(const protocol::AnyReport& a) {
        if (const auto* d = std::get_if<protocol::DeviceStatusReport>(&a)) last_status = *d;
        if (const auto* e = std::get_if<protocol::EffectStatesReport>(&a); e && e->page == 0) last_effects = *e;
    }

    protocol::CommandAnswerJoiner error_text_;
    std::unique_ptr<transport::Connection> connection_;
};

inline bool wait_until(const std::function<bool()>& done, std::chrono::milliseconds limit = 5s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (!done()) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(2ms);
    }
    return true;
}

inline PeripheralOptions quick_options(const char* profile = "iforce2") {
    PeripheralOptions o;
    o.profile = profile;
    o.runtime.realtime_priority = false;  // tests run beside other work; no SCHED_FIFO
    o.runtime.lock_memory = false;
    return o;
}

}  // namespace feel::peripheral::test
