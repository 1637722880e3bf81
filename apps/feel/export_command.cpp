// feel export (export_command.hpp). The generators are src/codegen's; this command reads the
// file, checks the flags and writes the code.
#include "export_command.hpp"

#include <filesystem>
#include <fstream>
#include <ostream>

#include "cli.hpp"
#include "codegen.hpp"
#include "feel/format/sensation_file.hpp"

namespace feel::cli {

void run_export(const ExportArgs& args, std::ostream& out) {
    const std::optional<codegen::Language> language = codegen::language_from_name(args.lang);
    if (!language) throw UsageError("--lang \"" + args.lang + "\" is not a language (allowed: cpp, c, library)");
    const format::SensationFile file = format::load_sensation_file(args.file);  // FormatError names the field
    std::vector<std::string> names = args.sensations;
    if (*language == codegen::Language::library && names.size() != 1) {
        if (names.empty() && file.sensations.size() == 1) {
            names.push_back(file.sensations.front().name);
        } else {
            std::string known;
            for (const format::Sensation& s : file.sensations) known += (known.empty() ? "" : ", ") + s.name;
            throw UsageError("--lang library plays one sensation: give exactly one --sensation (" + args.file +
                             " has: " + known + ")");
        }
    }
    std::string code;
    try {
        code = codegen::export_code(*language, file, names, args.file);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());  // an unknown or repeated --sensation
    }
    if (args.output.empty() || args.output == "-") {
        out << code;
        return;
    }
    std::ofstream f(args.output, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + args.output);
    f << code;
    if (!f.flush()) throw std::runtime_error("cannot write " + args.output);
}

}  // namespace feel::cli
