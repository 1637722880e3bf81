// Step 8 of the tick: reports to the host (issue 5, §9).
//
// Three kinds share one queue, in priority: acks (step 1, always posted: a command waits
// for room for its ack), the dynamics' interim and final reports, and the state reports.
// The last two leave max_commands_per_tick places free so that the next tick's acks fit;
// beyond that a dynamic's report waits in the engine's own report store (which drops and
// counts when it overflows) and a state report round is dropped and counted. Nothing ever
// blocks or allocates.
//
// The schedule. State report k is due at origin + ceil(k·10^6 / rate) µs and goes out at
// the first tick at or after that time, so over any second exactly `rate` reports are
// posted and no rounding accumulates, whatever the loop rate (a 300 Hz report on a 1 kHz
// loop alternates gaps of 3 and 4 ticks). A tick that comes later than a whole report
// period (an overrun of the loop) posts once and skips the reports it missed: a burst of
// identical reports would tell the host nothing. The schedule restarts, with a report at
// once, at the first tick and whenever the host sets a new rate.
#include <algorithm>

#include "feel/runtime/runtime_pipeline.hpp"

namespace feel::runtime {
namespace {

ReportedEffectState reported_state(EffectState s) noexcept {
    switch (s) {
        case EffectState::delayed: return ReportedEffectState::delayed;
        // Started: pending begins at the next tick (or at resume, while paused).
        case EffectState::pending:
        case EffectState::playing: return ReportedEffectState::playing;
        case EffectState::free:
        case EffectState::stopped: break;
    }
    return ReportedEffectState::stopped;
}

// ceil(k·10^6 / rate) without overflow for any k a device reaches (k < 2^43).
int64_t report_offset_us(int64_t k, int32_t rate_hz) noexcept {
    return (k * 1'000'000 + rate_hz - 1) / rate_hz;
}

}  // namespace

void RuntimePipeline::restart_report_schedule(int64_t t_us) noexcept {
    report_origin_us_ = t_us;
    next_report_ = 0;
}

void RuntimePipeline::forward_dynamic_reports() noexcept {
    const int64_t reserve = config_.max_commands_per_tick;
    while (report_room() > reserve && engine_.pop_report(dynamic_)) {
        report_ = Report{};
        report_.kind = ReportKind::dynamic;
        report_.dynamic = dynamic_;
        (void)reports_.try_push(report_);  // room checked; the only producer
        bump(counters_.dynamic_reports);
    }
    counters_.dropped_dynamic_reports.store(static_cast<int64_t>(engine_.dropped_reports()),
                                            std::memory_order_relaxed);
}

void RuntimePipeline::post_state_report_if_due(int64_t t_us) noexcept {
    if (t_us < report_origin_us_ + report_offset_us(next_report_, report_rate_hz_)) return;
    // Skip every report this tick is already past the due time of, except the latest.
    do {
        ++next_report_;
    } while (report_origin_us_ + report_offset_us(next_report_, report_rate_hz_) <= t_us);
    post_state_reports(t_us);
}

void RuntimePipeline::post_state_reports(int64_t t_us) noexcept {
    const int32_t pages = std::max(1, (resident_count_ + kEffectsPerReport - 1) / kEffectsPerReport);
    if (report_room() < int64_t{pages} + config_.max_commands_per_tick) {
        bump(counters_.dropped_state_reports);
        return;
    }
    const uint32_t number = report_number_++;
    const uint64_t dropped = static_cast<uint64_t>(counters_.dropped_state_reports.load(std::memory_order_relaxed)) +
                             engine_.dropped_reports();
    report_ = Report{};
    report_.kind = ReportKind::state;
    StateReport& s = report_.state;
    s.t_us = t_us;
    s.report_number = number;
    s.axis_count = config_.engine.axis_count;
    std::copy(std::begin(reported_), std::end(reported_), s.position);
    for (int a = 0; a < kMaxAxes; ++a) s.velocity[a] = a < s.axis_count ? out_.velocity[a] : 0.0f;
    s.buttons = in_.buttons;
    s.hats = in_.hats;
    std::copy(std::begin(applied_), std::end(applied_), s.force);
    s.safety = safety_.state();
    s.paused = engine_.paused();
    s.actuators_enabled = engine_.actuators_enabled();
    s.gain = engine_.gain();
    s.playing_effects = out_.playing_effects;
    s.resident_effects = resident_count_;
    s.pages = pages;
    s.dropped_reports = dropped;

    // The resident effects in slot order, kEffectsPerReport to a page.
    int32_t slot = 0;
    for (int32_t page = 0; page < pages; ++page) {
        s.page = page;
        s.effect_count = 0;
        for (; slot < config_.engine.max_effects && s.effect_count < kEffectsPerReport; ++slot) {
            const EffectId id = resident_[slot];
            if (!id.valid()) continue;
            s.effects[s.effect_count++] = EffectStateEntry{id, reported_state(engine_.state(id))};
        }
        std::fill(s.effects + s.effect_count, s.effects + kEffectsPerReport, EffectStateEntry{});
        (void)reports_.try_push(report_);  // room for every page checked above
        bump(counters_.state_reports);
    }
}

}  // namespace feel::runtime
