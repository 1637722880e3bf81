// Joystick Input in a device's own layout (codec.hpp: JoystickLayout): the report spec
// built from the layout, its size, and the checks of a layout.
#include "joystick_layout.hpp"

#include "hid_usages.hpp"
#include "report_table.hpp"

namespace feel::protocol {
namespace detail {
namespace {

int padding_bits(int bits) noexcept { return (8 - bits % 8) % 8; }

}  // namespace

void build_joystick_spec(const JoystickLayout& layout, JoystickSpec& out) noexcept {
    const int axes = layout.axis_count;
    for (int a = 0; a < axes; ++a) out.axis_usages[a] = usage::kAxisUsages[static_cast<int>(layout.axes[a])];
    for (int b = 0; b < 32; ++b) out.button_usages[b] = usage::button(static_cast<uint16_t>(b + 1));
    std::size_t n = 0;
    FieldSpec position = field(0, 16, range::kSignedLevel)
                             .times(axes)
                             .usages(std::span<const uint32_t>(out.axis_usages, static_cast<std::size_t>(axes)));
    position.path = "position[i]";
    position.get = [](const void* r, int i) noexcept -> int64_t {
        return static_cast<const JoystickInputReport*>(r)->position[i];
    };
    position.set = [](void* r, int i, int64_t v) noexcept {
        static_cast<JoystickInputReport*>(r)->position[i] = static_cast<int16_t>(v);
        return true;
    };
    out.fields[n++] = position;
    if (layout.button_count > 0) {
        out.fields[n++] = button_field(layout.button_count, out.button_usages);
        if (const int pad = padding_bits(layout.button_count); pad > 0) out.fields[n++] = padding_field(pad);
    }
    if (layout.hat_count > 0) {
        out.fields[n++] = hat_field(layout.hat_count);
        if (const int pad = padding_bits(4 * layout.hat_count); pad > 0) out.fields[n++] = padding_field(pad);
    }
    const ReportSpec& full = *find_report(static_cast<uint8_t>(ReportId::joystick_input));
    out.spec = full;
    out.spec.fields = std::span<const FieldSpec>(out.fields, n);
}

}  // namespace detail

Error check_layout(const JoystickLayout& layout) noexcept {
    if (layout.axis_count < 1 || layout.axis_count > kMaxAxes) {
        return Error::out_of_range("joystick_layout.axis_count", layout.axis_count, range::kAxisCount);
    }
    unsigned seen = 0;
    for (int a = 0; a < layout.axis_count; ++a) {
        const int axis = static_cast<int>(layout.axes[a]);
        if (axis < 0 || axis >= kMaxAxes) {
            return Error::out_of_range("joystick_layout.axes", axis, Range{0, kMaxAxes - 1});
        }
        if ((seen >> axis) & 1u) return Error::invalid("joystick_layout.axes", "names an axis twice");
        seen |= 1u << axis;
    }
    if (layout.button_count > 32) return Error::out_of_range("joystick_layout.button_count", layout.button_count, Range{0, 32});
    if (layout.hat_count > 4) return Error::out_of_range("joystick_layout.hat_count", layout.hat_count, Range{0, 4});
    return {};
}

std::size_t joystick_input_size(const JoystickLayout& layout) noexcept {
    if (check_layout(layout)) return 0;
    detail::JoystickSpec spec;
    detail::build_joystick_spec(layout, spec);
    return spec.spec.size();
}

}  // namespace feel::protocol
