// WAV: a known amplitude-modulated sine, written with libsndfile, imports to its known
// envelope.
//
// x(t) = e(t)·sin(2π·200 Hz·t), e(t) = 0.5 + 0.4·sin(2π·2 Hz·t), 48 kHz, 16-bit PCM. The
// profile's sample k is the largest |x| in its 10 ms window, which is e at one of the
// carrier's peaks (every 2.5 ms) in the window. So it lies within
//   max e over the window  −  |e'|max · 1.25 ms  −  the 16-bit step  −  the carrier's
//   sampling (peaks fall between 48 kHz samples: 1 − cos(π·200/48000) ≈ 9e-5)
// and max e over the window: |e'|max = 0.4·2π·2 = 5.03/s gives 0.0063, so a tolerance of
// 0.0075 of full scale (75 units) covers it with room for rounding.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <cmath>
#include <string>
#include <vector>

#include "feel/import/import.hpp"

namespace feel::import {
namespace {

struct Buffer {
    std::string bytes;
    sf_count_t pos = 0;
};
sf_count_t len(void* u) { return static_cast<sf_count_t>(static_cast<Buffer*>(u)->bytes.size()); }
sf_count_t seek(sf_count_t off, int whence, void* u) {
    auto* b = static_cast<Buffer*>(u);
    b->pos = whence == SEEK_SET ? off : whence == SEEK_CUR ? b->pos + off : static_cast<sf_count_t>(b->bytes.size()) + off;
    return b->pos;
}
sf_count_t rd(void*, sf_count_t, void*) { return 0; }
sf_count_t wr(const void* p, sf_count_t n, void* u) {
    auto* b = static_cast<Buffer*>(u);
    const auto end = static_cast<size_t>(b->pos + n);
    if (b->bytes.size() < end) b->bytes.resize(end);
    b->bytes.replace(static_cast<size_t>(b->pos), static_cast<size_t>(n), static_cast<const char*>(p), static_cast<size_t>(n));
    b->pos += n;
    return n;
}
sf_count_t tell(void* u) { return static_cast<Buffer*>(u)->pos; }

// A WAV file in memory: `channels` interleaved, frames from f(frame, channel).
template <class F>
std::string wav(int rate, int channels, sf_count_t frames, int subformat, F f) {
    Buffer b;
    SF_VIRTUAL_IO io{len, seek, rd, wr, tell};
    SF_INFO info{};
    info.samplerate = rate;
    info.channels = channels;
    info.format = SF_FORMAT_WAV | subformat;
    SNDFILE* s = sf_open_virtual(&io, SFM_WRITE, &info, &b);
    EXPECT_NE(s, nullptr) << sf_strerror(nullptr);
    std::vector<double> data(static_cast<size_t>(frames * channels));
    for (sf_count_t i = 0; i < frames; ++i) {
        for (int c = 0; c < channels; ++c) data[static_cast<size_t>(i * channels + c)] = f(i, c);
    }
    sf_writef_double(s, data.data(), frames);
    sf_close(s);
    return b.bytes;
}

double envelope(double t) { return 0.5 + 0.4 * std::sin(2 * M_PI * 2 * t); }
double am_sine(sf_count_t i, int rate) {
    const double t = static_cast<double>(i) / rate;
    return envelope(t) * std::sin(2 * M_PI * 200 * t);
}

TEST(WavImport, AmplitudeModulatedSineGivesItsEnvelope) {
    constexpr int kRate = 48000;
    const std::string bytes = wav(kRate, 1, 2 * kRate, SF_FORMAT_PCM_16, [](sf_count_t i, int) { return am_sine(i, kRate); });
    ImportOptions o;
    o.axis = Axis::z;
    const ImportResult r = import_wav(bytes, o);
    ASSERT_EQ(r.sensation.effects.size(), 1u);
    const format::EffectSpec& e = r.sensation.effects[0];
    EXPECT_EQ(e.params.type, EffectType::force_profile);
    EXPECT_EQ(e.params.axes[0], Axis::z);
    EXPECT_EQ(e.params.custom.sample_period_us, 10'000);
    ASSERT_EQ(e.samples.size(), 200u);
    EXPECT_EQ(e.params.duration_us, 2'000'000);
    for (size_t k = 0; k < e.samples.size(); ++k) {
        double top = 0;
        for (int j = 0; j <= 100; ++j) top = std::max(top, envelope((static_cast<double>(k) + j / 100.0) * 0.01));
        EXPECT_LE(e.samples[k], std::lround(top * 10000) + 2) << k;
        EXPECT_GE(e.samples[k], std::lround(top * 10000) - 75) << k;
    }
}

TEST(WavImport, FirstChannelOfAStereoFileAtTheChosenPeriod) {
    constexpr int kRate = 8000;
    // Channel 0: a 400 Hz tone at 0.25; channel 1: full-scale, which must not show.
    const std::string bytes = wav(kRate, 2, kRate / 2, SF_FORMAT_FLOAT, [](sf_count_t i, int c) {
        return c == 0 ? 0.25 * std::sin(2 * M_PI * 400 * static_cast<double>(i) / kRate + 0.3) : 1.0;
    });
    ImportOptions o;
    o.sample_period_us = 50'000;
    const ImportResult r = import_wav(bytes, o);
    const format::EffectSpec& e = r.sensation.effects.at(0);
    ASSERT_EQ(e.samples.size(), 10u);
    for (int16_t v : e.samples) {
        EXPECT_LE(v, 2500);
        EXPECT_GE(v, 2500 - 40);  // 20 samples per 400 Hz cycle: peaks within 1 − cos(π/20) ≈ 1.2%
    }
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_NE(r.notes[0].find("2 channels"), std::string::npos);
}

TEST(WavImport, ErrorsNameTheLimit) {
    const auto silence = [](sf_count_t, int) { return 0.0; };
    const std::string long_file = wav(1000, 1, 70 * 1000, SF_FORMAT_PCM_16, silence);
    try {
        (void)import_wav(long_file, {});
        FAIL() << "a 70 s sound was accepted";
    } catch (const ImportError& e) {
        EXPECT_NE(std::string(e.what()).find("allowed 1..65535 samples, at most 65 s"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("trim the sound to 65 s"), std::string::npos) << e.what();
    }
    const std::string minute = wav(1000, 1, 60 * 1000, SF_FORMAT_PCM_16, silence);
    ImportOptions fine;
    fine.sample_period_us = 1000;  // 60 s at 1 ms: 60000 samples, within 65535
    EXPECT_EQ(import_wav(minute, fine).sensation.effects.at(0).samples.size(), 60000u);
    ImportOptions bad;
    bad.sample_period_us = 10;
    EXPECT_THROW((void)import_wav(minute, bad), ImportError);
    try {
        (void)import_wav(minute, bad);
    } catch (const ImportError& e) {
        EXPECT_NE(std::string(e.what()).find("= 10 is out of range (allowed 1000..1000000)"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)import_wav("RIFF\x10\0\0\0WAVEjunkjunk", {}), ImportError);
    EXPECT_THROW((void)import_wav(long_file.substr(0, 30), {}), ImportError);  // cut inside the header
}

}  // namespace
}  // namespace feel::import
