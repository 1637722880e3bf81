// The engine's private state, shared by the files that implement Engine's methods.
//
// engine.cpp holds the tick and the effect commands; other engine_*.cpp files may add
// methods that need the slots. Nothing outside src/engine includes this header.
#pragma once

#include <cmath>
#include <memory>

#include "conditions/condition.hpp"
#include "dynamics/dynamic.hpp"
#include "feel/engine.hpp"
#include "motion_estimator.hpp"
#include "sample_pool.hpp"

namespace feel {
namespace detail {

struct Slot {
    EffectParams params{};
    float direction[kMaxAxes] = {};  // force per unit value on each device axis
    EffectState state = EffectState::free;
    uint16_t generation = 0;
    int64_t start_t_us = 0;
    bool began_playing = false;            // start_position is set
    float start_position[kMaxAxes] = {};   // sensed position when the effect began playing
    detail::ConditionState condition{};    // conditions' memory between ticks
    detail::DynamicState dynamic{};        // dynamics' simulated mass between ticks
    int64_t next_interim_us = 0;           // when the next interim report is due
};

// Checks every field of an EngineConfig; an invalid config makes an engine that refuses
// every create with this error.
[[nodiscard]] Error check_engine_config(const EngineConfig& c) noexcept;

}  // namespace detail

struct Engine::Impl {
    explicit Impl(const EngineConfig& c)
        : config(c),
          config_error(detail::check_engine_config(c)),
          slot_count(config_error ? 0 : c.max_effects),
          slots(new detail::Slot[static_cast<size_t>(slot_count > 0 ? slot_count : 1)]),
          samples(config_error ? 0 : c.max_samples, slot_count),
          report_capacity(config_error ? 1 : c.report_capacity),
          reports(new DynamicReport[static_cast<size_t>(report_capacity)]) {
        motion.configure(c.sensor_step);
    }

    // The report queue: a ring the tick writes and the host drains (single thread for now;
    // the device runtime puts a lock-free SPSC queue between them).
    void push_report(const DynamicReport& r) noexcept {
        if (report_count == report_capacity) {
            ++reports_dropped;
            return;
        }
        reports[(report_head + report_count) % report_capacity] = r;
        ++report_count;
    }

    // Interim reports at the configured rate while interim_reporting is set, a final report
    // when the dynamic ends by itself, and the first playing dynamic's mass in the output.
    void report_dynamic(detail::Slot& s, uint16_t index, int64_t t_us, const detail::DynamicResult& r,
                        const float* handle_velocity, TickOutput& out) noexcept {
        if (!out.has_mass) {
            out.has_mass = true;
            for (int a = 0; a < kMaxAxes; ++a) {
                out.mass_position[a] = r.mass_position[a];
                out.mass_velocity[a] = r.mass_velocity[a];
            }
        }
        const bool interim_due = s.params.dynamic.interim_reporting && t_us >= s.next_interim_us;
        if (!interim_due && !r.finished) return;
        DynamicReport report;
        report.effect = EffectId{index, s.generation};
        report.kind = r.finished ? DynamicReport::Kind::final : DynamicReport::Kind::interim;
        report.t_us = t_us;
        report.axis_count = s.params.axis_count;
        for (int i = 0; i < s.params.axis_count; ++i) {
            const int a = axis_index(s.params.axes[i]);
            report.position[i] = r.mass_position[a];
            report.velocity[i] = r.mass_velocity[a];
            report.handle_velocity[i] = handle_velocity[a];
        }
        push_report(report);
        if (interim_due) {
            // The next report is due one period after this one was due, so the rate holds on
            // average even when the period is not a whole number of ticks.
            const int64_t period_us = static_cast<int64_t>(1e6 / config.interim_report_hz);
            s.next_interim_us = (s.next_interim_us == 0 ? t_us : s.next_interim_us) + period_us;
            if (s.next_interim_us <= t_us) s.next_interim_us = t_us + period_us;
        }
    }

    detail::Slot* find(EffectId id) noexcept {
        if (id.index >= slot_count) return nullptr;
        detail::Slot& s = slots[id.index];
        return (s.state != EffectState::free && s.generation == id.generation) ? &s : nullptr;
    }

    EngineConfig config;
    Error config_error;
    int32_t slot_count;
    std::unique_ptr<detail::Slot[]> slots;
    detail::SamplePool samples;
    int32_t device_gain = kFullScale;
    detail::MotionEstimator motion;
    int32_t report_capacity;
    std::unique_ptr<DynamicReport[]> reports;
    int32_t report_head = 0;
    int32_t report_count = 0;
    uint64_t reports_dropped = 0;
    bool have_previous = false;
    int64_t previous_t_us = 0;
};

}  // namespace feel
