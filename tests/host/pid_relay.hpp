// A relay between PidDevice and the simulated device (a Peripheral on in-process pairs):
// frames pass both ways; what the host sends is decoded with feel's codec and kept (the
// device's view), and what the device sends is kept as it is (the host's view). For
// pid_device_test.cpp and standard_pid_device_test.cpp.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "feel/peripheral/peripheral.hpp"
#include "feel/protocol/codec.hpp"
#include "feel/transport/transport.hpp"

namespace feel::test {

class PidRelay {
public:
    explicit PidRelay(peripheral::PeripheralOptions po = {}) {
        po.profile = "iforce2";
        po.runtime.realtime_priority = false;
        po.runtime.lock_memory = false;
        device_ = std::make_unique<peripheral::Peripheral>(po);
        transport::ConnectionPair to_host = transport::in_process_pair("sim:iforce2");
        transport::ConnectionPair to_device = transport::in_process_pair("sim:iforce2");
        host_end_ = std::move(to_host.host);
        from_host_ = std::move(to_host.device);
        to_device_ = std::move(to_device.host);
        device_->attach(std::move(to_device.device));
        up_ = std::thread([this] { pump(*from_host_, *to_device_, true); });
        down_ = std::thread([this] { pump(*to_device_, *from_host_, false); });
    }
    ~PidRelay() {
        from_host_->close();
        to_device_->close();
        up_.join();
        down_.join();
        device_->stop();
    }
    PidRelay(const PidRelay&) = delete;
    PidRelay& operator=(const PidRelay&) = delete;

    std::unique_ptr<transport::Connection> host_end() { return std::move(host_end_); }
    // The host's output and feature reports that decode as feel's reports, in order.
    std::vector<protocol::AnyReport> sent() {
        std::lock_guard lock(mu_);
        return sent_;
    }
    // Every frame the device sent, in order.
    std::vector<transport::Frame> received() {
        std::lock_guard lock(mu_);
        return received_;
    }
    void clear() {
        std::lock_guard lock(mu_);
        sent_.clear();
        received_.clear();
    }

private:
    void pump(transport::Connection& from, transport::Connection& to, bool from_host) {
        try {
            for (;;) {
                std::optional<transport::Frame> f = from.receive(std::chrono::milliseconds(100));
                if (!f) continue;
                {
                    std::lock_guard lock(mu_);
                    if (!from_host) {
                        received_.push_back(*f);
                    } else if (f->kind == transport::FrameKind::output_report ||
                               f->kind == transport::FrameKind::set_feature) {
                        protocol::AnyReport r;
                        if (!protocol::decode(f->payload, r)) sent_.push_back(r);
                    }
                }
                to.send(*f);
            }
        } catch (const std::exception&) {
        }
    }
    std::unique_ptr<peripheral::Peripheral> device_;
    std::unique_ptr<transport::Connection> host_end_, from_host_, to_device_;
    std::thread up_, down_;
    std::mutex mu_;
    std::vector<protocol::AnyReport> sent_;
    std::vector<transport::Frame> received_;
};

}  // namespace feel::test
