// A RuntimePipeline on the simulated device, ticked by hand, with the host's end of its
// queues: what the device runtime's tests drive. No thread: tick n runs when the test says.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "feel/runtime/host_link.hpp"
#include "feel/runtime/runtime_backend.hpp"
#include "feel/runtime/runtime_pipeline.hpp"
#include "feel/sim/device_profile.hpp"
#include "feel/sim/input_schedule.hpp"

namespace feel::runtime::test {

inline const sim::DeviceProfile& joystick() { return *sim::find_device_profile("joystick"); }

// The profile's runtime with forces at once and no host watchdog: tests that are not about
// safety see the engine's forces unscaled, and need no keep-alives.
inline RuntimeConfig quiet_config(const sim::DeviceProfile& profile = joystick()) {
    RuntimeConfig c = runtime_config_for(profile);
    c.safety.fade_in_us = 0;
    c.safety.host_timeout_us = kInfiniteUs;
    return c;
}

class Rig {
public:
    explicit Rig(const RuntimeConfig& config, const sim::DeviceProfile& profile = joystick(),
                 sim::Grip grip = sim::Grip::firm, sim::TargetMotion motion = sim::TargetMotion::hold_at({0}),
                 std::optional<sim::InputSchedule> schedule = std::nullopt) {
        auto backend = std::make_unique<SimBackend>(profile, grip, std::move(motion), std::move(schedule));
        sim_ = backend.get();
        pipeline_ = std::make_unique<RuntimePipeline>(config, std::move(backend));
        host_ = std::make_unique<HostLink>(pipeline_->commands(), pipeline_->reports());
    }

    RuntimePipeline& pipeline() { return *pipeline_; }
    HostLink& host() { return *host_; }
    SimBackend& sim() { return *sim_; }
    // Device time of the next tick, µs.
    [[nodiscard]] int64_t t_us() const { return loop_tick_time_us(next_tick_, pipeline_->config().loop_rate_hz); }
    [[nodiscard]] int64_t next_tick() const { return next_tick_; }

    // Runs `ticks` ticks; after each, the host drains the report queue into acks, states
    // and dynamics (unless draining is off).
    void run(int64_t ticks) {
        for (int64_t i = 0; i < ticks; ++i) {
            pipeline_->tick(next_tick_++);
            if (draining_) drain();
        }
    }
    // Runs until device time t_us (exclusive).
    void run_until(int64_t t_us) {
        while (t_us_of(next_tick_) < t_us) run(1);
    }
    void drain() {
        Report r;
        while (host_->poll(r)) {
            switch (r.kind) {
                case ReportKind::ack: acks.push_back(r.ack); break;
                case ReportKind::state: states.push_back(r.state); break;
                case ReportKind::dynamic: dynamics.push_back(r.dynamic); break;
            }
        }
    }
    void set_draining(bool on) { draining_ = on; }

    // Ticks until the ack of `sequence` has come back (at most 100 ticks) and returns it.
    CommandAck ack(std::optional<uint32_t> sequence) {
        EXPECT_TRUE(sequence.has_value()) << "the command was not sent (queue full)";
        if (!sequence) return {};
        for (int i = 0; i <= 100; ++i) {
            for (const CommandAck& a : acks) {
                if (a.sequence == *sequence) return a;
            }
            run(1);
        }
        ADD_FAILURE() << "no ack for command " << *sequence;
        return {};
    }
    // Sends, then waits for the ack of a command that must succeed.
    CommandAck ok(std::optional<uint32_t> sequence) {
        const CommandAck a = ack(sequence);
        EXPECT_TRUE(a.error.ok()) << command_kind_name(a.command) << ": " << a.error.message();
        return a;
    }

    std::vector<CommandAck> acks;
    std::vector<StateReport> states;
    std::vector<DynamicReport> dynamics;

private:
    [[nodiscard]] int64_t t_us_of(int64_t tick) const { return loop_tick_time_us(tick, pipeline_->config().loop_rate_hz); }

    SimBackend* sim_ = nullptr;
    std::unique_ptr<RuntimePipeline> pipeline_;
    std::unique_ptr<HostLink> host_;
    int64_t next_tick_ = 0;
    bool draining_ = true;
};

}  // namespace feel::runtime::test
