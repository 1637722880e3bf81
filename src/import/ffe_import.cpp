// DirectInput effect files (.ffe) → feel/1 sensations.
//
// The format. Microsoft never documented it; IDirectInputDevice8::WriteEffectToFile and the
// DirectX SDK's Force Editor wrote it and EnumEffectsInFile read it. The layout below is
// what the DirectX 7 SDK's sample files show (the 110 files of samples/Multimedia/DInput/
// media, one of which is tests/import/data/click1.ffe), read against the public DIEFFECT,
// DIENVELOPE, DICONSTANTFORCE, DIRAMPFORCE, DIPERIODIC, DICONDITION and DICUSTOMFORCE
// structures of dinput.h. All integers are little-endian 32-bit.
//
//   "RIFF" u32 size "FORC"     size 0 (as Force Editor leaves it) means "to the end"
//   16-byte GUID               the file format's; read, not interpreted
//   then, per effect:
//   "LIST" u32 size "efct"
//     char name[64]            the friendly name, NUL-terminated
//     DIEFFECT                 dwSize (52: DirectX 5, or 56: with dwStartDelay) bytes; its
//                              pointer members only say whether the part is present
//     GUID                     the effect type (GUID_ConstantForce ... GUID_CustomForce)
//     u32                      the iteration count passed to Start (every known file: 1)
//     "data" cAxes × u32       rgdwAxes: DIJOFS_X.. offsets        (if rgdwAxes != 0)
//     "data" cAxes × i32       rglDirection                        (if rglDirection != 0)
//     "data" DIENVELOPE        20 bytes                            (if lpEnvelope != 0)
//     "data" type-specific     cbTypeSpecificParams bytes          (if it is not 0)
//     "data" cSamples × i32    custom forces only: the samples rglForceData points to
//
// The custom force's sample chunk is this reader's assumption: no public file has one
// (Force Editor cannot make custom forces), so the test files come from our own writer.
//
// The mapping, field by field, is in docs/import.md; its two subtle points are here. First,
// DirectInput's y axis grows toward the user and feel's +y is forward (docs/conventions.md),
// so a cartesian or spherical direction's y component changes sign, and a per-axis
// condition on y has its offset negated and its positive and negative sides swapped. Polar
// angles need no change: both are compass angles of where the force comes from, 0 north,
// clockwise. Second, a file with several effects is what Force Editor calls a composition:
// the effects play together, each after its own start delay, which is a compound sensation.
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "feel/import/import.hpp"
#include "import_support.hpp"

namespace feel::import {
namespace {

using detail::check_range;
using detail::fail;

constexpr uint32_t kInfinite = 0xFFFFFFFFu;  // INFINITE, DIEB_NOTRIGGER
constexpr uint32_t kDieffObjectIds = 0x01, kDieffObjectOffsets = 0x02;
constexpr uint32_t kDieffCartesian = 0x10, kDieffPolar = 0x20, kDieffSpherical = 0x40;
constexpr uint32_t kDijofsButton0 = 48;  // DIJOFS_BUTTON(n) = 48 + n
constexpr size_t kNameBytes = 64;
constexpr size_t kDiConditionBytes = 24;

// The GUIDs of DirectInput's predefined effects share all but their first byte:
// {13541C2x-8E33-11D0-9AD0-00A0C9A06E35}.
constexpr std::array<uint8_t, 15> kPredefinedGuidTail = {0x1C, 0x54, 0x13, 0x33, 0x8E, 0xD0, 0x11, 0x9A,
                                                         0xD0, 0x00, 0xA0, 0xC9, 0xA0, 0x6E, 0x35};
enum class DiType : uint8_t { constant, ramp, square, sine, triangle, saw_up, saw_down,
                              spring, damper, inertia, friction, custom };
constexpr std::array<const char*, 12> kDiTypeNames = {
    "GUID_ConstantForce", "GUID_RampForce", "GUID_Square", "GUID_Sine", "GUID_Triangle", "GUID_SawtoothUp",
    "GUID_SawtoothDown", "GUID_Spring", "GUID_Damper", "GUID_Inertia", "GUID_Friction", "GUID_CustomForce"};

class Reader {
public:
    Reader(std::string_view bytes, size_t begin, size_t end, std::string where)
        : bytes_(bytes), pos_(begin), end_(end), where_(std::move(where)) {}

    [[nodiscard]] size_t pos() const noexcept { return pos_; }
    // A chunk that ends before where it begins has nothing left (never a wrapped size_t).
    [[nodiscard]] size_t left() const noexcept { return pos_ < end_ ? end_ - pos_ : 0; }
    [[nodiscard]] const std::string& where() const noexcept { return where_; }

    void need(size_t n, std::string_view what) const {
        if (n <= left()) return;
        fail(where_ + ": truncated: " + std::string(what) + " needs " + std::to_string(n) + " bytes at offset " +
             std::to_string(pos_) + ", only " + std::to_string(left()) + " are left in its chunk");
    }
    std::string_view take(size_t n, std::string_view what) {
        need(n, what);
        const std::string_view s = bytes_.substr(pos_, n);
        pos_ += n;
        return s;
    }
    uint32_t u32(std::string_view what) {
        const std::string_view s = take(4, what);
        return static_cast<uint32_t>(static_cast<uint8_t>(s[0])) | static_cast<uint32_t>(static_cast<uint8_t>(s[1])) << 8 |
               static_cast<uint32_t>(static_cast<uint8_t>(s[2])) << 16 |
               static_cast<uint32_t>(static_cast<uint8_t>(s[3])) << 24;
    }
    int32_t i32(std::string_view what) { return static_cast<int32_t>(u32(what)); }

    // A "data" chunk of exactly `size` bytes: returns a reader over its body.
    Reader data_chunk(size_t size, std::string_view what) {
        const std::string_view id = take(4, std::string(what) + "'s chunk id");
        if (id != "data") {
            fail(where_ + ": expected the \"data\" chunk of " + std::string(what) + " at offset " +
                 std::to_string(pos_ - 4) + ", found \"" + printable(id) + "\"");
        }
        const uint32_t got = u32(std::string(what) + "'s chunk size");
        if (got != size) {
            fail(where_ + ": the \"data\" chunk of " + std::string(what) + " has " + std::to_string(got) +
                 " bytes; expected " + std::to_string(size));
        }
        need(size, what);
        Reader body(bytes_, pos_, pos_ + size, where_);
        pos_ += size;
        return body;
    }

    static std::string printable(std::string_view s) {
        std::string out;
        for (char c : s) out += (c >= 0x20 && c < 0x7F && c != '"') ? c : '?';
        return out;
    }

private:
    std::string_view bytes_;
    size_t pos_;
    size_t end_;
    std::string where_;
};

struct DiEffect {
    uint32_t size = 0, flags = 0, duration = 0, sample_period = 0, gain = 0, trigger_button = 0,
             trigger_repeat = 0, axes = 0, rgdw_axes = 0, rgl_direction = 0, envelope = 0, cb_type_specific = 0,
             type_specific = 0, start_delay = 0;
};

DiEffect read_dieffect(Reader& r) {
    DiEffect e;
    e.size = r.u32("DIEFFECT.dwSize");
    if (e.size != 52 && e.size != 56) {
        fail(r.where() + ": DIEFFECT.dwSize = " + std::to_string(e.size) +
             " is not a DIEFFECT size (allowed 52, DirectX 5, or 56, DirectX 6 and later)");
    }
    e.flags = r.u32("DIEFFECT.dwFlags");
    e.duration = r.u32("DIEFFECT.dwDuration");
    e.sample_period = r.u32("DIEFFECT.dwSamplePeriod");
    e.gain = r.u32("DIEFFECT.dwGain");
    e.trigger_button = r.u32("DIEFFECT.dwTriggerButton");
    e.trigger_repeat = r.u32("DIEFFECT.dwTriggerRepeatInterval");
    e.axes = r.u32("DIEFFECT.cAxes");
    e.rgdw_axes = r.u32("DIEFFECT.rgdwAxes");
    e.rgl_direction = r.u32("DIEFFECT.rglDirection");
    e.envelope = r.u32("DIEFFECT.lpEnvelope");
    e.cb_type_specific = r.u32("DIEFFECT.cbTypeSpecificParams");
    e.type_specific = r.u32("DIEFFECT.lpvTypeSpecificParams");
    if (e.size == 56) e.start_delay = r.u32("DIEFFECT.dwStartDelay");
    return e;
}

DiType read_type(Reader& r) {
    const std::string_view g = r.take(16, "the effect GUID");
    const auto first = static_cast<uint8_t>(g[0]);
    const bool predefined = std::memcmp(g.data() + 1, kPredefinedGuidTail.data(), kPredefinedGuidTail.size()) == 0;
    if (!predefined || first < 0x20 || first > 0x2B) {
        static constexpr char kHex[] = "0123456789ABCDEF";
        // Data1 (4 bytes LE), Data2, Data3 (2 bytes LE), then 8 bytes in order.
        auto hex = [&](size_t i) { const auto b = static_cast<uint8_t>(g[i]); return std::string{kHex[b >> 4], kHex[b & 15]}; };
        const std::string text = "{" + hex(3) + hex(2) + hex(1) + hex(0) + "-" + hex(5) + hex(4) + "-" + hex(7) +
                                 hex(6) + "-" + hex(8) + hex(9) + "-" + hex(10) + hex(11) + hex(12) + hex(13) +
                                 hex(14) + hex(15) + "}";
        fail(r.where() + ": unknown effect GUID " + text +
             ": feel imports DirectInput's predefined effects {13541C20..2B-8E33-11D0-9AD0-00A0C9A06E35} "
             "(ConstantForce, RampForce, Square, Sine, Triangle, SawtoothUp, SawtoothDown, Spring, Damper, "
             "Inertia, Friction, CustomForce); device-specific effects have no meaning on another device");
    }
    return static_cast<DiType>(first - 0x20);
}

EffectType feel_type(DiType t) {
    switch (t) {
        case DiType::constant: return EffectType::constant;
        case DiType::ramp: return EffectType::ramp;
        case DiType::square: return EffectType::square;
        case DiType::sine: return EffectType::sine;
        case DiType::triangle: return EffectType::triangle;
        case DiType::saw_up: return EffectType::saw_up;
        case DiType::saw_down: return EffectType::saw_down;
        case DiType::spring: return EffectType::spring;
        case DiType::damper: return EffectType::damper;
        case DiType::inertia: return EffectType::inertia;
        case DiType::friction: return EffectType::friction;
        case DiType::custom: return EffectType::force_profile;
    }
    return EffectType::constant;
}

Axis axis_of_offset(const std::string& where, uint32_t offset) {
    switch (offset) {
        case 0: return Axis::x;
        case 4: return Axis::y;
        case 8: return Axis::z;
        case 12: return Axis::rx;
        case 16: return Axis::ry;
        case 20: return Axis::rz;
        default: break;
    }
    fail(where + ": rgdwAxes holds the object offset " + std::to_string(offset) +
         ": feel's axes are DIJOFS_X, _Y, _Z, _RX, _RY, _RZ (offsets 0, 4, 8, 12, 16, 20)");
}

// A cartesian component in feel's frame: DirectInput's y grows toward the user.
double feel_sign(Axis a) { return a == Axis::y ? -1.0 : 1.0; }

// The direction, in feel's conventions, of an effect on `axes` (docs/import.md "Directions").
Direction map_direction(const std::string& where, uint32_t flags, const std::vector<Axis>& axes,
                        const std::vector<int32_t>& dir) {
    const int n = static_cast<int>(axes.size());
    Direction d;
    std::vector<double> from(axes.size(), 0.0);  // where the force comes from, feel's frame
    if (flags & kDieffPolar) {
        if (n != 2 || axes[0] != Axis::x || axes[1] != Axis::y) {
            fail(where + ": a polar direction (DIEFF_POLAR) needs the axes DIJOFS_X, DIJOFS_Y in that order");
        }
        check_range(where, "rglDirection[0] (polar angle, hundredths of a degree)", dir[0], range::kAngle);
        if (dir[1] != 0) {
            fail(where + ": rglDirection[1] = " + std::to_string(dir[1]) +
                 ": a polar direction's second value must be 0 (DirectInput's rule)");
        }
        d.kind = DirectionKind::polar;
        d.value[0] = dir[0];
        return d;
    }
    if (flags & kDieffSpherical) {
        // n - 1 angles: θ from +x toward +y(DirectInput), then φ toward +z.
        if (n < 2 || n > 3) {
            fail(where + ": a spherical direction (DIEFF_SPHERICAL) on " + std::to_string(n) +
                 " axes: feel maps 2 or 3 axes");
        }
        for (int i = 0; i + 1 < n; ++i) {
            check_range(where, "rglDirection[" + std::to_string(i) + "] (spherical angle, hundredths of a degree)",
                        dir[static_cast<size_t>(i)], range::kAngle);
        }
        if (dir[static_cast<size_t>(n - 1)] != 0) {
            fail(where + ": rglDirection[" + std::to_string(n - 1) + "] = " + std::to_string(dir[static_cast<size_t>(n - 1)]) +
                 ": a spherical direction's last value must be 0 (DirectInput's rule)");
        }
        const double theta = dir[0] * M_PI / 18000.0;
        const double phi = n == 3 ? dir[1] * M_PI / 18000.0 : 0.0;
        const double di[3] = {std::cos(theta) * std::cos(phi), std::sin(theta) * std::cos(phi), std::sin(phi)};
        for (int i = 0; i < n; ++i) from[static_cast<size_t>(i)] = di[i] * feel_sign(axes[static_cast<size_t>(i)]);
    } else if (flags & kDieffCartesian) {
        for (int i = 0; i < n; ++i) {
            from[static_cast<size_t>(i)] = dir[static_cast<size_t>(i)] * feel_sign(axes[static_cast<size_t>(i)]);
        }
    } else {
        fail(where + ": DIEFFECT.dwFlags = 0x" + [&] { char b[16]; std::snprintf(b, sizeof b, "%X", flags); return std::string(b); }() +
             " names no coordinate system (DIEFF_CARTESIAN 0x10, DIEFF_POLAR 0x20 or DIEFF_SPHERICAL 0x40)");
    }
    double largest = 0;
    for (double c : from) largest = std::max(largest, std::abs(c));
    if (largest == 0) {
        if (n == 1) return d;  // one axis, no direction: the value's own sign (docs/import.md)
        fail(where + ": rglDirection is the zero vector: a direction needs a non-zero component");
    }
    d.kind = DirectionKind::cartesian;
    for (int i = 0; i < n; ++i) {
        d.value[i] = static_cast<int32_t>(std::lround(from[static_cast<size_t>(i)] / largest * kFullScale));
    }
    return d;
}

ConditionBlock read_condition(Reader& r, const std::string& where, Axis axis, bool per_axis) {
    const std::string name = "DICONDITION";
    const int32_t offset = r.i32("DICONDITION.lOffset");
    const int32_t pos = r.i32("DICONDITION.lPositiveCoefficient");
    const int32_t neg = r.i32("DICONDITION.lNegativeCoefficient");
    const uint32_t pos_sat = r.u32("DICONDITION.dwPositiveSaturation");
    const uint32_t neg_sat = r.u32("DICONDITION.dwNegativeSaturation");
    const int32_t deadband = r.i32("DICONDITION.lDeadBand");
    check_range(where, "DICONDITION.lOffset", offset, range::kSignedLevel);
    check_range(where, "DICONDITION.lPositiveCoefficient", pos, range::kSignedLevel);
    check_range(where, "DICONDITION.lNegativeCoefficient", neg, range::kSignedLevel);
    check_range(where, "DICONDITION.dwPositiveSaturation", pos_sat, range::kLevel);
    check_range(where, "DICONDITION.dwNegativeSaturation", neg_sat, range::kLevel);
    check_range(where, "DICONDITION.lDeadBand", deadband, range::kLevel);
    ConditionBlock c;
    c.offset = offset;
    c.pos_coefficient = pos;
    c.neg_coefficient = neg;
    c.pos_saturation = static_cast<int32_t>(pos_sat);
    c.neg_saturation = static_cast<int32_t>(neg_sat);
    c.deadband = deadband;
    if (per_axis && axis == Axis::y) {  // DirectInput's +y is feel's -y: the sides swap
        c.offset = -offset;
        std::swap(c.pos_coefficient, c.neg_coefficient);
        std::swap(c.pos_saturation, c.neg_saturation);
    }
    return c;
}

void read_type_specific(Reader& r, DiType type, const DiEffect& di, const std::vector<Axis>& axes,
                        format::EffectSpec& spec, Reader& effect_reader, std::vector<std::string>& notes) {
    const std::string& where = r.where();
    EffectParams& p = spec.params;
    auto expect_size = [&](size_t want, const char* structure) {
        if (di.cb_type_specific != want) {
            fail(where + ": cbTypeSpecificParams = " + std::to_string(di.cb_type_specific) + " for " +
                 kDiTypeNames[static_cast<size_t>(type)] + ": " + structure + " has " + std::to_string(want) + " bytes");
        }
    };
    switch (type) {
        case DiType::constant: {
            expect_size(4, "DICONSTANTFORCE");
            const int32_t m = r.i32("DICONSTANTFORCE.lMagnitude");
            check_range(where, "DICONSTANTFORCE.lMagnitude", m, range::kSignedLevel);
            p.constant.magnitude = m;
            return;
        }
        case DiType::ramp: {
            expect_size(8, "DIRAMPFORCE");
            const int32_t start = r.i32("DIRAMPFORCE.lStart");
            const int32_t end = r.i32("DIRAMPFORCE.lEnd");
            check_range(where, "DIRAMPFORCE.lStart", start, range::kSignedLevel);
            check_range(where, "DIRAMPFORCE.lEnd", end, range::kSignedLevel);
            p.ramp = {start, end};
            return;
        }
        case DiType::square: case DiType::sine: case DiType::triangle: case DiType::saw_up: case DiType::saw_down: {
            expect_size(16, "DIPERIODIC");
            const uint32_t magnitude = r.u32("DIPERIODIC.dwMagnitude");
            const int32_t offset = r.i32("DIPERIODIC.lOffset");
            const uint32_t phase = r.u32("DIPERIODIC.dwPhase");
            const uint32_t period = r.u32("DIPERIODIC.dwPeriod");
            check_range(where, "DIPERIODIC.dwMagnitude", magnitude, range::kLevel);
            check_range(where, "DIPERIODIC.lOffset", offset, range::kSignedLevel);
            check_range(where, "DIPERIODIC.dwPhase", phase, range::kAngle);
            check_range(where, "DIPERIODIC.dwPeriod (µs)", period, range::kPeriodUs);
            p.periodic.magnitude = static_cast<int32_t>(magnitude);
            p.periodic.offset = offset;
            p.periodic.phase = static_cast<int32_t>(phase);
            p.periodic.period_us = period;
            return;
        }
        case DiType::spring: case DiType::damper: case DiType::inertia: case DiType::friction: {
            const size_t blocks = di.cb_type_specific / kDiConditionBytes;
            if (di.cb_type_specific % kDiConditionBytes != 0 || (blocks != 1 && blocks != axes.size())) {
                fail(where + ": cbTypeSpecificParams = " + std::to_string(di.cb_type_specific) +
                     " for a condition: allowed 24 (one DICONDITION along the direction) or 24 × cAxes = " +
                     std::to_string(24 * axes.size()) + " (one per axis)");
            }
            const bool per_axis = blocks == axes.size();
            if (!per_axis && p.direction.kind == DirectionKind::none) {
                fail(where + ": one DICONDITION on " + std::to_string(axes.size()) +
                     " axes acts along a direction, and the effect has none (rglDirection)");
            }
            for (size_t i = 0; i < blocks; ++i) {
                p.conditions[i] = read_condition(r, where, axes[i], per_axis);
                const ConditionBlock& c = p.conditions[i];
                if (c.pos_saturation == 0 && c.neg_saturation == 0 && (c.pos_coefficient != 0 || c.neg_coefficient != 0)) {
                    // Force Editor writes 0; drivers without saturation support ignore it, feel does not.
                    notes.push_back(where + ": DICONDITION[" + std::to_string(i) +
                                    "] has both saturations 0, so the condition gives no force in feel (DirectInput "
                                    "drivers without saturation support ignore them); raise pos_saturation and "
                                    "neg_saturation to feel it");
                }
            }
            // One block on several axes acts along the direction (a directed condition); one
            // block per axis acts on each axis, and DirectInput ignores the direction then.
            if (per_axis) p.direction = Direction{};
            return;
        }
        case DiType::custom: {
            expect_size(16, "DICUSTOMFORCE");
            const uint32_t channels = r.u32("DICUSTOMFORCE.cChannels");
            uint32_t sample_period = r.u32("DICUSTOMFORCE.dwSamplePeriod");
            const uint32_t samples = r.u32("DICUSTOMFORCE.cSamples");
            (void)r.u32("DICUSTOMFORCE.rglForceData");
            check_range(where, "DICUSTOMFORCE.cChannels", channels, range::kChannels);
            check_range(where, "DICUSTOMFORCE.cSamples", samples, range::kSampleCount);
            if (samples % channels != 0) {
                fail(where + ": DICUSTOMFORCE.cSamples = " + std::to_string(samples) +
                     " is not a multiple of cChannels = " + std::to_string(channels));
            }
            if (sample_period == 0) sample_period = di.sample_period;  // 0: the effect's own
            check_range(where, "DICUSTOMFORCE.dwSamplePeriod (µs; 0 takes DIEFFECT.dwSamplePeriod)", sample_period,
                        range::kPeriodUs);
            p.custom.channels = static_cast<int32_t>(channels);
            p.custom.sample_period_us = sample_period;
            p.custom.sample_count = static_cast<int32_t>(samples);
            Reader data = effect_reader.data_chunk(size_t{samples} * 4, "the custom force's samples (cSamples × 4)");
            spec.samples.reserve(samples);
            for (uint32_t i = 0; i < samples; ++i) {
                const int32_t v = data.i32("a custom force sample");
                check_range(where, "custom force sample [" + std::to_string(i) + "]", v, range::kSample);
                spec.samples.push_back(static_cast<int16_t>(v));
            }
            return;
        }
    }
}

struct NamedEffect {
    std::string name;
    format::EffectSpec spec;
};

NamedEffect read_effect(std::string_view bytes, size_t begin, size_t end, size_t index,
                        std::vector<std::string>& notes) {
    Reader r(bytes, begin, end, "effect " + std::to_string(index));
    const std::string_view raw_name = r.take(kNameBytes, "the effect name (64 bytes)");
    const size_t nul = raw_name.find('\0');
    if (nul == std::string_view::npos) fail(r.where() + ": the effect name is not NUL-terminated within its 64 bytes");
    NamedEffect out;
    out.name = Reader::printable(raw_name.substr(0, nul));
    Reader n(bytes, r.pos(), end, r.where() + " \"" + out.name + "\"");
    const std::string& where = n.where();

    const DiEffect di = read_dieffect(n);
    const DiType type = read_type(n);
    const uint32_t iterations = n.u32("the iteration count");

    EffectParams& p = out.spec.params;
    p.type = feel_type(type);
    if ((di.flags & kDieffObjectIds) || !(di.flags & kDieffObjectOffsets)) {
        fail(where + ": the axes are device object IDs (DIEFF_OBJECTIDS): feel maps axes given as "
                     "DIEFF_OBJECTOFFSETS (DIJOFS_X..DIJOFS_RZ) only");
    }
    if (di.duration == kInfinite) {
        p.duration_us = kInfiniteUs;
    } else {
        check_range(where, "DIEFFECT.dwDuration (µs; INFINITE = 0xFFFFFFFF)", di.duration, range::kDurationUs);
        p.duration_us = di.duration;
    }
    check_range(where, "DIEFFECT.dwGain", di.gain, range::kGain);
    p.gain = static_cast<int32_t>(di.gain);
    if (di.trigger_button != kInfinite) {
        if (di.trigger_button < kDijofsButton0 || di.trigger_button >= kDijofsButton0 + 32) {
            fail(where + ": DIEFFECT.dwTriggerButton = " + std::to_string(di.trigger_button) +
                 " is not a button: allowed DIJOFS_BUTTON0..31 (48..79) or DIEB_NOTRIGGER (0xFFFFFFFF)");
        }
        p.trigger = {TriggerKind::button, static_cast<int32_t>(di.trigger_button - kDijofsButton0 + 1)};
        if (di.trigger_repeat != kInfinite && di.trigger_repeat != 0) {
            check_range(where, "DIEFFECT.dwTriggerRepeatInterval (µs; INFINITE or 0 = no repeat)", di.trigger_repeat,
                        Range{1, kMaxTimeUs});
            p.trigger_repeat_interval_us = di.trigger_repeat;
        }
    }
    if (di.size == 56) {
        check_range(where, "DIEFFECT.dwStartDelay (µs)", di.start_delay, range::kDelayUs);
        p.start_delay_us = di.start_delay;
    }
    if (iterations == kInfinite) {
        p.iterations = kInfiniteIterations;
    } else {
        check_range(where, "the iteration count (INFINITE = 0xFFFFFFFF)", iterations, range::kIterations);
        p.iterations = static_cast<int32_t>(iterations);
    }
    if (di.sample_period != 0 && type != DiType::custom) {
        notes.push_back(where + ": DIEFFECT.dwSamplePeriod = " + std::to_string(di.sample_period) +
                        " µs is not mapped: feel plays every effect at its device's loop rate");
    }

    check_range(where, "DIEFFECT.cAxes", di.axes, range::kAxisCount);
    std::vector<Axis> axes;
    if (di.rgdw_axes == 0) fail(where + ": DIEFFECT.rgdwAxes is absent: an effect names its axes");
    {
        Reader a = n.data_chunk(size_t{di.axes} * 4, "rgdwAxes (cAxes × 4)");
        for (uint32_t i = 0; i < di.axes; ++i) {
            const Axis axis = axis_of_offset(where, a.u32("an axis offset"));
            for (Axis seen : axes) {
                if (seen == axis) fail(where + ": rgdwAxes names the axis " + std::string(axis_name(axis)) + " twice");
            }
            axes.push_back(axis);
        }
    }
    p.axis_count = static_cast<int32_t>(axes.size());
    for (size_t i = 0; i < axes.size(); ++i) p.axes[i] = axes[i];
    if (di.rgl_direction != 0) {
        Reader d = n.data_chunk(size_t{di.axes} * 4, "rglDirection (cAxes × 4)");
        std::vector<int32_t> dir;
        for (uint32_t i = 0; i < di.axes; ++i) dir.push_back(d.i32("a direction value"));
        p.direction = map_direction(where, di.flags, axes, dir);
    }
    if (di.envelope != 0) {
        Reader e = n.data_chunk(20, "DIENVELOPE");
        const uint32_t size = e.u32("DIENVELOPE.dwSize");
        if (size != 20) fail(where + ": DIENVELOPE.dwSize = " + std::to_string(size) + " (allowed 20)");
        const uint32_t attack_level = e.u32("DIENVELOPE.dwAttackLevel");
        const uint32_t attack_time = e.u32("DIENVELOPE.dwAttackTime");
        const uint32_t fade_level = e.u32("DIENVELOPE.dwFadeLevel");
        const uint32_t fade_time = e.u32("DIENVELOPE.dwFadeTime");
        check_range(where, "DIENVELOPE.dwAttackLevel", attack_level, range::kLevel);
        check_range(where, "DIENVELOPE.dwAttackTime (µs)", attack_time, range::kDelayUs);
        check_range(where, "DIENVELOPE.dwFadeLevel", fade_level, range::kLevel);
        check_range(where, "DIENVELOPE.dwFadeTime (µs)", fade_time, range::kDelayUs);
        if (!supports_envelope(p.type)) {
            fail(where + ": " + kDiTypeNames[static_cast<size_t>(type)] +
                 " has an envelope (lpEnvelope): conditions take none (§6.4)");
        }
        p.has_envelope = true;
        p.envelope = {static_cast<int32_t>(attack_level), attack_time, static_cast<int32_t>(fade_level), fade_time};
    }
    if (di.cb_type_specific != 0) {
        Reader t = n.data_chunk(di.cb_type_specific, "the type-specific parameters");
        read_type_specific(t, type, di, axes, out.spec, n, notes);
    } else {
        fail(where + ": cbTypeSpecificParams = 0: " + kDiTypeNames[static_cast<size_t>(type)] +
             " needs its type-specific structure");
    }
    if (n.left() != 0) {
        fail(where + ": " + std::to_string(n.left()) + " bytes follow the effect's last chunk inside its LIST");
    }
    return out;
}

}  // namespace

ImportResult import_ffe(std::string_view bytes, const ImportOptions& options) {
    if (options.axis) fail("--axis does not apply to a DirectInput effect file: its effects name their own axes");
    if (options.sample_period_us) fail("--sample-period applies to WAV files only");
    if (bytes.size() > kMaxImportBytes) {
        fail("the file has " + std::to_string(bytes.size()) + " bytes (allowed at most " +
             std::to_string(kMaxImportBytes) + ")");
    }
    Reader head(bytes, 0, bytes.size(), "the RIFF header");
    if (head.take(4, "the RIFF id") != "RIFF") fail("not a RIFF file: it does not begin with \"RIFF\"");
    const uint32_t riff_size = head.u32("the RIFF size");
    if (head.take(4, "the RIFF form type") != "FORC") {
        fail("a RIFF file but not a DirectInput effect file: its form type is not \"FORC\"");
    }
    // Force Editor leaves the RIFF size 0; then the file runs to its end.
    size_t end = bytes.size();
    if (riff_size != 0) {
        if (riff_size < 4 + 16) {  // the form type and the file's GUID at least
            fail("the RIFF header says " + std::to_string(riff_size) +
                 " bytes follow it (allowed 0, meaning to the end of the file, or 20.." +
                 std::to_string(bytes.size() - 8) + ": the form type and the file's GUID at least)");
        }
        if (riff_size > bytes.size() - 8) {
            fail("truncated: the RIFF header says " + std::to_string(riff_size) + " bytes follow it, the file has " +
                 std::to_string(bytes.size() - 8));
        }
        end = 8 + size_t{riff_size};
    }
    Reader r(bytes, head.pos(), end, "the RIFF FORC file");
    (void)r.take(16, "the file's GUID");

    ImportResult result;
    std::vector<NamedEffect> effects;
    while (r.left() > 0) {
        const std::string_view id = r.take(4, "a chunk id");
        const uint32_t size = r.u32("a chunk size");
        r.need(size, "the \"" + Reader::printable(id) + "\" chunk");
        const size_t body = r.pos();
        if (id == "LIST" && size >= 4 && bytes.substr(body, 4) == "efct") {
            if (effects.size() >= format::kMaxFileEffects) {
                fail("the file holds more than " + std::to_string(format::kMaxFileEffects) +
                     " effects (allowed at most " + std::to_string(format::kMaxFileEffects) + ")");
            }
            effects.push_back(read_effect(bytes, body + 4, body + size, effects.size() + 1, result.notes));
        } else {
            result.notes.push_back("a \"" + Reader::printable(id) + "\" chunk of " + std::to_string(size) +
                                   " bytes is not an effect and was skipped");
        }
        (void)r.take(size, "the chunk body");
        if (size % 2 == 1 && r.left() > 0) (void)r.take(1, "the chunk's pad byte");  // RIFF pads to even sizes
    }
    if (effects.empty()) fail("the file holds no effect (no LIST \"efct\" chunk)");

    format::Sensation& s = result.sensation;
    s.name = detail::sensation_name(options, effects.size() == 1 ? sensation_name_from_file(effects[0].name) : "imported");
    s.compound = effects.size() > 1;
    std::string names;
    for (NamedEffect& e : effects) {
        if (!names.empty()) names += ", ";
        names += e.name;
        s.effects.push_back(std::move(e.spec));
    }
    s.description = "Imported from a DirectInput effect file: " + names;
    detail::check_sensation(s, "sensation \"" + s.name + "\"");
    return result;
}

}  // namespace feel::import
