// The device session fuzzer's seeds (fuzz/corpus/device_session/) and its harness in the
// ordinary build: the seeds are the valid transactions built below, byte for byte, and the
// harness (fuzz/fuzz_device_session.cpp, compiled into this test) runs each one and a few
// hostile scripts clean. To write the seeds again after a protocol change:
//   FEEL_WRITE_DEVICE_SEEDS=1 build/tests/peripheral/feel_peripheral_tests --gtest_filter='FuzzCorpus.*'
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "session_rig.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace feel::peripheral::test {
namespace {

using protocol::EffectOperation;
using protocol::ReportId;

// A script in the fuzzer's format: [op][length u16 LE][payload].
class Script {
public:
    Script& frame(FrameKind kind, const std::vector<uint8_t>& payload) {
        bytes.push_back(static_cast<uint8_t>(kind));
        bytes.push_back(static_cast<uint8_t>(payload.size() & 0xFF));
        bytes.push_back(static_cast<uint8_t>(payload.size() >> 8));
        bytes.insert(bytes.end(), payload.begin(), payload.end());
        return *this;
    }
    Script& out(const protocol::AnyReport& r) { return frame(FrameKind::output_report, protocol::encode(r)); }
    Script& set(const protocol::AnyReport& r) { return frame(FrameKind::set_feature, protocol::encode(r)); }
    Script& get(ReportId id) { return frame(FrameKind::get_feature, {static_cast<uint8_t>(id)}); }
    Script& ticks(uint8_t n) {
        bytes.insert(bytes.end(), {0xFE, 1, 0, static_cast<uint8_t>(n - 1)});
        return *this;
    }
    Script& host_gone() {
        bytes.insert(bytes.end(), {0xFF, 0, 0});
        return *this;
    }
    std::vector<uint8_t> bytes;
};

protocol::CreateNewEffectReport create(uint32_t seq, EffectType type, uint16_t samples = 0) {
    protocol::CreateNewEffectReport r;
    r.sequence = seq;
    r.type = type;
    r.sample_count = samples;
    return r;
}

std::vector<std::pair<std::string, std::vector<uint8_t>>> seeds() {
    std::vector<std::pair<std::string, std::vector<uint8_t>>> all;
    {
        Script s;  // §7.5's spring on x and y: create, load, two conditions, commit, play, free
        s.set(create(1, EffectType::spring)).get(ReportId::block_load);
        s.out(spring_axis(2, 1, 0, 1000)).out(spring_axis(3, 1, 1, 1000));
        s.out(set_effect(4, 1, EffectType::spring, 2)).out(operation(5, 1, EffectOperation::start)).ticks(20);
        protocol::EffectStatusRequestReport q;
        q.sequence = 6;
        q.block = 1;
        s.out(q).out(operation(7, 1, EffectOperation::stop));
        protocol::BlockFreeReport f;
        f.sequence = 8;
        f.block = 1;
        s.out(f).get(ReportId::pid_pool);
        all.emplace_back("spring.bin", s.bytes);
    }
    {
        Script s;  // an enveloped sine, played, its magnitude updated while it plays
        s.set(create(1, EffectType::sine)).get(ReportId::block_load);
        s.out(periodic(2, 1, 3000, 20'000));
        protocol::SetEnvelopeReport env;
        env.sequence = 3;
        env.block = 1;
        env.impulse_level = 8000;
        env.settle_time_us = 50'000;
        s.out(env);
        protocol::SetEffectReport e = set_effect(4, 1, EffectType::sine);
        e.has_envelope = true;
        e.direction_kind = DirectionKind::polar;
        e.direction[0] = 9000;
        e.axis_count = 2;
        s.out(e).out(operation(5, 1, EffectOperation::start, protocol::kLoopInfinite)).ticks(30);
        s.out(periodic(6, 1, 6000, 20'000)).out(set_effect(7, 1, EffectType::sine));
        protocol::DeviceGainReport g;
        g.sequence = 8;
        g.gain = 7000;
        protocol::DeviceControlReport pause;
        pause.sequence = 9;
        pause.control = protocol::DeviceControlOp::device_pause;
        protocol::DeviceControlReport resume = pause;
        resume.sequence = 10;
        resume.control = protocol::DeviceControlOp::device_continue;
        s.out(g).out(pause).ticks(5).out(resume).ticks(5);
        all.emplace_back("sine_update.bin", s.bytes);
    }
    {
        Script s;  // a force profile in two data reports, then a force stream, then a reset
        s.set(create(1, EffectType::force_profile, 40)).get(ReportId::block_load);
        for (uint16_t offset = 0; offset < 40; offset += 24) {  // 24 + 16 (24 samples a report at most)
            protocol::CustomForceDataReport d;
            d.sequence = 2u + offset;
            d.block = 1;
            d.offset = offset;
            d.count = static_cast<uint8_t>(offset == 0 ? 24 : 16);
            for (int i = 0; i < d.count; ++i) d.samples[i] = static_cast<int16_t>(200 * (offset + i) - 4000);
            s.out(d);
        }
        protocol::SetCustomForceReport cf;
        cf.sequence = 50;
        cf.block = 1;
        cf.sample_period_us = 2000;
        cf.sample_count = 40;
        s.out(cf).out(set_effect(51, 1, EffectType::force_profile)).out(operation(52, 1, EffectOperation::start));
        for (uint32_t i = 0; i < 5; ++i) {
            protocol::DownloadForceSampleReport d;
            d.sequence = 60 + i;
            d.axis_count = 2;
            d.force[0] = static_cast<int16_t>(1000 * i);
            s.out(d).ticks(1);
        }
        s.get(ReportId::device_info).frame(FrameKind::get_descriptor, {});
        protocol::DeviceControlReport reset;
        reset.sequence = 70;
        reset.control = protocol::DeviceControlOp::device_reset;
        s.out(reset).get(ReportId::pid_pool);
        all.emplace_back("force_profile_stream.bin", s.bytes);
    }
    {
        Script s;  // a recoil on a trigger with a reflex, IDF, report rate; the host leaves and another comes
        s.set(create(1, EffectType::dynamic_recoil)).get(ReportId::block_load);
        protocol::SetDynamicReport d;
        d.sequence = 2;
        d.block = 1;
        d.dynamic.blast_intensity = 6000;
        d.dynamic.blast_resonance = 3000;
        d.dynamic.dynamic_mass = 2000;
        d.dynamic.interim_reporting = true;
        s.out(d);
        protocol::SetEffectReport e = set_effect(3, 1, EffectType::dynamic_recoil, 2);
        e.duration_us = 500'000;
        e.trigger_kind = TriggerKind::button;
        e.trigger_index = 1;
        s.out(e);
        protocol::ReflexReport r;
        r.sequence = 4;
        r.block = 1;
        s.out(r);
        protocol::IdfSettingsReport idf;
        idf.sequence = 5;
        idf.settings.periodic = true;
        protocol::ReportRateReport rate;
        rate.sequence = 6;
        rate.rate_hz = 500;
        protocol::KeepAliveReport k;
        k.sequence = 7;
        s.out(idf).out(rate).out(k).out(operation(8, 1, EffectOperation::start)).ticks(40);
        s.host_gone().set(create(1, EffectType::spring)).get(ReportId::block_load).get(ReportId::pid_pool);
        all.emplace_back("recoil_reflex_host_gone.bin", s.bytes);
    }
    return all;
}

const std::filesystem::path kCorpus = std::filesystem::path(FEEL_SOURCE_DIR) / "fuzz/corpus/device_session";

TEST(FuzzCorpus, SeedsAreTheValidTransactions) {
    const bool write = std::getenv("FEEL_WRITE_DEVICE_SEEDS") != nullptr;
    if (write) std::filesystem::create_directories(kCorpus);
    for (const auto& [name, bytes] : seeds()) {
        const std::filesystem::path path = kCorpus / name;
        if (write) {
            std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                        static_cast<std::streamsize>(bytes.size()));
        }
        std::ifstream in(path, std::ios::binary);
        ASSERT_TRUE(in) << path << " is missing (FEEL_WRITE_DEVICE_SEEDS=1 writes it)";
        const std::vector<uint8_t> on_disk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(on_disk, bytes) << path << " is not the transaction this test builds";
    }
}

TEST(FuzzCorpus, EverySeedReportIsAccepted) {
    // The seeds start the fuzzer from deep, valid states: each report in them succeeds.
    for (const auto& [name, bytes] : seeds()) {
        SCOPED_TRACE(name);
        SessionRig rig;
        std::size_t at = 0;
        int frames = 0;
        while (at + 3 <= bytes.size()) {
            const uint8_t op = bytes[at];
            const std::size_t length = bytes[at + 1] | static_cast<std::size_t>(bytes[at + 2]) << 8;
            const std::vector<uint8_t> payload(bytes.begin() + static_cast<std::ptrdiff_t>(at + 3),
                                               bytes.begin() + static_cast<std::ptrdiff_t>(at + 3 + length));
            at += 3 + length;
            if (op == 0xFE) {
                rig.run(payload[0] + 1);
            } else if (op == 0xFF) {
                rig.session().host_gone();
                rig.run(3);
            } else {
                rig.offer(Frame{static_cast<FrameKind>(op), payload});
                rig.run(2);
                ++frames;
            }
        }
        rig.run(10);
        EXPECT_GT(frames, 5);
        for (const protocol::CommandAnswer& s : rig.statuses) {
            EXPECT_EQ(s.code, ErrorCode::ok) << "sequence " << s.sequence << ": " << s.field << " " << s.rule;
        }
        for (const protocol::AnyReport& r : rig.feature_replies) {
            if (const auto* load = std::get_if<protocol::BlockLoadReport>(&r)) {
                EXPECT_EQ(load->status, protocol::BlockLoadStatus::success);
            }
        }
    }
}

TEST(FuzzCorpus, HarnessRunsTheSeedsClean) {
    for (const auto& [name, bytes] : seeds()) {
        SCOPED_TRACE(name);
        EXPECT_EQ(LLVMFuzzerTestOneInput(bytes.data(), bytes.size()), 0);
    }
}

TEST(FuzzCorpus, HarnessRunsHostileScriptsClean) {
    // Truncations of every seed at every tenth byte, and the seeds with bytes flipped: the
    // invariants (one answer per frame, blocks == engine) hold or the harness aborts.
    for (const auto& [name, bytes] : seeds()) {
        SCOPED_TRACE(name);
        for (std::size_t cut = 0; cut < bytes.size(); cut += 10) (void)LLVMFuzzerTestOneInput(bytes.data(), cut);
        std::vector<uint8_t> flipped = bytes;
        for (std::size_t i = 5; i < flipped.size(); i += 37) flipped[i] ^= 0x5A;
        (void)LLVMFuzzerTestOneInput(flipped.data(), flipped.size());
    }
}

}  // namespace
}  // namespace feel::peripheral::test
