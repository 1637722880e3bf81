// feel::import — sensations from other formats (docs/import.md).
//
// Three formats become feel/1 sensations:
//   - DirectInput effect files (.ffe, the RIFF "FORC" files of the DirectX SDKs' Force
//     Editor): every DIEFFECT type they hold, with envelopes, directions, triggers, delays;
//   - Apple AHAP (.ahap JSON): transient and continuous haptic events become waves with
//     envelopes on one axis;
//   - WAV (mono or the first channel): the amplitude envelope becomes a force profile.
//
// Every importer reads bytes already in memory (at most kMaxImportBytes), never allocates
// more than a bounded multiple of them, and throws ImportError naming what is wrong and the
// allowed range ("effect 2 \"Sine1\": DIPERIODIC.dwPhase = 36000 is out of range (allowed
// 0..35999)"). The result always passes the format's validator: a sensation that could not
// be written is never returned. What a format holds that feel cannot express is either an
// error (when ignoring it would change the feel) or a note in ImportResult::notes (when the
// source itself marks it as optional or non-haptic, e.g. AHAP audio events).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "feel/axis.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::import {

class ImportError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

enum class SourceFormat : uint8_t { ffe, ahap, wav };

// The largest file any importer reads (16 MiB): the largest real .ffe files are a few KiB,
// AHAP files tens of KiB; a WAV of 65 s of 48 kHz stereo 32-bit float is 25 MB, so long
// WAVs are better trimmed first.
inline constexpr size_t kMaxImportBytes = 16u << 20;

// WAV: the default force-profile sample period, 10 ms (100 Hz: the envelope, not the
// carrier), and its allowed range.
inline constexpr int64_t kDefaultWavSamplePeriodUs = 10'000;
inline constexpr int64_t kMinWavSamplePeriodUs = 1'000;
inline constexpr int64_t kMaxWavSamplePeriodUs = 1'000'000;

struct ImportOptions {
    // The sensation's name; empty: derived from the file name (import_sensation's
    // `file_name`), else "imported".
    std::string name;
    // AHAP and WAV: the axis the waves or the profile drive (their force pushes toward
    // +axis). DirectInput files name their own axes and refuse this option.
    std::optional<Axis> axis;
    // WAV: the force profile's sample period, kMinWavSamplePeriodUs..kMaxWavSamplePeriodUs.
    // Other formats refuse it.
    std::optional<int64_t> sample_period_us;
};

struct ImportResult {
    format::Sensation sensation;
    // What the source held that the sensation does not carry, one sentence each.
    std::vector<std::string> notes;
};

// The format of a file from its first bytes ("RIFF....FORC", "RIFF....WAVE", or JSON with
// a "Pattern"), falling back to its extension (.ffe, .ahap, .wav); nullopt if neither tells.
[[nodiscard]] std::optional<SourceFormat> detect_format(std::string_view bytes, std::string_view file_name);
[[nodiscard]] std::string_view format_name(SourceFormat f) noexcept;

[[nodiscard]] ImportResult import_ffe(std::string_view bytes, const ImportOptions& options);
[[nodiscard]] ImportResult import_ahap(std::string_view text, const ImportOptions& options);
[[nodiscard]] ImportResult import_wav(std::string_view bytes, const ImportOptions& options);

// Detects the format (detect_format) and imports; `file_name` also names the sensation
// when options.name is empty. Throws ImportError for an unknown format or a file larger
// than kMaxImportBytes.
[[nodiscard]] ImportResult import_sensation(std::string_view bytes, std::string_view file_name,
                                            const ImportOptions& options);

// A valid sensation name (format::is_valid_sensation_name) from a file name: its stem, each
// character outside a-z A-Z 0-9 _ - . replaced by '_', cut to 64; "imported" if empty.
[[nodiscard]] std::string sensation_name_from_file(std::string_view file_name);

}  // namespace feel::import
