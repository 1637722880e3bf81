// SensationLibrary: load a sensation file onto a device, play its sensations (§9.5).
#include "feel/host/sensation_library.hpp"

#include <algorithm>

namespace feel::host {
namespace {

Status with_prefix(Status s, const std::string& prefix) {
    s.message = prefix + ": " + s.message;
    return s;
}

}  // namespace

Result<SensationLibrary> SensationLibrary::load(const std::filesystem::path& file, std::string_view address,
                                                const OpenOptions& options) {
    // Read the file first: a bad file should not cost opening a device.
    try {
        (void)format::load_sensation_file(file);
    } catch (const format::FormatError& e) {
        return Status::failure(ErrorKind::invalid_parameter, e.what());
    }
    Result<Device> device = Device::open(address, options);
    if (!device) return device.status();
    return load(file, std::move(device.value()));
}

Result<SensationLibrary> SensationLibrary::load(const std::filesystem::path& file, Device device) {
    return load(file, std::move(device), std::span<const std::string>{});
}

Result<SensationLibrary> SensationLibrary::load(const std::filesystem::path& file, Device device,
                                                std::span<const std::string> only) {
    format::SensationFile model;
    try {
        model = format::load_sensation_file(file);
    } catch (const format::FormatError& e) {
        return Status::failure(ErrorKind::invalid_parameter, e.what());
    }
    for (const std::string& name : only) {
        if (model.find(name) != nullptr) continue;
        std::string names;
        for (const format::Sensation& s : model.sensations) names += (names.empty() ? "" : ", ") + s.name;
        return Status::failure(ErrorKind::invalid_parameter, file.string() + ": no sensation \"" + name +
                                                                 "\" in the file (it has: " + names + ")",
                               Error::invalid("sensation", "no sensation of that name in the file"));
    }
    const auto wanted = [&](const std::string& name) {
        return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
    };
    std::vector<Entry> entries;
    entries.reserve(model.sensations.size());
    for (const format::Sensation& sensation : model.sensations) {
        if (!wanted(sensation.name)) continue;
        Entry entry;
        entry.name = sensation.name;
        for (std::size_t i = 0; i < sensation.effects.size(); ++i) {
            // Effects with a trigger button in the file become reflexes here (§1.2.c):
            // create_effect arms them on the device, or the host emulates them.
            Result<Effect> effect = device.create_effect(sensation.effects[i]);
            if (!effect) {
                std::string where = file.string() + ": sensation \"" + sensation.name + "\"";
                if (sensation.compound) where += ", effect " + std::to_string(i);
                return with_prefix(effect.status(), where);
            }
            entry.effects.push_back(std::move(effect.value()));
        }
        entries.push_back(std::move(entry));
    }
    return SensationLibrary(std::move(device), std::move(entries));
}

namespace {

template <class Entries>
auto find_entry(Entries& entries, std::string_view name) -> decltype(&entries.front()) {
    for (auto& e : entries) {
        if (e.name == name) return &e;
    }
    return nullptr;
}

}  // namespace

Status SensationLibrary::play(std::string_view name, int32_t iterations) {
    auto* entry = find_entry(entries_, name);
    if (!entry) {
        std::string names;
        for (const auto& e : entries_) names += (names.empty() ? "" : ", ") + e.name;
        const Error err = Error::invalid("sensation", "no sensation of that name in the library");
        return Status::failure(ErrorKind::invalid_parameter,
                               "play: no sensation \"" + std::string(name) + "\" in the library (it has: " + names + ")",
                               err);
    }
    for (Effect& effect : entry->effects) {
        if (Status s = effect.start(iterations); !s.ok()) return with_prefix(s, "play \"" + entry->name + "\"");
    }
    return Status::success();
}

Status SensationLibrary::stop(std::string_view name) {
    auto* entry = find_entry(entries_, name);
    if (!entry) {
        return Status::failure(ErrorKind::invalid_parameter, "stop: no sensation \"" + std::string(name) +
                                                                 "\" in the library");
    }
    for (Effect& effect : entry->effects) {
        if (Status s = effect.stop(); !s.ok()) return with_prefix(s, "stop \"" + entry->name + "\"");
    }
    return Status::success();
}

Status SensationLibrary::stop_all() {
    for (Entry& entry : entries_) {
        for (Effect& effect : entry.effects) {
            if (Status s = effect.stop(); !s.ok()) return with_prefix(s, "stop \"" + entry.name + "\"");
        }
    }
    return Status::success();
}

std::vector<std::string> SensationLibrary::names() const {
    std::vector<std::string> out;
    out.reserve(entries_.size());
    for (const Entry& e : entries_) out.push_back(e.name);
    return out;
}

std::span<Effect> SensationLibrary::effects(std::string_view name) {
    auto* entry = find_entry(entries_, name);
    if (!entry) return {};
    return entry->effects;
}

}  // namespace feel::host
