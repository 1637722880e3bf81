// A writer of DirectInput effect files (.ffe) for the tests, from the layout documented in
// docs/import.md ("DirectInput effect files"): the tests build files from known DIEFFECT
// values and check the importer's result against the documented mapping. It is written
// from the public structure definitions (dinput.h's DIEFFECT and type-specific structs),
// not from the importer.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace feel::test {

// The first byte of {13541C2x-8E33-11D0-9AD0-00A0C9A06E35}, DirectInput's predefined effects.
enum DiGuid : uint8_t {
    kGuidConstant = 0x20, kGuidRamp, kGuidSquare, kGuidSine, kGuidTriangle, kGuidSawUp, kGuidSawDown,
    kGuidSpring, kGuidDamper, kGuidInertia, kGuidFriction, kGuidCustom
};

inline constexpr uint32_t kDiInfinite = 0xFFFFFFFFu;
inline constexpr uint32_t kDijofsX = 0, kDijofsY = 4, kDijofsZ = 8;
inline constexpr uint32_t kObjectOffsets = 0x02, kCartesian = 0x10, kPolar = 0x20, kSpherical = 0x40;

struct DiEnvelope {
    uint32_t attack_level, attack_time_us, fade_level, fade_time_us;
};

struct DiFileEffect {
    std::string name = "Effect";
    uint32_t flags = kObjectOffsets | kPolar;
    uint32_t duration_us = 1'000'000;
    uint32_t sample_period_us = 0;
    uint32_t gain = 10000;
    uint32_t trigger_button = kDiInfinite;  // DIEB_NOTRIGGER
    uint32_t trigger_repeat_us = kDiInfinite;
    std::vector<uint32_t> axes = {kDijofsX, kDijofsY};
    std::vector<int32_t> direction = {0, 0};
    std::optional<DiEnvelope> envelope;
    std::vector<int32_t> type_specific;  // the structure's members, each 4 bytes
    std::optional<std::vector<int32_t>> custom_samples;
    uint32_t start_delay_us = 0;
    bool dx5 = false;  // DIEFFECT without dwStartDelay (52 bytes)
    uint8_t guid = kGuidSine;
    uint32_t iterations = 1;
};

inline void put32(std::string& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
}

inline void put_chunk(std::string& out, const char* id, const std::string& body) {
    out += std::string(id, 4);
    put32(out, static_cast<uint32_t>(body.size()));
    out += body;
}

inline std::string data_of(const std::vector<int32_t>& values) {
    std::string body;
    for (int32_t v : values) put32(body, static_cast<uint32_t>(v));
    return body;
}

inline std::string effect_list(const DiFileEffect& e) {
    std::string body = "efct";
    std::string name = e.name;
    name.resize(64, '\0');
    body += name;
    put32(body, e.dx5 ? 52 : 56);
    put32(body, e.flags);
    put32(body, e.duration_us);
    put32(body, e.sample_period_us);
    put32(body, e.gain);
    put32(body, e.trigger_button);
    put32(body, e.trigger_repeat_us);
    put32(body, static_cast<uint32_t>(e.axes.size()));
    put32(body, 0x20);                       // rgdwAxes: present
    put32(body, 0x40);                       // rglDirection: present
    put32(body, e.envelope ? 0x80 : 0);      // lpEnvelope
    put32(body, static_cast<uint32_t>(e.type_specific.size() * 4));
    put32(body, 0x100);                      // lpvTypeSpecificParams
    if (!e.dx5) put32(body, e.start_delay_us);
    const uint8_t tail[15] = {0x1C, 0x54, 0x13, 0x33, 0x8E, 0xD0, 0x11, 0x9A, 0xD0, 0x00, 0xA0, 0xC9, 0xA0, 0x6E, 0x35};
    body += static_cast<char>(e.guid);
    body.append(reinterpret_cast<const char*>(tail), 15);
    put32(body, e.iterations);
    std::vector<int32_t> axes(e.axes.begin(), e.axes.end());
    put_chunk(body, "data", data_of(axes));
    put_chunk(body, "data", data_of(e.direction));
    if (e.envelope) {
        put_chunk(body, "data", data_of({20, static_cast<int32_t>(e.envelope->attack_level),
                                         static_cast<int32_t>(e.envelope->attack_time_us),
                                         static_cast<int32_t>(e.envelope->fade_level),
                                         static_cast<int32_t>(e.envelope->fade_time_us)}));
    }
    if (!e.type_specific.empty()) put_chunk(body, "data", data_of(e.type_specific));
    if (e.custom_samples) put_chunk(body, "data", data_of(*e.custom_samples));
    std::string out;
    put_chunk(out, "LIST", body);
    return out;
}

// A whole file; riff_size_zero writes the RIFF size as 0, as Force Editor does.
inline std::string ffe_file(const std::vector<DiFileEffect>& effects, bool riff_size_zero = false) {
    std::string body = "FORC";
    const uint8_t file_guid[16] = {0x5C, 0x77, 0x7E, 0x19, 0xBA, 0x34, 0xD3, 0x11,
                                   0xAB, 0xD5, 0x00, 0xC0, 0x4F, 0x8E, 0xC6, 0x27};
    body.append(reinterpret_cast<const char*>(file_guid), 16);
    for (const DiFileEffect& e : effects) body += effect_list(e);
    std::string out = "RIFF";
    put32(out, riff_size_zero ? 0 : static_cast<uint32_t>(body.size()));
    return out + body;
}

}  // namespace feel::test
