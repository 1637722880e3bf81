// libFuzzer target: arbitrary bytes as a DirectInput effect file (.ffe) must never crash the importer
// (src/import/ffe_import.cpp); what is checked is in import_round_trip.hpp.
#include "import_round_trip.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    return feel::fuzz::import_round_trip(data, size, [](std::string_view bytes) { return feel::import::import_ffe(bytes, {}); });
}
