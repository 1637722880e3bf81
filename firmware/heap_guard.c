/* No heap after start-up. The link wraps newlib's allocators (-Wl,--wrap=malloc, ...):
 * until heap_guard_lock() every request goes through and its size is counted; after it,
 * any request ends the program with status 3 and says so, so a test run proves that the
 * engine's tick never allocates on the device. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "heap_guard.h"

struct _reent;
void* __real_malloc(size_t size);
void* __real__malloc_r(struct _reent* r, size_t size);
void* __real_calloc(size_t n, size_t size);
void* __real__calloc_r(struct _reent* r, size_t n, size_t size);
void* __real_realloc(void* p, size_t size);
void* __real__realloc_r(struct _reent* r, void* p, size_t size);

static int locked;
static int depth;  /* newlib's malloc calls _malloc_r: count the outer request only */
static size_t requested;

static void check(size_t size) {
    if (locked) {
        fputs("heap_guard: an allocation after start-up\n", stderr);
        _exit(3);
    }
    if (depth == 0) requested += size;
}

void heap_guard_lock(void) { locked = 1; }
size_t heap_guard_requested_bytes(void) { return requested; }

#define GUARDED(call) \
    do {              \
        ++depth;      \
        void* p_ = (call); \
        --depth;      \
        return p_;    \
    } while (0)

void* __wrap_malloc(size_t size) { check(size); GUARDED(__real_malloc(size)); }
void* __wrap__malloc_r(struct _reent* r, size_t size) { check(size); GUARDED(__real__malloc_r(r, size)); }
void* __wrap_calloc(size_t n, size_t size) { check(n * size); GUARDED(__real_calloc(n, size)); }
void* __wrap__calloc_r(struct _reent* r, size_t n, size_t size) { check(n * size); GUARDED(__real__calloc_r(r, n, size)); }
void* __wrap_realloc(void* p, size_t size) { check(size); GUARDED(__real_realloc(p, size)); }
void* __wrap__realloc_r(struct _reent* r, void* p, size_t size) { check(size); GUARDED(__real__realloc_r(r, p, size)); }
