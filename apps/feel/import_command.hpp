// feel import: a DirectInput effect file, an Apple AHAP pattern or a WAV sound as a
// feel/1 sensation file (docs/import.md, docs/cli.md).
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace CLI { class App; }

namespace feel::cli {

struct ImportArgs {
    std::string file;
    std::string output;                   // the sensation file to write
    std::string name;                     // empty: from the file name
    std::string axis;                     // AHAP, WAV: x, y, z, rx, ry, rz; empty: x
    std::optional<int64_t> sample_period_us;  // WAV only
};

void add_import(CLI::App& app, ImportArgs& args);
void run_import(const ImportArgs& args, std::ostream& out, std::ostream& err);

}  // namespace feel::cli
