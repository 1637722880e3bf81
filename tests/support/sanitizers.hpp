// Whether this test binary runs under a sanitizer (make test-asan, make test-tsan), for
// the few tests that cannot hold there: memory figures (ASan's shadow memory and
// quarantine), memory locking (mlockall is a no-op under ASan and TSan), timing (both
// slow every instruction several times). Such a test skips, saying why.
#pragma once

namespace feel::test_support {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr const char* kSanitizer = "AddressSanitizer";
#elif defined(__SANITIZE_THREAD__)
inline constexpr const char* kSanitizer = "ThreadSanitizer";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr const char* kSanitizer = "AddressSanitizer";
#elif __has_feature(thread_sanitizer)
inline constexpr const char* kSanitizer = "ThreadSanitizer";
#else
inline constexpr const char* kSanitizer = nullptr;
#endif
#else
inline constexpr const char* kSanitizer = nullptr;
#endif

}  // namespace feel::test_support

// GTEST_SKIP()s the test under ASan or TSan; `why` says what the sanitizer breaks.
#define FEEL_SKIP_UNDER_SANITIZER(why)                                                          \
    do {                                                                                        \
        if (::feel::test_support::kSanitizer != nullptr) {                                      \
            GTEST_SKIP() << "under " << ::feel::test_support::kSanitizer << ": " << (why);      \
        }                                                                                       \
    } while (false)
