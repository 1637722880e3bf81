// libFuzzer target: the protocol decoder against arbitrary bytes (the device's first line
// of defence against a hostile host, codec.hpp).
//
//   decode(bytes) either refuses with an invalid_parameter Error naming a field, or gives
//   a report r, and then encode(r) == bytes   (nothing is normalized or lost)
//
// and the same for Joystick Input in a device's own layout.
//
// A crash, a sanitizer finding, an exception or a mismatch aborts.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>

#include "feel/protocol/codec.hpp"

namespace {

// Joystick Input in a device's own layout (picked from the input's size, so that every
// layout is reached): the same contract.
void check_joystick(std::span<const uint8_t> bytes) {
    using namespace feel::protocol;
    JoystickLayout layout;
    layout.axis_count = static_cast<uint8_t>(1 + bytes.size() % 6);
    layout.button_count = static_cast<uint8_t>(bytes.size() % 33);
    layout.hat_count = static_cast<uint8_t>(bytes.size() % 5);
    JoystickInputReport joy;
    const feel::Error e = decode(bytes, layout, joy);
    if (!e.ok()) {
        if (e.code != feel::ErrorCode::invalid_parameter || e.field[0] == '\0') std::abort();
        return;
    }
    const std::vector<uint8_t> again = encode(joy, layout);
    if (!std::equal(again.begin(), again.end(), bytes.begin(), bytes.end())) {
        std::fprintf(stderr, "decode/encode changed a %zu-byte joystick input\n", bytes.size());
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace feel::protocol;
    const std::span<const uint8_t> bytes(data, size);
    check_joystick(bytes);
    AnyReport report;
    const feel::Error e = decode(bytes, report);
    if (!e.ok()) {
        if (e.code != feel::ErrorCode::invalid_parameter || e.field[0] == '\0') {
            std::fprintf(stderr, "refusal without a field: %s\n", e.message().c_str());
            std::abort();
        }
        return 0;
    }
    const std::vector<uint8_t> again = encode(report);
    if (again.size() != size || !std::equal(again.begin(), again.end(), data)) {
        std::fprintf(stderr, "decode/encode changed a %zu-byte report (id 0x%02X)\n", size,
                     static_cast<unsigned>(data[0]));
        std::abort();
    }
    return 0;
}
