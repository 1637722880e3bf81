// Helpers for the §8 wrapper tests.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

#include "feel/effect_validation.hpp"

namespace feel::iforce::test {

// The engine's validator accepts the effect (every wrapper's output must pass it).
inline ::testing::AssertionResult engine_accepts(const EffectParams& p) {
    const Error e = validate_effect(p);
    if (e.ok()) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "validate_effect refused it: " << e.message();
}

// The call throws std::invalid_argument whose message is exactly `expected`.
inline ::testing::AssertionResult throws_message(const std::function<void()>& call, const std::string& expected) {
    try {
        call();
    } catch (const std::invalid_argument& e) {
        if (expected == e.what()) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "message was \"" << e.what() << "\", expected \"" << expected << '"';
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure() << "threw another exception: " << e.what();
    }
    return ::testing::AssertionFailure() << "did not throw; expected \"" << expected << '"';
}

// The call throws std::invalid_argument whose message starts with `prefix`.
inline ::testing::AssertionResult throws_starting(const std::function<void()>& call, const std::string& prefix) {
    try {
        call();
    } catch (const std::invalid_argument& e) {
        if (std::string(e.what()).starts_with(prefix)) return ::testing::AssertionSuccess();
        return ::testing::AssertionFailure() << "message was \"" << e.what() << "\", expected it to start with \""
                                             << prefix << '"';
    }
    return ::testing::AssertionFailure() << "did not throw; expected \"" << prefix << "...\"";
}

}  // namespace feel::iforce::test
