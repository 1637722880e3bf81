// libFuzzer target: the protocol decoder against arbitrary bytes (the device's first line
// of defence against a hostile host, codec.hpp).
//
//   decode(bytes) either refuses with an invalid_parameter Error naming a field, or gives
//   a report r, and then encode(r) == bytes   (nothing is normalized or lost)
//
// A crash, a sanitizer finding, an exception or a mismatch aborts.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>

#include "feel/protocol/codec.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace feel::protocol;
    const std::span<const uint8_t> bytes(data, size);
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
