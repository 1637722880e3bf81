// What both import fuzz targets check (fuzz_ffe_import, fuzz_ahap_import): arbitrary bytes
// never crash an importer: it either throws ImportError with a message or gives a
// sensation, and every sensation it gives can be written and read back with the same
// parameters and samples (the reader also records which optional fields the text spelled
// out, which the importer leaves empty, so whole models are not compared).
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "feel/format/sensation_file.hpp"
#include "feel/import/import.hpp"

namespace feel::fuzz {

template <typename Importer>
int import_round_trip(const uint8_t* data, size_t size, Importer import) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    feel::import::ImportResult result;
    try {
        result = import(bytes);
    } catch (const feel::import::ImportError& e) {
        if (std::string_view(e.what()).empty()) std::abort();  // every refusal says why
        return 0;
    }
    feel::format::SensationFile file;
    file.sensations.push_back(result.sensation);
    const std::string text = feel::format::write_sensation_file(file);
    const feel::format::SensationFile back = feel::format::parse_sensation_file(text, "fuzz.json");
    bool same = back.sensations.size() == 1 && back.sensations[0].effects.size() == result.sensation.effects.size();
    for (size_t i = 0; same && i < result.sensation.effects.size(); ++i) {
        same = back.sensations[0].effects[i].params == result.sensation.effects[i].params &&
               back.sensations[0].effects[i].samples == result.sensation.effects[i].samples;
    }
    if (!same) {
        std::fprintf(stderr, "the imported sensation does not survive a round trip:\n%s\n", text.c_str());
        std::abort();
    }
    return 0;
}

}  // namespace feel::fuzz
