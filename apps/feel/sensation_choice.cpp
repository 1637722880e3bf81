// choose_sensation (sensation_choice.hpp).
#include "sensation_choice.hpp"

#include "cli.hpp"

namespace feel::cli {

const format::Sensation& choose_sensation(const format::SensationFile& file, const std::string& name,
                                          const std::string& path) {
    if (name.empty() && file.sensations.size() == 1) return file.sensations.front();
    if (!name.empty()) {
        if (const format::Sensation* s = file.find(name)) return *s;
    }
    std::string names;
    for (const format::Sensation& s : file.sensations) names += (names.empty() ? "" : ", ") + s.name;
    if (names.empty()) names = "none: the file holds no sensations";
    if (name.empty()) {
        throw UsageError("--sensation is required: " + path + " holds " + std::to_string(file.sensations.size()) +
                         " sensations (available: " + names + ")");
    }
    throw UsageError("--sensation \"" + name + "\" is not in " + path + " (available: " + names + ")");
}

}  // namespace feel::cli
