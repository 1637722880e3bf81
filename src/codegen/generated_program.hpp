// feel::codegen — what the C++ and C generators share: the sensations to export, in file
// order, each with a unique identifier for its function.
#pragma once

#include <string>
#include <vector>

#include "feel/format/sensation_file.hpp"

namespace feel::codegen {

struct ExportedSensation {
    const format::Sensation* sensation = nullptr;
    std::string ident;  // unique among the exported ones
};

struct ExportPlan {
    std::vector<ExportedSensation> sensations;
    std::string file_path;  // how the code names the sensation file
};

[[nodiscard]] std::string cpp_program(const ExportPlan& plan);
[[nodiscard]] std::string c_program(const ExportPlan& plan);
[[nodiscard]] std::string library_program(const ExportPlan& plan);

// The samples of a force profile as the body of an int16_t array initializer, 16 a line.
[[nodiscard]] std::string sample_initializer(const std::vector<int16_t>& samples, std::string_view indent);

}  // namespace feel::codegen
