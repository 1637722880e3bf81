// feel.h: the library's version (feel/version.h, generated from the project's version).
#include "capi_internal.hpp"
#include "feel/version.h"

extern "C" {

uint32_t feel_version(void) { return FEEL_VERSION; }

const char* feel_version_string(void) { return FEEL_VERSION_STRING; }

}  // extern "C"
