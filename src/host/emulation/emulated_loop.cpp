// A wall in closed loop through a modelled link (emulated_loop.hpp).
#include "emulation/emulated_loop.hpp"

#include <algorithm>
#include <deque>

#include "emulation/host_renderer.hpp"
#include "feel/sim/sim_device.hpp"

namespace feel::host::emulation {
namespace {

constexpr double kStepS = 1e-3;  // the device's physics step, 1 ms

// One loop: the renderer, the link's queues, the held motor force.
class Loop {
public:
    Loop(const EngineConfig& config, int32_t hardness, const LoopLink& link) : renderer_(config), link_(link) {
        const CreateResult r = renderer_.create(wall_on_x(hardness));
        (void)renderer_.start(r.id, HostRenderer::kOwnIterations, false);
        // Reports in flight, one per ms, oldest first (L_up of them ahead of now).
        for (int i = 0; i < link.latency_up_ms; ++i) up_.push_back(0.0f);
        down_.assign(static_cast<size_t>(link.host ? link.latency_down_ms : 0), Pending{false, 0.0f});
    }

    // One ms: what the motor plays now, given the sensed position now.
    float step(int64_t ms, float sensed) {
        // The report sent now arrives L_up later; the one arriving now was sensed then.
        float seen = sensed;
        if (link_.host && link_.latency_up_ms > 0) {
            up_.push_back(sensed);
            seen = up_.front();
            up_.pop_front();
        }
        Pending sent{false, 0.0f};
        if (ms % link_.update_period_ms == 0) {
            const TickOutput& out = renderer_.render(ms * 1000, std::span<const float>(&seen, 1), 0, 0);
            sent = Pending{true, out.force[0]};
        }
        if (link_.host && link_.latency_down_ms > 0) {
            down_.push_back(sent);
            sent = down_.front();
            down_.pop_front();
        }
        if (sent.valid) held_ = sent.force;
        return held_;
    }

private:
    struct Pending {
        bool valid;
        float force;
    };
    HostRenderer renderer_;
    LoopLink link_;
    std::deque<float> up_;
    std::deque<Pending> down_;
    float held_ = 0.0f;
};

WallRun run(const sim::DeviceProfile& profile, const EngineConfig& config, int32_t hardness, const LoopLink& link,
            sim::Grip grip, sim::TargetMotion motion, double push, double start_x, double start_v, double duration_s) {
    sim::SimDevice device(profile, grip, std::move(motion));
    if (grip == sim::Grip::none) {
        device.set_position(0, start_x);
        device.set_velocity(0, start_v);
    }
    Loop loop(config, hardness, link);
    WallRun out;
    const auto steps = static_cast<int64_t>(duration_s / kStepS + 0.5);
    out.position.reserve(static_cast<size_t>(steps));
    out.force.reserve(static_cast<size_t>(steps));
    out.sensed.reserve(static_cast<size_t>(steps));
    for (int64_t ms = 0; ms < steps; ++ms) {
        TickInput in;
        device.sense(in);
        const float wall = loop.step(ms, in.position[0]);
        float force[kMaxAxes] = {};
        force[0] = std::clamp(wall + static_cast<float>(push), -static_cast<float>(kFullScale),
                              static_cast<float>(kFullScale));
        out.position.push_back(device.position(0));
        out.sensed.push_back(in.position[0]);
        out.force.push_back(wall);
        device.step(force, kStepS);
    }
    return out;
}

}  // namespace

EffectParams wall_on_x(int32_t hardness) {
    EffectParams p;
    p.type = EffectType::axis_wall;
    p.axis_count = 1;
    p.axes[0] = Axis::x;
    p.wall.hardness = hardness;
    p.wall.sense = WallSense::positive;
    return p;
}

WallRun run_pressed_wall(const sim::DeviceProfile& profile, const EngineConfig& config, int32_t hardness,
                         const LoopLink& link, double push, double kick_speed, double duration_s) {
    return run(profile, config, hardness, link, sim::Grip::none, sim::TargetMotion::hold_at({0.0}), push, 0.0,
               kick_speed, duration_s);
}

WallRun run_ramp_into_wall(const sim::DeviceProfile& profile, const EngineConfig& config, int32_t hardness,
                           const LoopLink& link, double x0, double speed, double duration_s) {
    const double x1 = x0 + speed * duration_s;
    std::string spec = "ramp:x:" + std::to_string(x0) + ":" + std::to_string(x1);
    return run(profile, config, hardness, link, sim::Grip::kinematic,
               sim::TargetMotion::parse(spec, duration_s, profile.axis_count), 0.0, x0, 0.0, duration_s);
}

double swing(const WallRun& run, double from_s, double to_s) {
    const auto from = static_cast<std::ptrdiff_t>(std::clamp(from_s / kStepS, 0.0, double(run.position.size())));
    const auto to = static_cast<std::ptrdiff_t>(std::clamp(to_s / kStepS, 0.0, double(run.position.size())));
    if (to <= from) return 0.0;
    const auto [lo, hi] = std::minmax_element(run.position.begin() + from, run.position.begin() + to);
    return *hi - *lo;
}

bool settled(const WallRun& run, const sim::DeviceProfile& profile) {
    if (run.position.size() < 1000) return false;
    const auto from = run.position.end() - 1000;
    const auto [lo, hi] = std::minmax_element(from, run.position.end());
    return *hi - *lo < 2.0 * 20000.0 / profile.axes[0].sensor_counts;
}

}  // namespace feel::host::emulation
