// A scripted device at the far end of an in-process connection, for the host's protocol
// paths a real device rarely takes: refusals with a field and range, Block Load Full, a
// device that never answers, one that is busy, one with another descriptor. It speaks
// the protocol with the codec (protocol::encode/decode) and answers what the test says.
#pragma once

#include <atomic>
#include <cstring>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "feel/protocol/codec.hpp"
#include "feel/protocol/command_answer.hpp"
#include "feel/transport/transport.hpp"

namespace feel::host::test {

class FakeDevice {
public:
    // What the device answers a host report with: the status to send (its sequence is
    // filled in), or std::nullopt for "ok".
    using Answer = std::function<std::optional<protocol::CommandAnswer>(const protocol::AnyReport&)>;

    std::atomic<bool> silent{false};  // answers nothing (from now on)
    bool busy = false;           // sends `busy` at the first frame, then closes
    bool close_on_set_effect = false;  // goes away when the host commits an effect
    std::optional<std::vector<uint8_t>> descriptor;  // instead of the codec's
    protocol::BlockLoadReport block_load{1, protocol::BlockLoadStatus::success, 4096};
    protocol::DeviceInfoReport device_info = info();  // what Get Feature(Device Info) answers
    Answer answer;

    FakeDevice() {
        transport::ConnectionPair pair = transport::in_process_pair("fake");
        host_end_ = std::move(pair.host);
        device_ = std::move(pair.device);
    }
    ~FakeDevice() { stop(); }

    // The host's end, for Device::attach (once). Starts the device thread.
    std::unique_ptr<transport::Connection> host_end() {
        thread_ = std::thread([this] { run(); });
        return std::move(host_end_);
    }

    void stop() {
        stopping_ = true;
        device_->close();
        if (thread_.joinable()) thread_.join();
    }

    std::vector<protocol::AnyReport> received() const {
        std::lock_guard lock(mu_);
        return received_;
    }
    template <class R>
    int count() const {
        int n = 0;
        for (const auto& r : received()) n += std::holds_alternative<R>(r) ? 1 : 0;
        return n;
    }

    // Sends an input report as the device would, unasked (after host_end()).
    void push(const protocol::AnyReport& report) { send(transport::FrameKind::input_report, report); }

    // A DeviceInfo within every wire range: a 2-axis stick of 4 effect slots.
    static protocol::DeviceInfoReport info() {
        protocol::DeviceInfoReport d;
        std::strncpy(d.device, "fake", sizeof d.device);
        std::strncpy(d.description, "a scripted test device", sizeof d.description);
        d.device_class = 2;  // sim::DeviceClass::iforce2
        d.axis_count = 2;
        for (int i = 0; i < 2; ++i) {
            d.axes[i].axis = static_cast<Axis>(i);
            d.axes[i].half_travel_micro = 50'000;
            d.axes[i].max_force_milli = 4'450;
            d.axes[i].sensor_counts = 4096;
        }
        d.button_count = 4;
        d.hat_count = 1;
        d.supported_types = (uint64_t{1} << 33) - 1;
        d.effect_slots = 4;
        d.pool_bytes = 4096;
        d.sample_memory = 2048;
        d.local_reflexes = true;
        d.loop_rate_hz = 1000;
        d.max_loop_rate_hz = 1000;
        d.report_rate_hz = 250;
        std::strncpy(d.firmware_version, "fake 1", sizeof d.firmware_version);
        return d;
    }

private:
    void send(transport::FrameKind kind, const protocol::AnyReport& report) {
        device_->send(transport::Frame{kind, protocol::encode(report)});
    }

    void run() {
        try {
            while (!stopping_) {
                std::optional<transport::Frame> f = device_->receive(std::chrono::milliseconds(10));
                if (!f) continue;
                if (busy) {
                    device_->send(transport::Frame{transport::FrameKind::busy, {}});
                    device_->close();
                    return;
                }
                if (f->kind == transport::FrameKind::get_descriptor) {
                    if (silent) continue;
                    const auto d = protocol::report_descriptor();
                    device_->send(transport::Frame{transport::FrameKind::descriptor_reply,
                                                   descriptor ? *descriptor : std::vector<uint8_t>(d.begin(), d.end())});
                    continue;
                }
                if (f->kind == transport::FrameKind::get_feature) {
                    if (silent || f->payload.size() != 1) continue;
                    const auto id = static_cast<protocol::ReportId>(f->payload[0]);
                    if (id == protocol::ReportId::device_info) send(transport::FrameKind::feature_reply, device_info);
                    if (id == protocol::ReportId::block_load) send(transport::FrameKind::feature_reply, block_load);
                    continue;
                }
                protocol::AnyReport report;
                if (protocol::decode(f->payload, report)) continue;
                {
                    std::lock_guard lock(mu_);
                    received_.push_back(report);
                }
                if (silent) continue;
                if (close_on_set_effect && std::holds_alternative<protocol::SetEffectReport>(report)) {
                    device_->close();
                    return;
                }
                protocol::CommandAnswer status;
                if (answer) {
                    if (auto a = answer(report)) status = *a;
                }
                std::visit(
                    [&](const auto& r) {
                        if constexpr (requires { r.sequence; }) status.sequence = r.sequence;
                    },
                    report);
                status.command = protocol::report_id_of(report);
                // A refusal's text first, then its status, as a feel device sends them.
                const protocol::ErrorTextParts text = protocol::error_text_parts(status);
                for (std::size_t i = 0; i < text.count; ++i) send(transport::FrameKind::input_report, text.parts[i]);
                send(transport::FrameKind::input_report, static_cast<const protocol::CommandStatusReport&>(status));
            }
        } catch (const transport::TransportError&) {
            // The host went away.
        }
    }

    std::unique_ptr<transport::Connection> host_end_;
    std::unique_ptr<transport::Connection> device_;
    std::thread thread_;
    std::atomic<bool> stopping_{false};
    mutable std::mutex mu_;
    std::vector<protocol::AnyReport> received_;
};

}  // namespace feel::host::test
