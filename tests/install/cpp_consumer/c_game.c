/* The C ABI through CMake's feel::c target: the library's version is the headers'. */
#include <stdio.h>

#include "feel/feel.h"

int main(void) {
    printf("libfeel %s, headers %s\n", feel_version_string(), FEEL_VERSION_STRING);
    return feel_version() == FEEL_VERSION ? 0 : 1;
}
