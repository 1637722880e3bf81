// The runtime's default loop period (1 kHz), the step the runtime tests advance their
// clocks by: one definition for every test file, so that the files of one test executable
// can be compiled together (unity builds, tests/CMakeLists.txt).
#pragma once

#include <cstdint>

namespace feel::test_support {

inline constexpr int64_t kTickUs = 1000;
inline constexpr double kTickS = 1e-3;

}  // namespace feel::test_support
