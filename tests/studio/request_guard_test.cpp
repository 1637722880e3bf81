// Host and Origin checks (request_guard.hpp): DNS rebinding and other sites' pages.
#include <gtest/gtest.h>

#include "request_guard.hpp"

namespace feel::studio {
namespace {

TEST(RequestGuard, AcceptsTheServersOwnNamesWithAndWithoutOrigin) {
    const RequestGuard g("127.0.0.1", 8750);
    EXPECT_FALSE(g.refusal("127.0.0.1:8750", std::nullopt));
    EXPECT_FALSE(g.refusal("localhost:8750", std::string_view("http://localhost:8750")));
    EXPECT_FALSE(g.refusal("LOCALHOST:8750", std::string_view("http://127.0.0.1:8750")));
    EXPECT_FALSE(g.refusal("[::1]:8750", std::string_view("http://[::1]:8750")));
}

TEST(RequestGuard, RefusesARebindingHostName) {
    const RequestGuard g("127.0.0.1", 8750);
    auto r = g.refusal("attacker.example:8750", std::nullopt);
    ASSERT_TRUE(r);
    EXPECT_NE(r->find("DNS rebinding"), std::string::npos) << *r;
    EXPECT_TRUE(g.refusal("127.0.0.1:8751", std::nullopt));  // another port is another origin
    EXPECT_TRUE(g.refusal("127.0.0.1", std::nullopt));       // no port
    EXPECT_TRUE(g.refusal("", std::nullopt));                // no Host at all
}

TEST(RequestGuard, RefusesOtherSitesOrigins) {
    const RequestGuard g("127.0.0.1", 8750);
    for (std::string_view o : {"http://evil.example", "https://127.0.0.1:8750", "http://127.0.0.1:8750.evil.example",
                               "null", "http://127.0.0.1:9999", ""}) {
        auto r = g.refusal("127.0.0.1:8750", o);
        ASSERT_TRUE(r) << o;
        EXPECT_NE(r->find("Origin"), std::string::npos) << *r;
    }
}

TEST(RequestGuard, AListenAddressIsOneMoreName) {
    const RequestGuard g("192.168.1.5", 8750);
    EXPECT_FALSE(g.refusal("192.168.1.5:8750", std::string_view("http://192.168.1.5:8750")));
    EXPECT_TRUE(g.refusal("192.168.1.6:8750", std::nullopt));
}

}  // namespace
}  // namespace feel::studio
