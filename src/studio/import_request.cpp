// The Studio's import: base64 from the browser → the importer → a workspace file.
#include "import_request.hpp"

#include <array>
#include <stdexcept>
#include <string>

#include "feel/format/sensation_file.hpp"
#include "feel/import/import.hpp"
#include "workspace.hpp"

namespace feel::studio {
namespace {

// Strict standard base64 (RFC 4648 §4, padded): the browser's FileReader writes exactly
// this, and anything else is refused rather than guessed at. Boost's only decoder is in
// Beast's detail namespace and skips invalid characters.
std::string decode_base64(const std::string& text) {
    static constexpr std::array<int8_t, 256> kValue = [] {
        std::array<int8_t, 256> v{};
        v.fill(-1);
        const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        for (int i = 0; i < 64; ++i) v[static_cast<unsigned char>(digits[i])] = static_cast<int8_t>(i);
        return v;
    }();
    if (text.size() % 4 != 0) {
        throw std::runtime_error("import_file.data is not base64: its length " + std::to_string(text.size()) +
                                 " is not a multiple of 4");
    }
    std::string out;
    out.reserve(text.size() / 4 * 3);
    for (size_t i = 0; i < text.size(); i += 4) {
        int v[4];
        int pad = 0;
        for (int k = 0; k < 4; ++k) {
            const char c = text[i + static_cast<size_t>(k)];
            const bool last_group = i + 4 == text.size();
            if (c == '=' && last_group && k >= 2 && (k == 3 || text[i + 3] == '=')) {
                v[k] = 0;
                ++pad;
                continue;
            }
            v[k] = kValue[static_cast<unsigned char>(c)];
            if (v[k] < 0 || pad > 0) {
                throw std::runtime_error("import_file.data is not base64: character " + std::to_string(i + static_cast<size_t>(k)) +
                                         " is not one of A-Z a-z 0-9 + / (or = at the end)");
            }
        }
        const uint32_t n = static_cast<uint32_t>(v[0] << 18 | v[1] << 12 | v[2] << 6 | v[3]);
        out += static_cast<char>(n >> 16);
        if (pad < 2) out += static_cast<char>((n >> 8) & 0xFF);
        if (pad < 1) out += static_cast<char>(n & 0xFF);
    }
    return out;
}

}  // namespace

nlohmann::json import_into_workspace(Workspace& workspace, const nlohmann::json& m) {
    const std::string file_name = m.at("name").get<std::string>();
    const std::string bytes = decode_base64(m.at("data").get<std::string>());
    if (bytes.size() > kMaxStudioImportBytes) {
        throw std::runtime_error(file_name + " has " + std::to_string(bytes.size()) +
                                 " bytes; the Studio imports files up to " + std::to_string(kMaxStudioImportBytes) +
                                 " bytes (1 MiB): use `feel import` for larger ones");
    }
    import::ImportOptions options;
    // The axis belongs to AHAP and WAV: the file bar always sends its choice, and a .ffe,
    // whose effects name their own axes, does not use it.
    if (m.contains("axis") && import::detect_format(bytes, file_name) != import::SourceFormat::ffe) {
        options.axis = axis_from_name(m["axis"].get<std::string>());
    }
    import::ImportResult result = import::import_sensation(bytes, file_name, options);
    format::SensationFile file;
    const std::string name = result.sensation.name;
    file.sensations.push_back(std::move(result.sensation));
    const std::string text = format::write_sensation_file(file);

    std::string path;
    for (int n = 1; n <= 99 && path.empty(); ++n) {
        const std::string candidate = name + (n == 1 ? "" : "_" + std::to_string(n)) + ".feel.json";
        try {
            (void)workspace.resolve(candidate, true);  // exists: try the next name
        } catch (const WorkspaceFileMissing&) {
            path = candidate;
        }
    }
    if (path.empty()) throw std::runtime_error(name + ".feel.json and _2 .. _99 all exist in the workspace");
    const std::string saved = workspace.save(path, text, false);

    nlohmann::json notes = nlohmann::json::array();
    for (size_t i = 0; i < result.notes.size() && i < kMaxImportNotes - 1; ++i) notes.push_back(result.notes[i]);
    if (result.notes.size() >= kMaxImportNotes) {
        notes.push_back("… and " + std::to_string(result.notes.size() - (kMaxImportNotes - 1)) + " more notes");
    }
    return {{"type", "imported"}, {"file", path}, {"sensation", name}, {"text", saved}, {"notes", notes}};
}

}  // namespace feel::studio
