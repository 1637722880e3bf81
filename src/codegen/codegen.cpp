// Dispatch, names and the checks every language shares (codegen.hpp).
#include "codegen.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include "effect_code.hpp"
#include "generated_program.hpp"

namespace feel::codegen {

std::optional<Language> language_from_name(std::string_view name) noexcept {
    if (name == "cpp") return Language::cpp;
    if (name == "c") return Language::c;
    if (name == "library") return Language::library;
    return std::nullopt;
}

std::string_view language_name(Language language) noexcept {
    switch (language) {
        case Language::cpp: return "cpp";
        case Language::c: return "c";
        case Language::library: return "library";
    }
    return "cpp";
}

std::string_view language_extension(Language language) noexcept {
    return language == Language::c ? ".c" : ".cpp";
}

std::string sample_initializer(const std::vector<int16_t>& samples, std::string_view indent) {
    std::string out;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (i % 16 == 0) out += (i == 0 ? "" : "\n") + std::string(indent);
        out += std::to_string(samples[i]) + (i + 1 < samples.size() ? ", " : "");
    }
    return out;
}

std::string export_code(Language language, const format::SensationFile& file, std::span<const std::string> names,
                        std::string_view file_path) {
    ExportPlan plan;
    plan.file_path = file_path;
    for (const std::string& name : names) {
        if (file.find(name) != nullptr) continue;
        std::string known;
        for (const format::Sensation& s : file.sensations) known += (known.empty() ? "" : ", ") + s.name;
        throw std::invalid_argument("export: no sensation \"" + name + "\" in " + std::string(file_path) +
                                    " (it has: " + known + ")");
    }
    for (size_t i = 0; i < names.size(); ++i) {
        if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(i), names[i]) !=
            names.begin() + static_cast<std::ptrdiff_t>(i)) {
            throw std::invalid_argument("export: sensation \"" + names[i] + "\" is named twice");
        }
    }
    std::set<std::string> taken;
    for (const format::Sensation& s : file.sensations) {
        if (!names.empty() && std::find(names.begin(), names.end(), s.name) == names.end()) continue;
        std::string ident = identifier(s.name);
        for (int n = 2; taken.contains(ident); ++n) ident = identifier(s.name) + "_" + std::to_string(n);
        taken.insert(ident);
        plan.sensations.push_back({&s, ident});
    }
    if (plan.sensations.empty()) {
        throw std::invalid_argument("export: " + std::string(file_path) + " has no sensations to export");
    }
    switch (language) {
        case Language::cpp: return cpp_program(plan);
        case Language::c: return c_program(plan);
        case Language::library: return library_program(plan);
    }
    return {};
}

}  // namespace feel::codegen
