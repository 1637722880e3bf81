// The exported programs on a simulated device (issue 11 §2): each example file exported in
// C++ and C (tests/codegen/CMakeLists.txt builds them with `feel export`), run against a
// `feel device`-like Peripheral on a Unix socket. While the program holds its effects, the
// test stops the device's loop and reads, slot by slot, the effect parameters the device's
// engine holds and whether a reflex is armed on them. Then the program ends (the device
// resets), the file itself is loaded onto the same device by SensationLibrary (§9.5), and
// the device is read the same way. Both must hold the same effects, field for field: the
// reference is what the device received from the file, not the generator's own output.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "feel/format/sensation_file.hpp"
#include "feel/host/device.hpp"
#include "feel/host/sensation_library.hpp"
#include "feel/peripheral/peripheral.hpp"
#include "feel/transport/transport.hpp"

namespace feel {
namespace {

namespace fs = std::filesystem;

struct SlotContents {
    int index = 0;
    EffectParams params{};
    bool reflex = false;
};

// Every occupied slot of the device's engine, in slot order, read with the loop stopped.
std::vector<SlotContents> device_slots(peripheral::Peripheral& device) {
    runtime::DeviceRuntime& rt = device.runtime();
    rt.stop();
    std::vector<SlotContents> out;
    const Engine& engine = rt.pipeline().engine();
    for (int index = 0; index < engine.config().max_effects; ++index) {
        // The handle's generation is the engine's business; any generation that reads is the slot's.
        for (uint32_t generation = 0; generation <= 0xFFFF; ++generation) {
            const EffectId id{static_cast<uint16_t>(index), static_cast<uint16_t>(generation)};
            SlotContents slot;
            if (engine.params(id, slot.params)) continue;
            slot.index = index;
            slot.reflex = rt.pipeline().reflexes().find(id) != nullptr;
            out.push_back(slot);
            break;
        }
    }
    rt.start();
    return out;
}

// The effect as a feel/1 file, for a failure's message.
std::string describe(const EffectParams& params) {
    format::SensationFile file;
    file.sensations.push_back({"slot", std::nullopt, false, {format::EffectSpec{params, {}, {}}}});
    try {
        return format::write_sensation_file(file);
    } catch (const std::exception& e) {
        return std::string("(not writable: ") + e.what() + ")\n";
    }
}

// A child process with its standard input and output on pipes.
class Program {
public:
    Program(const std::string& path, const std::string& address) {
        int in[2];
        int out[2];
        if (::pipe(in) != 0 || ::pipe(out) != 0) throw std::runtime_error("pipe");
        pid_ = ::fork();
        if (pid_ == 0) {
            ::dup2(in[0], 0);
            ::dup2(out[1], 1);
            ::close(in[1]);
            ::close(out[0]);
            ::execl(path.c_str(), path.c_str(), address.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        ::close(in[0]);
        ::close(out[1]);
        stdin_ = in[1];
        stdout_ = out[0];
    }
    ~Program() {
        finish();
        if (stdout_ >= 0) ::close(stdout_);
    }
    // The program's output up to and with the line that starts with `prefix` (or all of it).
    std::string read_until(const std::string& prefix) {
        std::string text;
        std::string line;
        char c;
        while (::read(stdout_, &c, 1) == 1) {
            text += c;
            if (c != '\n') {
                line += c;
                continue;
            }
            if (line.starts_with(prefix)) break;
            line.clear();
        }
        return text;
    }
    // Closes its input (the program's "Enter") and returns its exit status.
    int finish() {
        if (stdin_ >= 0) {
            ::close(stdin_);
            stdin_ = -1;
        }
        if (pid_ <= 0) return status_;
        int status = 0;
        ::waitpid(pid_, &status, 0);
        pid_ = -1;
        status_ = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        return status_;
    }

private:
    pid_t pid_ = -1;
    int stdin_ = -1;
    int stdout_ = -1;
    int status_ = -1;
};

class ExportedPrograms : public ::testing::TestWithParam<std::tuple<const char*, const char*>> {};

TEST_P(ExportedPrograms, GiveTheDeviceTheEffectsOfTheFile) {
    const auto [example, lang] = GetParam();
    const fs::path program = fs::path(FEEL_BINARY_DIR) / "tests" / "codegen" / ("exported_" + std::string(example) + "_" + lang);
    const fs::path file = fs::path(FEEL_SOURCE_DIR) / "examples" / (std::string(example) + ".feel.json");
    ASSERT_TRUE(fs::exists(program)) << program;
    const fs::path dir = fs::temp_directory_path() / ("feel-codegen-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string address = "unix:" + (dir / (std::string(example) + "-" + lang + ".sock")).string();

    peripheral::PeripheralOptions options;
    options.runtime.realtime_priority = false;
    options.runtime.lock_memory = false;
    peripheral::Peripheral device(options);
    device.serve(transport::listen(transport::Address::parse(address)));

    std::vector<SlotContents> exported;
    {
        Program run(program.string(), address);
        const std::string said = run.read_until("ready:");
        ASSERT_NE(said.find("ready:"), std::string::npos) << program << " said: " << said;
        exported = device_slots(device);
        EXPECT_EQ(run.finish(), 0) << program;
    }
    std::vector<SlotContents> from_file;
    {
        host::OpenOptions open;
        host::Result<host::Device> host = host::Device::open(address, open);
        ASSERT_TRUE(host) << host.status().message;
        host::Result<host::SensationLibrary> library = host::SensationLibrary::load(file, host.value());
        ASSERT_TRUE(library) << library.status().message;
        from_file = device_slots(device);
    }
    device.stop();
    fs::remove_all(dir);

    size_t effects_in_file = 0;
    for (const format::Sensation& s : format::load_sensation_file(file).sensations) effects_in_file += s.effects.size();
    ASSERT_EQ(from_file.size(), effects_in_file);
    ASSERT_EQ(exported.size(), from_file.size());
    for (size_t i = 0; i < exported.size(); ++i) {
        SCOPED_TRACE("slot " + std::to_string(from_file[i].index) + ": " +
                     std::string(effect_type_name(from_file[i].params.type)));
        EXPECT_EQ(exported[i].index, from_file[i].index);
        EXPECT_TRUE(exported[i].params == from_file[i].params)
            << "exported:\n" << describe(exported[i].params) << "from the file:\n" << describe(from_file[i].params);
        EXPECT_EQ(exported[i].reflex, from_file[i].reflex);
    }
}

INSTANTIATE_TEST_SUITE_P(EveryExample, ExportedPrograms,
                         ::testing::Combine(::testing::Values("conditions", "dynamics", "primer", "walls"),
                                            ::testing::Values("cpp", "c")),
                         [](const auto& param_info) {
                             return std::string(std::get<0>(param_info.param)) + "_" + std::get<1>(param_info.param);
                         });

}  // namespace
}  // namespace feel
