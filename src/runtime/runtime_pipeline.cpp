// The device's local control loop, one tick at a time (§2.2, figure 2-4).
//
// Why this order. Commands come first so that a start or a gain change the host sent
// before tick n acts in tick n, and so that the watchdog sees the host heard in this very
// tick. The sensors are read next, after the commands and before anything renders, so
// that the reflexes, the engine and the safety monitor all judge the same instant; the
// reflexes run before the engine so that a press starts its effect in the tick that sees
// the press (latency 0 ticks). The safety monitor is the last stage before the motors: it
// scales what the engine wants, and when it reports the host lost it stops every effect
// after this tick's force has been cut to zero anyway. IDF comes after the motors because
// it needs what the motors really got (the engine's force, clipped by the motor limit and
// scaled by the safety fade), and the reports come last because they describe the tick.
//
// The reported position. IDF removes the displacement the device's own vibrations and
// jolts cause from the sensed position; walls with clipping on hold the reported position
// at the wall's surface (§3.7), which the engine computes as TickOutput::reported_position
// from the sensed one. The two compose as sensed − displacement + (clipped − sensed): the
// wall's offset is added to the filtered position, so a vibration played against a
// clipping wall is filtered and the report still stops at the wall.
//
// Nothing here allocates, locks or throws after construction; every buffer, the scratch
// messages included, is a member sized in the constructor.
#include "feel/runtime/runtime_pipeline.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "error_prefix.hpp"

namespace feel::runtime {
namespace {

using detail::prefixed;

// The longest force profile one create can carry (validate_effect's sample count).
constexpr int32_t kMaxProfileSamples = static_cast<int32_t>(range::kSampleCount.max);

}  // namespace

Range report_rate_range(int32_t loop_rate_hz) noexcept {
    return {kMinReportRateHz, std::min<int64_t>(kMaxReportRateHz, loop_rate_hz)};
}

int32_t state_report_pages(int32_t max_effects) noexcept {
    return std::max(1, (max_effects + kEffectsPerReport - 1) / kEffectsPerReport);
}

RuntimeConfig runtime_config_for(const sim::DeviceProfile& profile) noexcept {
    RuntimeConfig c;
    c.engine = sim::engine_config_for(profile);
    c.safety = safety_config_for(profile);
    c.idf = idf_config_for(profile);
    c.loop_rate_hz = profile.default_loop_rate_hz;
    c.local_reflexes = profile.local_reflexes;
    return c;
}

Error check_runtime_config(const RuntimeConfig& c) noexcept {
    const Range loop{kMinLoopRateHz, kMaxLoopRateHz};
    if (!loop.contains(c.loop_rate_hz)) return Error::out_of_range("loop_rate_hz", c.loop_rate_hz, loop);
    if (const Range r = report_rate_range(c.loop_rate_hz); !r.contains(c.report_rate_hz)) {
        return Error::out_of_range("report_rate_hz", c.report_rate_hz, r);
    }
    const Range axes{1, kMaxAxes};
    if (!axes.contains(c.engine.axis_count)) return Error::out_of_range("engine.axis_count", c.engine.axis_count, axes);
    const Range slots{1, 65535};
    if (!slots.contains(c.engine.max_effects)) return Error::out_of_range("engine.max_effects", c.engine.max_effects, slots);
    const Range same_axes{c.engine.axis_count, c.engine.axis_count};
    if (c.safety.axis_count != c.engine.axis_count) {
        return Error::out_of_range("safety.axis_count", c.safety.axis_count, same_axes);
    }
    if (c.idf.axis_count != c.engine.axis_count) return Error::out_of_range("idf.axis_count", c.idf.axis_count, same_axes);
    if (Error e = check_safety_config(c.safety)) return prefixed("safety.", e);
    if (Error e = check_idf_config(c.idf)) return prefixed("idf.", e);
    const Range commands{1, 65536};
    if (!commands.contains(c.command_capacity)) return Error::out_of_range("command_capacity", c.command_capacity, commands);
    const Range per_tick{1, 1024};
    if (!per_tick.contains(c.max_commands_per_tick)) {
        return Error::out_of_range("max_commands_per_tick", c.max_commands_per_tick, per_tick);
    }
    const Range reports{int64_t{c.max_commands_per_tick} + state_report_pages(c.engine.max_effects) + 1, 1 << 20};
    if (!reports.contains(c.report_capacity)) return Error::out_of_range("report_capacity", c.report_capacity, reports);
    return {};
}

namespace {

const RuntimeConfig& checked(const RuntimeConfig& config, const RuntimeBackend* backend) {
    if (const Error e = check_runtime_config(config)) throw std::invalid_argument("runtime config: " + e.message());
    if (backend == nullptr) throw std::invalid_argument("runtime: no backend (a null RuntimeBackend)");
    if (backend->axis_count() != config.engine.axis_count) {
        throw std::invalid_argument("runtime: the backend has " + std::to_string(backend->axis_count()) +
                                    " axes and the engine " + std::to_string(config.engine.axis_count) +
                                    " (they must be the same device)");
    }
    return config;
}

}  // namespace

RuntimePipeline::RuntimePipeline(const RuntimeConfig& config, std::unique_ptr<RuntimeBackend> backend)
    : config_(checked(config, backend.get())),
      backend_(std::move(backend)),
      engine_(config_.engine),
      // An effect has at most one reflex, so one per effect slot can never run out.
      reflexes_(config_.engine.max_effects),
      idf_(config_.idf),
      force_stream_(config_.engine.axis_count, config_.loop_rate_hz),
      commands_(static_cast<std::size_t>(config_.command_capacity)),
      reports_(static_cast<std::size_t>(config_.report_capacity)),
      stage_capacity_(std::min(config_.engine.max_samples, kMaxProfileSamples)),
      report_rate_hz_(config_.report_rate_hz) {
    if (const Error e = safety_.configure(config_.safety)) {
        throw std::invalid_argument("runtime config: " + prefixed("safety.", e).message());
    }
    stage_ = std::make_unique<int16_t[]>(static_cast<std::size_t>(std::max(stage_capacity_, 1)));
    resident_ = std::make_unique<EffectId[]>(static_cast<std::size_t>(config_.engine.max_effects));
}

RuntimePipeline::~RuntimePipeline() = default;

RuntimeCounters RuntimePipeline::counters() const noexcept {
    constexpr auto r = std::memory_order_relaxed;
    const Counters& c = counters_;
    RuntimeCounters s;
    s.ticks = c.ticks.load(r);
    s.last_tick = c.last_tick.load(r);
    s.t_us = c.t_us.load(r);
    s.rejected_ticks = c.rejected_ticks.load(r);
    s.commands = c.commands.load(r);
    s.commands_refused = c.commands_refused.load(r);
    s.command_stalls = c.command_stalls.load(r);
    s.state_reports = c.state_reports.load(r);
    s.dropped_state_reports = c.dropped_state_reports.load(r);
    s.dynamic_reports = c.dynamic_reports.load(r);
    s.dropped_dynamic_reports = c.dropped_dynamic_reports.load(r);
    s.reflex_starts = c.reflex_starts.load(r);
    s.host_losses = c.host_losses.load(r);
    return s;
}

void RuntimePipeline::tick(int64_t tick_index) noexcept {
    if (tick_index <= last_tick_) {
        bump(counters_.rejected_ticks);
        return;
    }
    const int64_t t_us = loop_tick_time_us(tick_index, config_.loop_rate_hz);
    if (!started_) {
        // The host gets host_timeout_us from the first tick to say something, and the
        // first state report goes out at once.
        started_ = true;
        host_heard_us_ = t_us;
        restart_report_schedule(t_us);
    }
    last_tick_ = tick_index;

    // 1. The host's commands.
    drain_commands(t_us);

    // 2. The sensors.
    in_ = TickInput{};
    in_.t_us = t_us;
    backend_->sense(t_us, in_);

    // 3. Reflexes, before the engine: a press plays in this tick.
    reflexes_.on_tick(in_, engine_);

    // 4. Render: the effects, and the host's streamed force added as one more effect.
    engine_.tick(in_, out_);
    float force[kMaxAxes];
    std::copy(std::begin(out_.force), std::end(out_.force), force);
    force_stream_.output(tick_index, streamed_);
    add_streamed_force(streamed_, config_.engine.axis_count, engine_.gain(),
                       engine_.actuators_enabled() && !engine_.paused(), force);

    // 5. Safety, the last stage before the motors. A lost host ends the stream too: the
    // monitor has cut this tick's force, and nothing the host streamed comes back.
    const SafetyState& safety = safety_.process(safety_input(in_, out_, applied_, host_heard_us_), force);
    if (safety.host_lost_event) {
        engine_.stop_all();
        force_stream_.clear();
        bump(counters_.host_losses);
    }

    // 6. The motors.
    backend_->actuate(force);
    std::copy(std::begin(force), std::end(force), applied_);

    // 7. The reported position: IDF on the sensed position, then the clipping walls.
    engine_.activity(activity_);
    fit_activity_to_output(activity_, out_);
    scale_activity(activity_, safety.output_scale);
    float filtered[kMaxAxes];
    idf_.filter(t_us, in_.position, activity_, filtered);
    const int axes = config_.engine.axis_count;
    for (int a = 0; a < kMaxAxes; ++a) {
        const float clip_offset = out_.reported_position[a] - in_.position[a];
        reported_[a] = a < axes ? std::clamp(filtered[a] + clip_offset, -10000.0f, 10000.0f) : 0.0f;
    }

    // 8. Reports to the host.
    forward_dynamic_reports();
    post_state_report_if_due(t_us);

    const auto fired = static_cast<int64_t>(reflexes_.fired());
    if (fired != reflex_fired_seen_) {
        bump(counters_.reflex_starts, fired - reflex_fired_seen_);
        reflex_fired_seen_ = fired;
    }
    bump(counters_.ticks);
    counters_.last_tick.store(tick_index, std::memory_order_release);  // next_tick_index()
    counters_.t_us.store(t_us, std::memory_order_relaxed);
}

}  // namespace feel::runtime
