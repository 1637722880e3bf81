// feel import FILE -o OUT.feel.json: the importers of src/import/ on the command line.
#include "import_command.hpp"

#include <CLI/CLI.hpp>

#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>

#include "cli.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/import/import.hpp"

namespace feel::cli {

void add_import(CLI::App& app, ImportArgs& a) {
    CLI::App* cmd = app.add_subcommand(
        "import", "Convert a DirectInput effect file (.ffe), an Apple AHAP pattern (.ahap) or a WAV sound "
                  "(.wav) into a sensation file (docs/import.md)");
    cmd->add_option("FILE", a.file, "The file to import; its format is recognized from its content")->required();
    cmd->add_option("-o,--output", a.output, "The sensation file to write (feel/1 JSON)")->required();
    cmd->add_option("--name", a.name, "The sensation's name (default: the file's name)");
    cmd->add_option("--axis", a.axis, "AHAP and WAV: the axis the force drives, x, y, z, rx, ry or rz (default x)");
    cmd->add_option("--sample-period", a.sample_period_us,
                    "WAV: the force profile's sample period in µs, " + std::to_string(import::kMinWavSamplePeriodUs) +
                        ".." + std::to_string(import::kMaxWavSamplePeriodUs) + " (default " +
                        std::to_string(import::kDefaultWavSamplePeriodUs) + ")");
    cmd->footer("Exit codes: 0 imported; 1 an unreadable or invalid file, an effect feel cannot express, an "
                "unwritable output; 2 a wrong command line.");
}

void run_import(const ImportArgs& args, std::ostream& out, std::ostream& err) {
    import::ImportOptions options;
    options.name = args.name;
    options.sample_period_us = args.sample_period_us;
    if (!args.axis.empty()) {
        const std::optional<Axis> axis = axis_from_name(args.axis);
        if (!axis) throw UsageError("--axis " + args.axis + " is not an axis (allowed x, y, z, rx, ry, rz)");
        options.axis = axis;
    }
    std::ifstream in(args.file, std::ios::binary);
    if (!in) throw std::runtime_error(args.file + ": cannot be read");
    std::string bytes;
    bytes.resize(import::kMaxImportBytes + 1);
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<size_t>(in.gcount()));
    if (bytes.size() > import::kMaxImportBytes) {
        throw std::runtime_error(args.file + ": larger than " + std::to_string(import::kMaxImportBytes) +
                                 " bytes (16 MiB), the most an import reads");
    }
    const std::optional<import::SourceFormat> format = import::detect_format(bytes, args.file);
    import::ImportResult result = import::import_sensation(bytes, args.file, options);
    for (const std::string& note : result.notes) err << "feel import: note: " << note << '\n';

    format::SensationFile file;
    file.sensations.push_back(std::move(result.sensation));
    const std::string text = format::write_sensation_file(file);
    std::ofstream o(args.output, std::ios::binary | std::ios::trunc);
    if (!o || !(o << text) || !o.flush()) throw std::runtime_error(args.output + ": cannot be written");
    const format::Sensation& s = file.sensations.front();
    out << args.output << ": sensation \"" << s.name << "\" (" << s.effects.size()
        << (s.effects.size() == 1 ? " effect" : " effects") << ") from " << import::format_name(*format) << " "
        << args.file << '\n';
}

}  // namespace feel::cli
