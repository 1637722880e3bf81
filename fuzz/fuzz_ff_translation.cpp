// `feel bridge`'s ff_effect translation against hostile games (src/bridge/ff_translation):
// whatever bytes a struct ff_effect holds (the kernel checks only its type and waveform
// against the EV_FF bits; every other field is the game's), for a two-axis device with
// every type, a one-axis device and a device with constant forces only.
//
// Input: the bytes of a struct ff_effect (short inputs are zero-padded). Checks: a refusal
// is -EINVAL with a sentence and no effects; an accepted ff_effect gives one feel effect (two
// for FF_RUMBLE), each of a type the device plays, each valid by feel's one validator
// (validate_effect: in range, consistent), so the device never sees what it must refuse.
// Seeds (fuzz/corpus/ff_translation): the bytes (x86-64 layout) of the effects fftest and
// SDL2's testhaptic upload, as ff_spy recorded them in the Linux VM (tests/linux).
#include <linux/input.h>

#include <cerrno>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "../src/bridge/ff_translation.hpp"
#include "feel/effect_validation.hpp"

namespace {

feel::host::DeviceCaps device(int32_t axes, uint64_t types) {
    feel::host::DeviceCaps caps;
    caps.device = "fuzz";
    caps.axis_count = axes;
    const feel::Axis order[] = {feel::Axis::x, feel::Axis::y, feel::Axis::z};
    for (int i = 0; i < axes; ++i) caps.axes[i].axis = order[i];
    caps.button_count = 32;
    caps.supported_types = types;
    return caps;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    ff_effect e{};
    std::memcpy(&e, data, size < sizeof e ? size : sizeof e);
    static const feel::host::DeviceCaps devices[] = {
        device(2, feel::kAllEffectTypes), device(1, feel::kAllEffectTypes),
        device(3, feel::effect_type_bit(feel::EffectType::constant))};
    for (const feel::host::DeviceCaps& caps : devices) {
        const feel::bridge::Translation t = feel::bridge::translate_effect(e, caps);
        if (t.error != 0) {
            if (t.error != -EINVAL || t.message.empty() || !t.effects.empty()) std::abort();
            continue;
        }
        if (t.effects.size() != (e.type == FF_RUMBLE ? 2u : 1u)) std::abort();
        for (const feel::EffectParams& p : t.effects) {
            if (!caps.supports(p.type)) std::abort();
            if (feel::validate_effect(p)) std::abort();  // an invalid effect passed as valid
        }
    }
    return 0;
}
