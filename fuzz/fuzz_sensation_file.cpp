// libFuzzer target: sensation files must never crash the reader, and every file the
// reader accepts must survive writing and reading back unchanged.
//
//   parse(bytes) either throws FormatError or gives f, and then
//   parse(write(f)) == f               (the model survives a round trip)
//   write(parse(write(f))) == write(f) (the canonical text is a fixed point)
//
// Any other exception escapes and libFuzzer reports it; a mismatch aborts.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "feel/format/sensation_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace feel::format;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    SensationFile file;
    try {
        file = parse_sensation_file(text, "fuzz.json");
    } catch (const FormatError&) {
        return 0;  // rejected with a message: the expected outcome for most inputs
    }
    const std::string written = write_sensation_file(file);
    const SensationFile reread = parse_sensation_file(written, "fuzz-rewritten.json");
    if (!(reread == file)) {
        std::fprintf(stderr, "round trip changed the model; canonical text:\n%s\n", written.c_str());
        std::abort();
    }
    if (write_sensation_file(reread) != written) {
        std::fprintf(stderr, "canonical text is not a fixed point:\n%s\n", written.c_str());
        std::abort();
    }
    return 0;
}
