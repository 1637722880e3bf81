// WAV → a force profile: the sound's amplitude envelope, pushed along one axis.
//
// libsndfile decodes the file (every WAV encoding it knows: PCM 8..32-bit, float, µ-law,
// A-law, ADPCM...) from memory through its virtual I/O, normalized to ±1. The first
// channel is the signal. The envelope sample k, for the window [k·P, (k+1)·P) of the
// chosen sample period P, is the largest |x| in the window: for a carrier whose period is
// shorter than P, the carrier's peaks inside the window trace the envelope, so a sound at
// amplitude A becomes the force 10000·A (pushing toward +axis). A carrier slower than P
// shows as its own waveform's magnitude, which is what a hand would feel of it anyway.
// Frames are read in blocks of 4096, so memory stays at the profile plus one block.
//
// Limits: the profile holds 1..65535 samples and lasts at most 65 s (§6.3, §6.6.d); a
// file that needs more is refused with the figures and the sample period that would fit.
#include <sndfile.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "feel/import/import.hpp"
#include "import_support.hpp"

namespace feel::import {
namespace {

using detail::fail;

// libsndfile's virtual I/O over bytes in memory.
struct MemoryFile {
    std::string_view bytes;
    sf_count_t pos = 0;
};

sf_count_t vio_length(void* user) { return static_cast<sf_count_t>(static_cast<MemoryFile*>(user)->bytes.size()); }
sf_count_t vio_seek(sf_count_t offset, int whence, void* user) {
    auto* f = static_cast<MemoryFile*>(user);
    const auto size = static_cast<sf_count_t>(f->bytes.size());
    sf_count_t to = offset;
    if (whence == SEEK_CUR) to = f->pos + offset;
    else if (whence == SEEK_END) to = size + offset;
    f->pos = std::clamp<sf_count_t>(to, 0, size);  // libsndfile's own seeks; not user data
    return f->pos;
}
sf_count_t vio_read(void* ptr, sf_count_t count, void* user) {
    auto* f = static_cast<MemoryFile*>(user);
    const sf_count_t n = std::min(count, static_cast<sf_count_t>(f->bytes.size()) - f->pos);
    if (n <= 0) return 0;
    std::memcpy(ptr, f->bytes.data() + f->pos, static_cast<size_t>(n));
    f->pos += n;
    return n;
}
sf_count_t vio_write(const void*, sf_count_t, void*) { return 0; }
sf_count_t vio_tell(void* user) { return static_cast<MemoryFile*>(user)->pos; }

struct SndFile {
    SNDFILE* handle = nullptr;
    ~SndFile() {
        if (handle) sf_close(handle);
    }
};

}  // namespace

ImportResult import_wav(std::string_view bytes, const ImportOptions& options) {
    if (bytes.size() > kMaxImportBytes) {
        fail("the file has " + std::to_string(bytes.size()) + " bytes (allowed at most " +
             std::to_string(kMaxImportBytes) + ")");
    }
    const int64_t period_us = options.sample_period_us.value_or(kDefaultWavSamplePeriodUs);
    detail::check_range("--sample-period", "the sample period (µs)", period_us,
                        Range{kMinWavSamplePeriodUs, kMaxWavSamplePeriodUs});
    const Axis axis = options.axis.value_or(Axis::x);

    MemoryFile memory{bytes};
    SF_VIRTUAL_IO io{vio_length, vio_seek, vio_read, vio_write, vio_tell};
    SF_INFO info{};
    SndFile file;
    file.handle = sf_open_virtual(&io, SFM_READ, &info, &memory);
    if (!file.handle) fail(std::string("not a WAV file libsndfile can read: ") + sf_strerror(nullptr));
    if ((info.format & SF_FORMAT_TYPEMASK) != SF_FORMAT_WAV && (info.format & SF_FORMAT_TYPEMASK) != SF_FORMAT_WAVEX) {
        fail("libsndfile reads this file, but it is not a WAV file (RIFF WAVE)");
    }
    if (info.channels < 1 || info.samplerate < 1) {
        fail("the WAV header gives " + std::to_string(info.channels) + " channels at " +
             std::to_string(info.samplerate) + " Hz (allowed at least 1 channel at 1 Hz or more)");
    }
    if (info.frames <= 0) fail("the WAV file holds no audio frames");

    const double seconds = static_cast<double>(info.frames) / info.samplerate;
    const auto samples_needed = static_cast<int64_t>(std::ceil(seconds * 1e6 / static_cast<double>(period_us)));
    if (samples_needed > range::kSampleCount.max || samples_needed * period_us > kMaxTimeUs) {
        const int64_t fit = std::max<int64_t>(
            static_cast<int64_t>(std::ceil(seconds * 1e6 / static_cast<double>(range::kSampleCount.max))), 1);
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "the sound lasts %.3f s: at a sample period of %lld µs that is %lld samples over %.3f s "
                      "(allowed 1..65535 samples, at most 65 s)%s",
                      seconds, static_cast<long long>(period_us), static_cast<long long>(samples_needed),
                      static_cast<double>(samples_needed * period_us) * 1e-6,
                      seconds > 65.0 ? "; trim the sound to 65 s" : "");
        std::string msg = buf;
        if (seconds <= 65.0) msg += "; a --sample-period of at least " + std::to_string(fit) + " µs fits";
        fail(msg);
    }

    // Frames per window, fractional: window k covers frames [k·w, (k+1)·w).
    const double frames_per_window = static_cast<double>(info.samplerate) * static_cast<double>(period_us) * 1e-6;
    std::vector<double> peaks(static_cast<size_t>(samples_needed), 0.0);
    constexpr sf_count_t kBlock = 4096;
    std::vector<double> block(static_cast<size_t>(kBlock) * static_cast<size_t>(info.channels));
    sf_count_t frame = 0;
    while (frame < info.frames) {
        const sf_count_t got = sf_readf_double(file.handle, block.data(), kBlock);
        if (got <= 0) break;
        for (sf_count_t i = 0; i < got; ++i, ++frame) {
            const double x = block[static_cast<size_t>(i) * static_cast<size_t>(info.channels)];
            if (!std::isfinite(x)) fail("frame " + std::to_string(frame) + " is not a finite number");
            const auto k = std::min(static_cast<size_t>(static_cast<double>(frame) / frames_per_window), peaks.size() - 1);
            peaks[k] = std::max(peaks[k], std::abs(x));
        }
    }
    if (frame < info.frames) {
        fail("truncated: the WAV header announces " + std::to_string(info.frames) + " frames, the data holds " +
             std::to_string(frame));
    }

    ImportResult result;
    format::Sensation& s = result.sensation;
    s.name = detail::sensation_name(options, "imported");
    format::EffectSpec spec;
    EffectParams& p = spec.params;
    p.type = EffectType::force_profile;
    p.axis_count = 1;
    p.axes[0] = axis;
    p.custom.channels = 1;
    p.custom.sample_period_us = period_us;
    p.custom.sample_count = static_cast<int32_t>(peaks.size());
    p.duration_us = static_cast<int64_t>(peaks.size()) * period_us;
    bool clipped = false;
    for (double peak : peaks) {
        // Float WAVs may exceed full scale; the force never exceeds the device maximum.
        if (peak > 1.0) clipped = true;
        spec.samples.push_back(static_cast<int16_t>(std::lround(std::min(peak, 1.0) * kFullScale)));
    }
    if (clipped) result.notes.push_back("the sound exceeds full scale (|x| > 1 in a float WAV); those windows are 10000");
    if (info.channels > 1) {
        result.notes.push_back("the file has " + std::to_string(info.channels) + " channels; the first is used");
    }
    s.effects.push_back(std::move(spec));
    char desc[160];
    std::snprintf(desc, sizeof desc, "Imported from a WAV file (%d Hz, %.3f s): its amplitude envelope on %s",
                  info.samplerate, seconds, std::string(axis_name(axis)).c_str());
    s.description = desc;
    detail::check_sensation(s, "sensation \"" + s.name + "\"");
    return result;
}

}  // namespace feel::import
