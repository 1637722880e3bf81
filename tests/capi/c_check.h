/* The C tests' one check macro: prints "ok" or "FAIL" and what was checked; main returns
 * c_check_failures != 0. */
#ifndef FEEL_TESTS_CAPI_C_CHECK_H
#define FEEL_TESTS_CAPI_C_CHECK_H

#include <stdio.h>

static int c_check_failures = 0;

#define CHECK(cond, ...)                                        \
    do {                                                        \
        if (cond) {                                             \
            printf("ok    ");                                   \
        } else {                                                \
            printf("FAIL  ");                                   \
            ++c_check_failures;                                 \
        }                                                       \
        printf(__VA_ARGS__);                                    \
        printf("\n");                                           \
    } while (0)

#endif
