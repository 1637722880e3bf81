// feel::host — load a sensation file and play its sensations: two calls (§9.5).
//
//   auto library = feel::host::SensationLibrary::load("examples/primer.feel.json");
//   library->play("railing_impact");
//
// load() opens the device (the in-process simulated one unless an address is given),
// creates and downloads every effect of every sensation, and arms as reflexes the effects
// whose file gives them a trigger button or hat ("button assignments", §1.2.c) — on the
// device, or emulated by the host on a device without local reflexes. play() starts a
// sensation's effects together. effects() hands out the effects so that a game can change a
// designed sensation before playing it again (§9.5: "alter some parameters ... directly").
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "feel/host/device.hpp"

namespace feel::host {

class SensationLibrary {
public:
    // Call 1. Errors: invalid_parameter for a file that does not load (the message is the
    // format's, naming file, sensation, field and range), and any error of open/create
    // (not_supported for a type the device lacks, device_full when it all does not fit).
    [[nodiscard]] static Result<SensationLibrary> load(const std::filesystem::path& file,
                                                       std::string_view address = "sim:iforce2",
                                                       const OpenOptions& options = {});
    [[nodiscard]] static Result<SensationLibrary> load(const std::filesystem::path& file, Device device);
    // Loads only the named sensations of the file (a device too small for the whole file,
    // e.g. an I-FORCE 1.x with 16 effect slots, can still play one). invalid_parameter for
    // a name the file lacks (the message lists the file's names).
    [[nodiscard]] static Result<SensationLibrary> load(const std::filesystem::path& file, Device device,
                                                       std::span<const std::string> only);

    // Call 2. Starts every effect of the sensation (iterations as in Effect::start).
    // invalid_parameter for an unknown name (the message lists the names).
    Status play(std::string_view name, int32_t iterations = runtime::kEffectIterations);
    Status stop(std::string_view name);
    Status stop_all();

    [[nodiscard]] std::vector<std::string> names() const;
    // The sensation's effects, in file order; empty for an unknown name.
    [[nodiscard]] std::span<Effect> effects(std::string_view name);
    [[nodiscard]] Device& device() noexcept { return device_; }

private:
    struct Entry {
        std::string name;
        std::vector<Effect> effects;
    };
    SensationLibrary(Device device, std::vector<Entry> entries)
        : device_(std::move(device)), entries_(std::move(entries)) {}
    Device device_;
    std::vector<Entry> entries_;
};

}  // namespace feel::host
