// A frame built in one expression, for the transport tests.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "feel/transport/transport.hpp"

namespace feel::transport {

inline Frame frame_of(FrameKind kind, std::vector<uint8_t> payload) {
    Frame f;
    f.kind = kind;
    f.payload = std::move(payload);
    return f;
}

}  // namespace feel::transport
