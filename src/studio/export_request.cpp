// The export_code message (export_request.hpp).
#include "export_request.hpp"

#include <string>
#include <vector>

#include "codegen.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::studio {

using json = nlohmann::json;

json export_reply(const json& m) {
    const std::string name = m["name"].get<std::string>();
    const std::string lang = m["lang"].get<std::string>();
    const std::string file_path = m.contains("file") ? m["file"].get<std::string>() : name + ".feel.json";
    const auto error = [&](const std::string& message) {
        return json{{"type", "error"}, {"message", message.substr(0, 2000)}, {"request", "export_code"}};
    };
    const std::optional<codegen::Language> language = codegen::language_from_name(lang);
    if (!language) return error("export_code: lang \"" + lang + "\" is not a language (allowed: cpp, c, library)");
    const json& effects = m["effects"];
    if (effects.empty()) return error("export_code: the sensation \"" + name + "\" has no effects to export");
    const json sensation = effects.size() > 1 ? json{{"effects", effects}} : effects[0];
    format::SensationFile file;
    try {
        file = format::parse_sensation_file(json{{"format", "feel/1"}, {"sensations", {{name, sensation}}}}.dump(),
                                            file_path);
    } catch (const format::FormatError& e) {
        return error(std::string("export_code: ") + e.what());
    }
    const std::vector<std::string> names = {name};
    const std::string code = codegen::export_code(*language, file, names, file_path);
    std::string base = name;
    for (char& c : base) {
        if (c == '.') c = '_';
    }
    return json{{"type", "exported"},
                {"seq", m["seq"]},
                {"lang", lang},
                {"filename", base + (*language == codegen::Language::c ? ".c" : ".cpp")},
                {"code", code}};
}

}  // namespace feel::studio
