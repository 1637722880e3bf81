// feel export: the code that recreates sensations of a file (src/codegen, docs/cli.md).
//
//   feel export FILE --lang cpp|c|library [--sensation NAME]... [-o OUT]
//
// cpp: a C++ program on the §8 wrappers and the host API; c: the same in C on feel.h;
// library: §9.5's two SensationLibrary calls for one sensation of the saved file.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace feel::cli {

struct ExportArgs {
    std::string file;
    std::string lang;                    // cpp, c or library
    std::vector<std::string> sensations; // empty: all (cpp, c), the file's only one (library)
    std::string output;                  // empty or "-": standard output
};

void run_export(const ExportArgs& args, std::ostream& out);

}  // namespace feel::cli
