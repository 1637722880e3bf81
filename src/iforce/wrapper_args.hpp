// The argument checks the §8 wrappers share, and the skeletons of their effects.
//
// Each wrapper builds one Args named after itself and passes every argument through it
// before using it: the first argument out of range throws std::invalid_argument with
// "<wrapper>: <parameter> = <value> is out of range (allowed <min>..<max>)". finish() then
// runs the engine's own validate_effect over the result, so a rule that ties fields
// together (which the per-argument checks do not see) is reported under the wrapper's
// name too, and a wrapper can never hand out an effect the engine would refuse.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string_view>

#include "feel/effect.hpp"
#include "feel/units.hpp"

namespace feel::iforce::detail {

// §8's ranges that units.hpp does not name (the primer is narrower than the engine there).
inline constexpr Range kWaveMagnitude{1, kFullScale};   // §8.3 Magnitude
inline constexpr Range kWaveOffset{0, kFullScale};      // §8.3 Offset
inline constexpr Range kRampLevel{0, kFullScale};       // §8.3 Start, End
inline constexpr Range kEnvelopeTimeUs{1, kMaxTimeUs};  // §8.3 SettleTime, FadeTime
inline constexpr Range kInertiaMass{1, kFullScale};     // §8.2 Mass
inline constexpr Range kInertiaSaturation{1, kFullScale};  // §8.2 Saturation (inertia)

class Args {
public:
    explicit Args(std::string_view wrapper) noexcept : wrapper_(wrapper) {}

    // Throws unless value lies in allowed.
    void check(std::string_view name, int64_t value, Range allowed) const;
    // A duration: 1..65e6 µs, or kInfiniteUs when allow_infinite.
    void duration(std::string_view name, int64_t value, bool allow_infinite) const;
    // A trigger (none, button 1..32, hat 1..4) and its repeat interval (0 or 1..65e6, only
    // with a trigger). required: kNoTrigger is refused.
    void trigger(Trigger trigger, int64_t repeat_interval_us, bool required = false) const;
    // Throws "<wrapper>: <name>: <rule>".
    [[noreturn]] void fail(std::string_view name, std::string_view rule) const;

    // validate_effect(params); throws with the engine's message if it refuses. Returns params.
    [[nodiscard]] EffectParams finish(const EffectParams& params) const;

private:
    std::string_view wrapper_;
};

// An effect of `type` that plays until stopped on the given axes, with §8.5's defaults.
[[nodiscard]] EffectParams on_axes(EffectType type, std::initializer_list<Axis> axes);

}  // namespace feel::iforce::detail
