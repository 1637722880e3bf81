// The argument checks of the §8 wrappers (wrapper_args.hpp).
#include "wrapper_args.hpp"

#include <stdexcept>
#include <string>

#include "feel/effect_validation.hpp"
#include "feel/status.hpp"

namespace feel::iforce::detail {

void Args::check(std::string_view name, int64_t value, Range allowed) const {
    if (allowed.contains(value)) return;
    throw std::invalid_argument(std::string(wrapper_) + ": " +
                                Error::out_of_range(name, value, allowed).message());
}

void Args::duration(std::string_view name, int64_t value, bool allow_infinite) const {
    if (value == kInfiniteUs) {
        if (allow_infinite) return;
        fail(name, "must be finite here (allowed 1..65000000 µs, not kInfiniteUs)");
    }
    if (range::kDurationUs.contains(value)) return;
    throw std::invalid_argument(
        std::string(wrapper_) + ": " + Error::out_of_range(name, value, range::kDurationUs).message() +
        (allow_infinite ? ", or kInfiniteUs for no end" : ""));
}

void Args::trigger(Trigger trigger, int64_t repeat_interval_us, bool required) const {
    switch (trigger.kind) {
        case TriggerKind::none:
            if (required) {
                fail("trigger", "is none; this wrapper plays on a button press: pass "
                                "button_trigger(1..32) or hat_trigger(1..4)");
            }
            if (repeat_interval_us != 0) {
                fail("trigger_repeat_interval_us",
                     "= " + std::to_string(repeat_interval_us) +
                         " needs a trigger to repeat on (the trigger is none); pass 0");
            }
            return;
        case TriggerKind::button:
            check("trigger button", trigger.index, range::kTriggerButton);
            break;
        case TriggerKind::hat:
            check("trigger hat", trigger.index, range::kTriggerHat);
            break;
        default:
            fail("trigger", "the trigger kind must be none, button or hat");
    }
    check("trigger_repeat_interval_us", repeat_interval_us, range::kRepeatIntervalUs);
}

void Args::fail(std::string_view name, std::string_view rule) const {
    std::string message(wrapper_);
    message += ": ";
    message += name;
    // A rule that continues the sentence ("= 5 needs ...", "is none; ...") follows a space.
    message += rule.starts_with("=") || rule.starts_with("is ") || rule.starts_with("must ") ? " " : ": ";
    message += rule;
    throw std::invalid_argument(message);
}

EffectParams Args::finish(const EffectParams& params) const {
    if (const Error e = validate_effect(params)) {
        throw std::invalid_argument(std::string(wrapper_) + ": " + e.message());
    }
    return params;
}

EffectParams on_axes(EffectType type, std::initializer_list<Axis> axes) {
    EffectParams p;
    p.type = type;
    p.duration_us = kInfiniteUs;
    p.start_delay_us = 0;
    p.gain = kFullScale;
    p.iterations = 1;
    p.axis_count = static_cast<int32_t>(axes.size());
    int i = 0;
    for (Axis a : axes) p.axes[i++] = a;
    return p;
}

}  // namespace feel::iforce::detail
