/* No heap after start-up: see heap_guard.c. */
#pragma once
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif
void heap_guard_lock(void);                 /* from now on any allocation ends the run (status 3) */
size_t heap_guard_requested_bytes(void);    /* bytes requested before the lock */
#ifdef __cplusplus
}
#endif
