// The engine refuses the effect types its device does not play (engine_support.hpp).
#include "engine_support.hpp"

#include <algorithm>
#include <string_view>

namespace feel::detail {
namespace {

// Appends `s` to the field buffer, keeping room for the terminating NUL: Error::field is
// fixed-size so that errors never allocate; a long device class is cut, never overflowed.
void append(char (&dst)[48], int& len, std::string_view s) noexcept {
    const int room = static_cast<int>(sizeof dst) - 1 - len;
    const int n = std::min(room, static_cast<int>(s.size()));
    std::copy_n(s.data(), n, dst + len);
    len += n;
    dst[len] = '\0';
}

}  // namespace

Error check_supported(const EngineConfig& config, EffectType type) noexcept {
    if ((config.supported_types & effect_type_bit(type)) != 0) return {};
    Error e = Error::of(ErrorCode::not_supported, "",
                        config.device_class.empty()
                            ? "not supported by this device (its EngineConfig::supported_types)"
                            : "not supported by this device class (feel caps lists the effect "
                              "types a device plays)");
    int len = 0;
    append(e.field, len, "type ");
    append(e.field, len, effect_type_name(type));
    if (!config.device_class.empty()) {
        append(e.field, len, " on ");
        append(e.field, len, config.device_class);
    }
    return e;
}

static_assert(kEffectTypeCount == 33, "the message of check_supported_types names 33 types");

Error check_supported_types(const EngineConfig& config) noexcept {
    if ((config.supported_types & ~kAllEffectTypes) == 0) return {};
    return Error::invalid("supported_types", "has bits beyond the 33 effect types "
                                             "(allowed bits 0..32, one per EffectType)");
}

}  // namespace feel::detail
