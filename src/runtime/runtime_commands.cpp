// Step 1 of the tick: the host's commands, applied to the engine and acknowledged.
//
// Each command is checked before it changes anything (the engine's own rule), so a refused
// command leaves the device as it was, and its ack names the field and the range. A
// command is taken from its queue only when the report queue has room for its ack: a
// host that stops reading reports stalls its own commands instead of losing acks.
//
// Beyond the engine's methods the runtime keeps three things in step with the effects:
//  - the reflex table: an effect's Trigger Button and Trigger Repeat Interval (§6.3) make
//    its reflex when it is created and whenever an update touches them; destroying the
//    effect or resetting the device removes it. A device without local reflexes (the
//    I-FORCE 1.x class) keeps the trigger fields and arms nothing;
//  - the resident list (slot -> EffectId), which the state reports enumerate;
//  - the sample stage, which force profiles' create and update consume.
#include <algorithm>

#include "error_prefix.hpp"
#include "feel/runtime/runtime_pipeline.hpp"

namespace feel::runtime {
namespace {

Error no_such_effect() noexcept {
    return Error::of(ErrorCode::invalid_handle, "effect", "no such effect: freed, reset or never created");
}

Error no_local_reflexes() noexcept {
    return Error::of(ErrorCode::not_supported, "trigger_button",
                     "this device runs no reflexes itself (an I-FORCE 1.x-class processor): the host emulates them");
}

}  // namespace

int64_t RuntimePipeline::report_room() const noexcept {
    // From the producer's side size_approx() can only overstate what the queue holds (the
    // consumer may have popped since), so this never promises room that is not there.
    return static_cast<int64_t>(reports_.capacity()) - static_cast<int64_t>(reports_.size_approx());
}

void RuntimePipeline::drain_commands(int64_t t_us) noexcept {
    // A release holds every later command, and its ack, until the host's fade has ended.
    if (releasing_) {
        if (!safety_.state().host_faded || report_room() < 1) return;
        report_ = Report{};
        report_.kind = ReportKind::ack;
        report_.ack.sequence = release_sequence_;
        report_.ack.command = CommandKind::release_host;
        report_.ack.t_us = t_us;
        (void)reports_.try_push(report_);
        releasing_ = false;
    }
    // Anything waiting in the queue, applied now or not, shows the host is alive.
    if (commands_.size_approx() > 0) host_heard_us_ = t_us;
    for (int32_t i = 0; i < config_.max_commands_per_tick; ++i) {
        if (report_room() < 1) {
            if (commands_.size_approx() > 0) bump(counters_.command_stalls);
            return;
        }
        if (!commands_.try_pop(command_)) return;
        // A release with force on the motors fades it out first; with none there is
        // nothing to fade, and it is acked at once like any command.
        const bool at_rest = std::all_of(std::begin(applied_), std::end(applied_), [](float f) { return f == 0.0f; });
        if (command_.kind == CommandKind::release_host && !at_rest) {
            safety_.release_host(t_us);
            releasing_ = true;
            release_sequence_ = command_.sequence;
            bump(counters_.commands);
            return;
        }
        report_ = Report{};
        report_.kind = ReportKind::ack;
        CommandAck& ack = report_.ack;
        ack.sequence = command_.sequence;
        ack.command = command_.kind;
        ack.t_us = t_us;
        ack.effect = command_.effect;
        ack.error = apply(command_, ack);
        (void)reports_.try_push(report_);  // room checked above; this thread is the only producer
        bump(counters_.commands);
        if (!ack.error.ok()) bump(counters_.commands_refused);
    }
}

Error RuntimePipeline::apply(const Command& c, CommandAck& ack) noexcept {
    switch (c.kind) {
        case CommandKind::keep_alive:
        case CommandKind::release_host:  // with the motors at rest: nothing to fade
            return {};
        case CommandKind::create:
            return apply_create(c, ack);
        case CommandKind::update:
            return apply_update(c, ack);
        case CommandKind::start:
            return apply_start(c, ack);
        case CommandKind::stop: {
            const Error e = engine_.stop(c.effect);
            ack.status = engine_.status(c.effect);
            return e.ok() ? e : no_such_effect();
        }
        case CommandKind::destroy:
            return apply_destroy(c, ack);
        case CommandKind::status:
            ack.status = engine_.status(c.effect);
            return ack.status.state == EffectState::free ? no_such_effect() : Error{};
        case CommandKind::set_gain:
            return engine_.set_gain(c.value);
        case CommandKind::device_control:
            return apply_device_control(c, ack);
        case CommandKind::query_pool:
            ack.pool = engine_.pool();
            return {};
        case CommandKind::assign_reflex:
            if (engine_.state(c.effect) == EffectState::free) return no_such_effect();
            if (!config_.local_reflexes) return no_local_reflexes();
            return reflexes_.assign_from(engine_, c.effect);
        case CommandKind::remove_reflex:
            if (engine_.state(c.effect) == EffectState::free) return no_such_effect();
            if (!config_.local_reflexes) return no_local_reflexes();
            return reflexes_.remove(c.effect);
        case CommandKind::set_idf:
            idf_.set_settings(c.idf);
            return {};
        case CommandKind::configure_safety:
            return apply_configure_safety(c);
        case CommandKind::set_report_rate:
            return apply_set_report_rate(c, ack.t_us);
        case CommandKind::stage_samples:
            return apply_stage_samples(c, ack);
        case CommandKind::stream_force:
            return apply_stream_force(c);
    }
    return Error::out_of_range("command.kind", static_cast<int64_t>(c.kind), {0, kCommandKindCount - 1});
}

std::span<const int16_t> RuntimePipeline::take_staged_samples() noexcept {
    const std::span<const int16_t> samples(stage_.get(), static_cast<std::size_t>(staged_));
    staged_ = 0;  // taken, whatever the command's outcome: a new stage starts at offset 0
    return samples;
}

Error RuntimePipeline::apply_create(const Command& c, CommandAck& ack) noexcept {
    const bool profile = c.params.type == EffectType::force_profile;
    const std::span<const int16_t> samples = profile ? take_staged_samples() : std::span<const int16_t>();
    const CreateResult r = engine_.create(c.params, samples);
    if (r.error) {
        ack.pool = engine_.pool();
        return r.error;
    }
    // The table has a reflex per slot and the engine has already checked the trigger
    // fields with the reflex's own rules, so this cannot fail; if it ever did, the create
    // is undone rather than leaving an effect without the reflex it asked for.
    if (const Error e = config_.local_reflexes ? reflexes_.assign_from(engine_, r.id) : Error{}) {
        (void)engine_.destroy(r.id);
        ack.pool = engine_.pool();
        return e;
    }
    track(r.id);
    ack.effect = r.id;
    ack.pool = engine_.pool();
    return {};
}

Error RuntimePipeline::apply_update(const Command& c, CommandAck& ack) noexcept {
    const bool new_samples =
        c.params.type == EffectType::force_profile && (c.field_mask & effect_field::kTypeSpecific) != 0;
    const std::span<const int16_t> samples = new_samples ? take_staged_samples() : std::span<const int16_t>();
    Error e = engine_.update(c.effect, c.params, c.field_mask, c.restart, samples);
    if (e.ok() && config_.local_reflexes &&
        (c.field_mask & (effect_field::kTrigger | effect_field::kTriggerRepeat)) != 0) {
        // The new trigger fields passed the engine's validation, so this cannot fail.
        e = reflexes_.assign_from(engine_, c.effect);
    }
    ack.status = engine_.status(c.effect);
    if (!e.ok() && ack.status.state == EffectState::free) return no_such_effect();
    return e;
}

Error RuntimePipeline::apply_start(const Command& c, CommandAck& ack) noexcept {
    if (engine_.state(c.effect) == EffectState::free) return no_such_effect();
    Error e;
    if (c.iterations != kEffectIterations) {
        e = engine_.start(c.effect, c.iterations, c.solo);
    } else {
        // The effect's own count: Engine::start(id). Solo stops every other effect first,
        // as Engine::start(id, n, true) does.
        if (c.solo) {
            for (int32_t i = 0; i < config_.engine.max_effects; ++i) {
                if (resident_[i].valid() && !(resident_[i] == c.effect)) (void)engine_.stop(resident_[i]);
            }
        }
        e = engine_.start(c.effect);
    }
    ack.status = engine_.status(c.effect);
    return e;
}

Error RuntimePipeline::apply_destroy(const Command& c, CommandAck& ack) noexcept {
    if (engine_.state(c.effect) == EffectState::free) return no_such_effect();
    const Error e = engine_.destroy(c.effect);
    if (e.ok()) {
        (void)reflexes_.remove(c.effect);  // invalid_handle when it had none: nothing to do
        untrack(c.effect);
    }
    ack.pool = engine_.pool();
    return e;
}

Error RuntimePipeline::apply_device_control(const Command& c, CommandAck& ack) noexcept {
    switch (c.control) {
        case DeviceControl::actuators_on:
        case DeviceControl::actuators_off: {
            const bool on = c.control == DeviceControl::actuators_on;
            // The engine cuts and restores at once; the monitor makes the restore a fade-in.
            engine_.set_actuators_enabled(on);
            safety_.set_actuators_enabled(on);
            return {};
        }
        case DeviceControl::stop_all:
            engine_.stop_all();
            force_stream_.clear();  // the streamed force is one more playing force
            return {};
        case DeviceControl::reset:
            engine_.reset();
            force_stream_.clear();
            reflexes_.clear();
            untrack_all();
            staged_ = 0;
            safety_.set_actuators_enabled(true);  // the engine's reset turned them on
            ack.pool = engine_.pool();
            return {};
        case DeviceControl::pause:
            engine_.pause();
            return {};
        case DeviceControl::resume:
            engine_.resume();
            return {};
    }
    return Error::out_of_range("control", static_cast<int64_t>(c.control), {0, kDeviceControlCount - 1});
}

Error RuntimePipeline::apply_configure_safety(const Command& c) noexcept {
    if (c.safety.axis_count != config_.engine.axis_count) {
        const Range same{config_.engine.axis_count, config_.engine.axis_count};
        return Error::out_of_range("safety.axis_count", c.safety.axis_count, same);
    }
    // configure() validates first and changes nothing on an error; on success it restarts
    // the monitor (fade level 0: forces fade in again) with the actuators enabled, so the
    // host's last actuator command is applied again.
    if (Error e = safety_.configure(c.safety)) return detail::prefixed("safety.", e);
    safety_.set_actuators_enabled(engine_.actuators_enabled());
    return {};
}

Error RuntimePipeline::apply_set_report_rate(const Command& c, int64_t t_us) noexcept {
    const Range allowed = report_rate_range(config_.loop_rate_hz);
    if (!allowed.contains(c.value)) return Error::out_of_range("report_rate_hz", c.value, allowed);
    report_rate_hz_ = c.value;
    restart_report_schedule(t_us);  // the first report at the new rate goes out this tick
    return {};
}

Error RuntimePipeline::apply_stage_samples(const Command& c, CommandAck& ack) noexcept {
    const Range count{1, kSamplesPerCommand};
    if (!count.contains(c.sample_count)) {
        ack.staged_samples = staged_;
        return Error::out_of_range("sample_count", c.sample_count, count);
    }
    // Offset 0 starts a new stage; any other continues the current one, in order.
    const int32_t expected = c.sample_offset == 0 ? 0 : staged_;
    if (c.sample_offset != expected) {
        ack.staged_samples = staged_;
        return Error::out_of_range("sample_offset", c.sample_offset, {0, staged_});
    }
    if (int64_t{c.sample_offset} + c.sample_count > stage_capacity_) {
        ack.staged_samples = staged_;
        Error e = Error::of(ErrorCode::device_full, "sample_offset",
                            "the samples exceed the device's sample stage (value: the samples "
                            "they would make; allowed.max: the stage's size)");
        e.value = int64_t{c.sample_offset} + c.sample_count;
        e.allowed = {0, stage_capacity_};
        return e;
    }
    std::copy(c.samples, c.samples + c.sample_count, stage_.get() + c.sample_offset);
    staged_ = c.sample_offset + c.sample_count;
    ack.staged_samples = staged_;
    return {};
}

Error RuntimePipeline::apply_stream_force(const Command& c) noexcept {
    const int32_t axes = config_.engine.axis_count;
    if (c.stream_axis_count != axes) return Error::out_of_range("stream.axis_count", c.stream_axis_count, {axes, axes});
    static constexpr const char* kForceFields[kMaxAxes] = {"stream.force[0]", "stream.force[1]", "stream.force[2]",
                                                           "stream.force[3]", "stream.force[4]", "stream.force[5]"};
    for (int32_t a = 0; a < axes; ++a) {
        if (!range::kSignedLevel.contains(c.stream_force[a])) {
            return Error::out_of_range(kForceFields[a], c.stream_force[a], range::kSignedLevel);
        }
    }
    // Commands are applied in the tick that takes them (last_tick_ is already this tick).
    force_stream_.push(last_tick_, c.stream_force);
    return {};
}

void RuntimePipeline::track(EffectId id) noexcept {
    if (id.index >= config_.engine.max_effects) return;
    if (!resident_[id.index].valid()) ++resident_count_;
    resident_[id.index] = id;
}

void RuntimePipeline::untrack(EffectId id) noexcept {
    if (id.index >= config_.engine.max_effects || !(resident_[id.index] == id)) return;
    resident_[id.index] = EffectId{};
    --resident_count_;
}

void RuntimePipeline::untrack_all() noexcept {
    std::fill(resident_.get(), resident_.get() + config_.engine.max_effects, EffectId{});
    resident_count_ = 0;
}

}  // namespace feel::runtime
