// The Peripheral: the device runtime on its own loop thread and a service thread speaking
// the protocol over a transport. One host at a time; a host that leaves gets the device
// reset behind it.
#include "feel/peripheral/peripheral.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "session_rig.hpp"

namespace feel::peripheral::test {
namespace {

using namespace std::chrono_literals;
using protocol::ReportId;

// The host's side of a connection, reading frames until the one it waits for.
class Host {
public:
    explicit Host(std::unique_ptr<transport::Connection> c) : connection_(std::move(c)) {}

    transport::Connection& connection() { return *connection_; }

    protocol::CommandStatusReport command(const protocol::AnyReport& r, bool feature = false) {
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
            if (const auto* s = std::get_if<protocol::CommandStatusReport>(&a); s && s->sequence == sequence) return *s;
            if (const auto* d = std::get_if<protocol::DeviceStatusReport>(&a)) last_status = *d;
        }
        ADD_FAILURE() << "no CommandStatus for sequence " << sequence;
        return {};
    }

    template <class R>
    R get(ReportId id) {
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
            if (const auto* d = std::get_if<protocol::DeviceStatusReport>(&a)) last_status = *d;
        }
        ADD_FAILURE() << "no feature reply";
        return R{};
    }

    // Reads input reports for a while, keeping the last Device Status.
    void listen_for(std::chrono::milliseconds span) {
        const auto deadline = std::chrono::steady_clock::now() + span;
        while (std::chrono::steady_clock::now() < deadline) {
            const std::optional<Frame> f = connection_->receive(10ms);
            if (!f) continue;
            protocol::AnyReport a;
            if (!protocol::decode(f->payload, a).ok()) continue;
            if (const auto* d = std::get_if<protocol::DeviceStatusReport>(&a)) last_status = *d;
        }
    }

    // Create New Effect + Block Load + Set Condition (x) + Set Effect + start: a spring.
    uint16_t play_spring(uint32_t first_sequence) {
        protocol::CreateNewEffectReport c;
        c.sequence = first_sequence;
        c.type = EffectType::spring;
        EXPECT_EQ(command(c, true).code, ErrorCode::ok);
        const auto load = get<protocol::BlockLoadReport>(ReportId::block_load);
        EXPECT_EQ(load.status, protocol::BlockLoadStatus::success);
        EXPECT_EQ(command(spring_axis(first_sequence + 1, load.block, 0, 2000)).code, ErrorCode::ok);
        EXPECT_EQ(command(set_effect(first_sequence + 2, load.block, EffectType::spring)).code, ErrorCode::ok);
        EXPECT_EQ(command(operation(first_sequence + 3, load.block, protocol::EffectOperation::start)).code,
                  ErrorCode::ok);
        return load.block;
    }

    std::optional<protocol::DeviceStatusReport> last_status;

private:
    std::unique_ptr<transport::Connection> connection_;
};

bool wait_until(const std::function<bool()>& done, std::chrono::milliseconds limit = 5s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (!done()) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(2ms);
    }
    return true;
}

PeripheralOptions quick_options(const char* profile = "iforce2") {
    PeripheralOptions o;
    o.profile = profile;
    o.runtime.realtime_priority = false;  // tests run beside other work; no SCHED_FIFO
    o.runtime.lock_memory = false;
    return o;
}

TEST(Peripheral, InProcessDeviceAnswersAndPlays) {
    Host host(open_in_process(quick_options()));
    const auto info = host.get<protocol::DeviceInfoReport>(ReportId::device_info);
    EXPECT_STREQ(info.device, "iforce2");
    EXPECT_EQ(info.effect_slots, 32);
    const uint16_t block = host.play_spring(1);
    EXPECT_EQ(block, 1);
    host.listen_for(100ms);
    ASSERT_TRUE(host.last_status.has_value());
    EXPECT_EQ(host.last_status->resident_effects, 1);
    EXPECT_EQ(host.last_status->loop_rate_hz, 1000);
    EXPECT_EQ(host.last_status->effect_block[0], block);
}

TEST(Peripheral, DeviceStatusCarriesTheMeasuredLoopRate) {
    PeripheralOptions o = quick_options();
    o.loop_rate_hz = 500;
    Host host(open_in_process(o));
    host.listen_for(1300ms);  // the rate is measured over windows of a second
    ASSERT_TRUE(host.last_status.has_value());
    EXPECT_EQ(host.last_status->loop_rate_hz, 500);
    // Ticks per second over the last second: 500 Hz, less what overruns on a busy machine
    // skipped, never more (to the window's edge tick).
    EXPECT_GT(host.last_status->measured_rate_millihz, 250'000u);
    EXPECT_LT(host.last_status->measured_rate_millihz, 505'000u);
    EXPECT_EQ(host.get<protocol::DeviceInfoReport>(ReportId::device_info).loop_rate_hz, 500);
}

TEST(Peripheral, RejectsBadOptionsByName) {
    PeripheralOptions o = quick_options("nosuch");
    try {
        Peripheral p(o);
        FAIL() << "an unknown profile was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("iforce2"), std::string::npos) << e.what();  // lists the known ones
    }
    o = quick_options();
    o.hand = "claw";
    EXPECT_THROW(Peripheral{o}, std::invalid_argument);
    o = quick_options("iforce1");
    o.loop_rate_hz = 2000;  // an I-FORCE 1.x-class loop runs at 1 kHz at most
    try {
        Peripheral p(o);
        FAIL() << "a loop rate beyond the profile's was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("100..1000"), std::string::npos) << e.what();
    }
}

TEST(Peripheral, SecondHostGetsBusyAndIsClosed) {
    Peripheral device(quick_options());
    transport::ConnectionPair first = transport::in_process_pair("first");
    transport::ConnectionPair second = transport::in_process_pair("second");
    device.attach(std::move(first.device));
    ASSERT_TRUE(device.host_attached());
    device.attach(std::move(second.device));
    const std::optional<Frame> f = second.host->receive(2s);
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, FrameKind::busy);
    EXPECT_THROW((void)second.host->receive(1s), transport::TransportError);
    // The first host is still served.
    Host host(std::move(first.host));
    EXPECT_EQ(host.get<protocol::DeviceInfoReport>(ReportId::device_info).effect_slots, 32);
    EXPECT_EQ(device.stats().hosts_served, 1u);
}

TEST(Peripheral, HostDisconnectResetsTheDevice) {
    Peripheral device(quick_options());
    {
        transport::ConnectionPair pair = transport::in_process_pair("first");
        device.attach(std::move(pair.device));
        Host host(std::move(pair.host));
        host.play_spring(1);
        host.play_spring(10);
        const auto pool = host.get<protocol::PidPoolReport>(ReportId::pid_pool);
        EXPECT_EQ(pool.free_effects, 30);
        host.connection().close();
    }
    ASSERT_TRUE(wait_until([&] { return !device.host_attached(); }));
    EXPECT_EQ(device.stats().runtime.pipeline.commands_refused, 0);

    transport::ConnectionPair pair = transport::in_process_pair("second");
    device.attach(std::move(pair.device));
    Host host(std::move(pair.host));
    const auto pool = host.get<protocol::PidPoolReport>(ReportId::pid_pool);
    EXPECT_EQ(pool.free_effects, 32);
    EXPECT_EQ(pool.ram_pool_available, pool.ram_pool_size);
    host.listen_for(50ms);
    ASSERT_TRUE(host.last_status.has_value());
    EXPECT_EQ(host.last_status->resident_effects, 0);
    EXPECT_EQ(host.last_status->playing_effects, 0);
    // The new host starts at block 1 again.
    EXPECT_EQ(host.play_spring(1), 1);
    EXPECT_EQ(device.stats().hosts_served, 2u);
}

TEST(Peripheral, ServesHostsOnAUnixSocket) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("feel-peripheral-test-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    transport::Address address;
    address.kind = transport::Address::Kind::unix_socket;
    address.path = (dir / "dev.sock").string();
    {
        Peripheral device(quick_options("iforce1"));
        device.serve(transport::listen(address));
        EXPECT_EQ(device.address(), address);
        Host host(transport::connect(address, 2s));
        EXPECT_STREQ(host.get<protocol::DeviceInfoReport>(ReportId::device_info).device, "iforce1");
        EXPECT_EQ(host.play_spring(1), 1);
        // A second host on the socket is turned away while the first is attached.
        auto second = transport::connect(address, 2s);
        const std::optional<Frame> f = second->receive(2s);
        ASSERT_TRUE(f.has_value());
        EXPECT_EQ(f->kind, FrameKind::busy);
        device.stop();
        EXPECT_FALSE(device.host_attached());
    }
    EXPECT_FALSE(std::filesystem::exists(address.path));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace feel::peripheral::test
