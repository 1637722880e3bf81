// Load and play in two calls (§9.5), with the primer's own sensation file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "feel/format/sensation_file.hpp"
#include "feel/host/sensation_library.hpp"
#include "feel/sim/device_profile.hpp"
#include "host_test_support.hpp"

namespace feel::host::test {
namespace {

const std::filesystem::path kPrimerFile = std::filesystem::path(FEEL_SOURCE_DIR) / "examples" / "primer.feel.json";

// The primer's reflex table and its railing impact, in a file of their own (written with the
// format's own writer): the whole primer file holds 19 effects, more than the 16 slots of
// the 1.x-class device.
struct ReflexTableFile {
    std::filesystem::path path;
    ReflexTableFile() {
        format::SensationFile file = format::load_sensation_file(kPrimerFile);
        std::erase_if(file.sensations, [](const format::Sensation& s) {
            return s.name != "railing_impact" && s.effects[0].params.trigger.kind == TriggerKind::none;
        });
        path = std::filesystem::temp_directory_path() /
               ("feel-host-primer-" + std::to_string(reinterpret_cast<uintptr_t>(this)) + ".feel.json");
        std::ofstream(path) << format::write_sensation_file(file);
    }
    ~ReflexTableFile() {
        std::error_code ec;
        std::filesystem::remove(path, ec);
    }
};

TEST(HostSensationLibrary, ThePrimersFileLoadsAsWrittenAndAHatTheDeviceLacksIsRefused) {
    // §1.2.c's table puts the Patriot missile on hat switch #2: the I-FORCE sticks have two.
    ASSERT_GE(sim::find_device_profile("iforce2")->hat_count, 2);
    Result<SensationLibrary> library = SensationLibrary::load(kPrimerFile, "sim:iforce2");
    EXPECT_TRUE(library) << library.status().message;

    // A trigger on a hat the device lacks would never fire: refused, naming it.
    format::SensationFile file = format::load_sensation_file(kPrimerFile);
    for (auto& sensation : file.sensations) {
        if (sensation.name == "patriot_missile") sensation.effects[0].params.trigger.index = 3;
    }
    const auto path = std::filesystem::temp_directory_path() / "feel-host-hat3.feel.json";
    std::ofstream(path) << format::write_sensation_file(file);
    Result<SensationLibrary> hat3 = SensationLibrary::load(path, "sim:iforce2");
    std::filesystem::remove(path);
    ASSERT_FALSE(hat3);
    EXPECT_EQ(hat3.status().kind, ErrorKind::invalid_parameter);
    const std::string& m = hat3.status().message;
    EXPECT_NE(m.find("sensation \"patriot_missile\""), std::string::npos) << m;
    EXPECT_NE(m.find("trigger_button = hat3 is out of range (allowed hat1..hat2)"), std::string::npos) << m;
}

TEST(HostSensationLibrary, LoadingChosenSensationsFitsASmallDevice) {
    // The whole primer file holds more effects than iforce1's 16 slots; one sensation fits.
    Result<Device> device = Device::open("sim:iforce1");
    ASSERT_TRUE(device) << device.status().message;
    const std::string only[] = {"railing_impact"};
    Result<SensationLibrary> library = SensationLibrary::load(kPrimerFile, device.value(), only);
    ASSERT_TRUE(library) << library.status().message;
    EXPECT_EQ(library->names(), std::vector<std::string>{"railing_impact"});
    EXPECT_TRUE(library->play("railing_impact").ok());
    Result<PoolInfo> pool = device->pool();
    ASSERT_TRUE(pool) << pool.status().message;
    EXPECT_EQ(pool->max_effects - pool->free_effects, 1);  // only its one effect is resident

    const std::string unknown[] = {"warp_drive"};
    Result<SensationLibrary> missing = SensationLibrary::load(kPrimerFile, device.value(), unknown);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(missing.status().message.find("no sensation \"warp_drive\""), std::string::npos)
        << missing.status().message;
    EXPECT_NE(missing.status().message.find("railing_impact"), std::string::npos) << missing.status().message;
}

TEST(HostSensationLibrary, LoadsThePrimerFileAndPlaysASensation) {
    const std::filesystem::path kPrimer = kPrimerFile;
    Result<SensationLibrary> library = SensationLibrary::load(kPrimer, "sim:iforce2");
    ASSERT_TRUE(library) << library.status().message;
    // Every sensation of the file, in file order (read independently with the format).
    const format::SensationFile file = format::load_sensation_file(kPrimer);
    std::vector<std::string> expected;
    for (const auto& s : file.sensations) expected.push_back(s.name);
    EXPECT_EQ(library->names(), expected);

    ASSERT_TRUE(library->play("railing_impact").ok());
    std::span<Effect> effects = library->effects("railing_impact");
    ASSERT_EQ(effects.size(), 1u);
    EXPECT_EQ(effects[0].status()->state, runtime::ReportedEffectState::playing);
    ASSERT_TRUE(library->stop("railing_impact").ok());
    EXPECT_EQ(effects[0].status()->state, runtime::ReportedEffectState::stopped);

    // A compound plays all its effects; the second waits its start delay.
    ASSERT_TRUE(library->play("cross_wind_with_gun_blasts").ok());
    std::span<Effect> wind = library->effects("cross_wind_with_gun_blasts");
    ASSERT_EQ(wind.size(), 2u);
    EXPECT_EQ(wind[0].status()->state, runtime::ReportedEffectState::playing);
    EXPECT_EQ(wind[1].status()->state, runtime::ReportedEffectState::delayed);
    ASSERT_TRUE(library->stop_all().ok());
    EXPECT_EQ(wind[0].status()->state, runtime::ReportedEffectState::stopped);

    const Status unknown = library->play("warp_drive");
    EXPECT_EQ(unknown.kind, ErrorKind::invalid_parameter);
    EXPECT_NE(unknown.message.find("warp_drive"), std::string::npos);
    EXPECT_NE(unknown.message.find("railing_impact"), std::string::npos) << unknown.message;
    EXPECT_TRUE(library->effects("warp_drive").empty());
}

TEST(HostSensationLibrary, ButtonAssignmentsBecomeReflexes) {
    const ReflexTableFile primer;
    const std::filesystem::path kPrimer = primer.path;
    // iforce1: the file's trigger buttons are emulated by the host (§1.2.c).
    Result<SensationLibrary> one = SensationLibrary::load(kPrimer, "sim:iforce1");
    ASSERT_TRUE(one) << one.status().message;
    ASSERT_EQ(one->effects("machine_guns").size(), 1u);
    EXPECT_TRUE(one->effects("machine_guns")[0].emulated());
    EXPECT_EQ(one->effects("machine_guns")[0].parameters().trigger.index, 1);
    EXPECT_FALSE(one->effects("railing_impact")[0].emulated());
    // iforce2: the same triggers are device reflexes.
    Result<SensationLibrary> two = SensationLibrary::load(kPrimer, "sim:iforce2");
    ASSERT_TRUE(two) << two.status().message;
    EXPECT_FALSE(two->effects("machine_guns")[0].emulated());
    EXPECT_TRUE(two->effects("machine_guns")[0].downloaded());
}

TEST(HostSensationLibrary, PullingTheTriggerFiresTheFilesReflex) {
    const ReflexTableFile primer;
    for (const char* profile : {"iforce1", "iforce2"}) {
        SCOPED_TRACE(profile);
        SimRig rig = SimRig::make(profile);
        Result<SensationLibrary> library = SensationLibrary::load(primer.path, *rig.host);
        ASSERT_TRUE(library) << library.status().message;
        Effect& guns = library->effects("machine_guns")[0];  // §1.2.c: trigger 1
        rig.set_buttons(0b1);
        // Emulated by the host on the 1.x device, a device reflex on the 2.0 one.
        const auto expected = rig.host->capabilities().local_reflexes ? runtime::ReportedEffectState::playing
                                                                        : runtime::ReportedEffectState::emulated;
        EXPECT_TRUE(wait_until([&] {
            Result<EffectStatusInfo> st = guns.status();
            return st && st->state == expected;
        }));
        rig.set_buttons(0);
    }
}

TEST(HostSensationLibrary, TheWholePrimerDoesNotFitTheSixteenSlotsOfIforce1) {
    const format::SensationFile file = format::load_sensation_file(kPrimerFile);
    std::size_t effects = 0;
    for (const auto& sensation : file.sensations) effects += sensation.effects.size();
    ASSERT_GT(effects, 16u);  // iforce1's data sheet: 16 effect slots
    Result<SensationLibrary> library = SensationLibrary::load(kPrimerFile, "sim:iforce1");
    ASSERT_FALSE(library);
    EXPECT_EQ(library.status().kind, ErrorKind::device_full) << library.status().message;
}

TEST(HostSensationLibrary, ABadFileIsAnInvalidParameterNamingIt) {
    const auto path = std::filesystem::temp_directory_path() / "feel-host-bad.feel.json";
    std::ofstream(path) << R"({"format": "feel/1", "sensations": {"hum": {"type": "sine", "duration_us": 1000000, "axes": ["x"],
        "periodic": {"magnitude": 2000, "period_us": 10000, "phase": 36000}}}})";
    Result<SensationLibrary> library = SensationLibrary::load(path, "sim:iforce2");
    std::filesystem::remove(path);
    ASSERT_FALSE(library);
    EXPECT_EQ(library.status().kind, ErrorKind::invalid_parameter);
    EXPECT_NE(library.status().message.find("periodic.phase = 36000 is out of range (allowed 0..35999)"),
              std::string::npos)
        << library.status().message;
    EXPECT_NE(library.status().message.find("hum"), std::string::npos);

    Result<SensationLibrary> missing = SensationLibrary::load("/nonexistent/x.feel.json");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.status().kind, ErrorKind::invalid_parameter);
}

TEST(HostSensationLibrary, ATypeTheDeviceLacksIsRenderedByTheHost) {
    // iforce1 plays no Dynamics: the library's dynamics are host-rendered (emulated).
    const auto path = std::filesystem::path(FEEL_SOURCE_DIR) / "examples" / "dynamics.feel.json";
    Result<SensationLibrary> library = SensationLibrary::load(path, "sim:iforce1");
    ASSERT_TRUE(library) << library.status().message;
    std::span<Effect> recoil = library->effects("rifle_recoil");
    ASSERT_FALSE(recoil.empty());
    for (Effect& e : recoil) EXPECT_TRUE(e.emulated());
}

}  // namespace
}  // namespace feel::host::test
