// The Studio's device (studio_device.hpp).
#include "studio_device.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "feel/effect_type.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/hand.hpp"
#include "feel/transport/thread_priority.hpp"
#include "feel/transport/transport.hpp"

namespace feel::studio {
namespace {

using json = nlohmann::json;

// "sim:iforce2" -> "iforce2"; "iforce1" -> "iforce1"; anything with another scheme -> "".
std::string simulated_profile(const std::string& address) {
    if (address.starts_with("sim:")) return address.substr(4);
    if (address.find(':') == std::string::npos) return address;
    return "";
}

bool studio_grip(const std::string& g) { return g == "loose" || g == "firm" || g == "stiff"; }

std::string_view class_key(EffectClass c) {
    switch (c) {
        case EffectClass::condition: return "condition";
        case EffectClass::wave: return "wave";
        case EffectClass::dynamic: return "dynamic";
    }
    return "wave";
}

}  // namespace

// A connection that keeps the simulated device it talks to alive (like
// peripheral::open_in_process), while the Studio keeps a handle to reach its hand.
class SharedPeripheralConnection final : public transport::Connection {
public:
    SharedPeripheralConnection(std::shared_ptr<peripheral::Peripheral> device,
                               std::unique_ptr<transport::Connection> host)
        : device_(std::move(device)), host_(std::move(host)) {}
    void send(const transport::Frame& frame) override { host_->send(frame); }
    std::optional<transport::Frame> receive(std::chrono::milliseconds timeout) override {
        return host_->receive(timeout);
    }
    void close() noexcept override { host_->close(); }
    [[nodiscard]] std::string peer() const override { return host_->peer(); }

private:
    std::shared_ptr<peripheral::Peripheral> device_;
    std::unique_ptr<transport::Connection> host_;
};

StudioDevice::StudioDevice(const StudioDeviceOptions& options) : grip_(options.grip), ring_(kRingSize) {
    if (!studio_grip(options.grip)) {
        throw std::invalid_argument("hand \"" + options.grip + "\" is not one of loose, firm, stiff");
    }
    if (const std::string wrong =
            transport::check_fifo_priority("report_path_fifo_priority", options.report_path_fifo_priority);
        !wrong.empty()) {
        throw std::invalid_argument(wrong);
    }
    host::OpenOptions open;
    open.report_rate_hz = options.report_rate_hz;  // 0: the device's own, until set below
    open.io_fifo_priority = options.report_path_fifo_priority;
    const std::string profile = simulated_profile(options.address);
    if (!profile.empty()) {
        peripheral::PeripheralOptions p;
        p.profile = profile;
        p.hand = options.grip;
        p.service_fifo_priority = options.report_path_fifo_priority;
        peripheral_ = std::make_shared<peripheral::Peripheral>(p);  // throws for an unknown profile
        transport::ConnectionPair pair = transport::in_process_pair("sim:" + profile);
        peripheral_->attach(std::move(pair.device));
        auto dev = host::Device::attach(
            std::make_unique<SharedPeripheralConnection>(peripheral_, std::move(pair.host)), "sim:" + profile, open);
        if (!dev) throw std::runtime_error("device " + options.address + ": " + dev.status().message);
        device_.emplace(std::move(dev.value()));
    } else {
        auto dev = host::Device::open(options.address, open);
        if (!dev) throw std::runtime_error("device " + options.address + ": " + dev.status().message);
        device_.emplace(std::move(dev.value()));
    }
    if (options.report_rate_hz == 0) {
        const int32_t every_tick = std::min(1000, device_->capabilities().loop_rate_hz);
        if (every_tick >= 100 && every_tick != device_->capabilities().report_rate_hz) {
            if (const host::Status s = device_->set_report_rate(every_tick); !s.ok()) {
                throw std::runtime_error("device " + options.address + ": " + s.message);
            }
        }
    }
    sampler_ = std::thread([this, priority = options.report_path_fifo_priority] {
        (void)transport::raise_thread_priority(priority);  // where the process may
        sample_loop();
    });
}

StudioDevice::~StudioDevice() {
    stopping_ = true;
    if (sampler_.joinable()) sampler_.join();
    device_->close();
}

void StudioDevice::sample_loop() {
    // Every report, through a per-report subscription (a plot that took only the newest
    // state lost stretches of reports whenever this thread waited for a core). Its queue
    // holds 2 s at 1 kHz: longer than this thread is ever kept from running.
    host::Device device = *device_;  // a copy of the shared handle for this thread
    std::optional<host::InputSubscription> reports;
    while (!stopping_) {
        if (!reports) {
            auto sub = device.subscribe_input(kSubscriptionRounds);
            if (!sub) {  // the device is gone: the plot stops, the sessions see it
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
                continue;
            }
            reports.emplace(std::move(sub.value()));
        }
        auto batch = reports->wait(std::chrono::milliseconds(50));
        if (!batch) {
            if (batch.status().kind == host::ErrorKind::disconnected) {
                reports.reset();
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
            continue;
        }
        const int64_t now_us = std::chrono::duration_cast<std::chrono::microseconds>(
                                   std::chrono::steady_clock::now().time_since_epoch()).count();
        std::lock_guard lock(mu_);
        dropped_ += batch->dropped;
        for (const host::InputState& in : batch->reports) {
            DeviceSample s;
            s.t_us = in.t_us;
            s.axis_count = in.axis_count;
            for (int a = 0; a < in.axis_count && a < kMaxAxes; ++a) {
                s.force[a] = in.force[a];
                s.position[a] = in.position[a];
            }
            s.buttons = in.buttons;
            s.fade_level = in.fade_level;
            s.hands_off = in.hands_off;
            s.host_us = now_us;
            s.seq = next_seq_++;
            ring_[s.seq % kRingSize] = s;
        }
    }
}

std::vector<DeviceSample> StudioDevice::samples_after(uint64_t after) const {
    std::lock_guard lock(mu_);
    std::vector<DeviceSample> out;
    const uint64_t newest = next_seq_ - 1;
    uint64_t first = after + 1;
    if (newest >= kRingSize && first + kRingSize <= newest) first = newest - kRingSize + 1;
    for (uint64_t s = first; s <= newest; ++s) out.push_back(ring_[s % kRingSize]);
    return out;
}

uint64_t StudioDevice::dropped_reports() const {
    std::lock_guard lock(mu_);
    return dropped_;
}

DeviceSample StudioDevice::newest() const {
    std::lock_guard lock(mu_);
    return next_seq_ == 1 ? DeviceSample{} : ring_[(next_seq_ - 1) % kRingSize];
}

uint64_t StudioDevice::newest_seq() const {
    std::lock_guard lock(mu_);
    return next_seq_ - 1;
}

json StudioDevice::describe() const {
    const host::DeviceCaps& c = device_->capabilities();
    json axes = json::array();
    for (int a = 0; a < c.axis_count; ++a) {
        axes.push_back({{"name", axis_name(c.axes[a].axis)},
                        {"rotary", c.axes[a].rotary},
                        {"half_travel", c.axes[a].half_travel},
                        {"max_force", c.axes[a].max_force}});
    }
    json types = {{"condition", json::array()}, {"wave", json::array()}, {"dynamic", json::array()}};
    for (const host::EffectSupport& e : device_->effects()) {
        types[std::string(class_key(e.effect_class))].push_back(effect_type_name(e.type));
    }
    json out = {{"address", device_->address()},
            {"name", c.device},
            {"description", c.description},
            {"class", c.class_name},
            {"axes", axes},
            {"buttons", c.button_count},
            {"hats", c.hat_count},
            {"local_reflexes", c.local_reflexes},
            {"loop_rate_hz", c.loop_rate_hz},
            {"interim_report_hz", c.interim_report_hz},
            {"effect_slots", c.effect_slots},
            {"types", types}};
    // A simulated device's input scales (EngineConfig): a damper reads velocity_ref
    // units/s as 10000, an inertia acceleration_ref units/s² (docs/conditions.md); the
    // condition editors plot their curves against these.
    if (const sim::DeviceProfile* p = peripheral_ ? sim::find_device_profile(simulated_profile(device_->address())) : nullptr) {
        const EngineConfig config = sim::engine_config_for(*p);
        out["velocity_ref"] = config.velocity_ref;
        out["acceleration_ref"] = config.acceleration_ref;
    }
    return out;
}

std::string StudioDevice::grip() const {
    std::lock_guard lock(mu_);
    return grip_;
}

bool StudioDevice::set_hand_target(int32_t x, int32_t y) {
    return peripheral_ && peripheral_->set_hand_target(x, y, 0);
}

int64_t StudioDevice::hand_target_taken_us() const noexcept {
    return peripheral_ ? peripheral_->hand_target_taken_us() : -1;
}

bool StudioDevice::set_grip(const std::string& grip) {
    if (!peripheral_ || !studio_grip(grip)) return false;
    peripheral_->set_grip(*sim::grip_from_name(grip));
    std::lock_guard lock(mu_);
    grip_ = grip;
    return true;
}

bool StudioDevice::set_buttons(uint32_t pressed) { return peripheral_ && peripheral_->set_buttons(pressed); }
bool StudioDevice::set_hats(uint32_t pushed) { return peripheral_ && peripheral_->set_hats(pushed); }

}  // namespace feel::studio
