// feel::studio — files built into the feel binary: the front end (studio/dist, built by
// Vite at build time) and the data the Studio offers (the example sensation files, the
// palette's starter effects). The build turns each file into a byte array of a generated
// .cpp (src/studio/embed_assets.cmake), so running the Studio needs no Node and no files.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace feel::studio {

struct Asset {
    std::string_view path;  // web assets: "/index.html", "/assets/index-1234.js"; data: "examples/primer.feel.json"
    const unsigned char* bytes;
    size_t size;
    [[nodiscard]] std::string_view text() const noexcept {
        return {reinterpret_cast<const char*>(bytes), size};
    }
};

[[nodiscard]] std::span<const Asset> web_assets() noexcept;
[[nodiscard]] std::span<const Asset> data_assets() noexcept;
[[nodiscard]] const Asset* find_web_asset(std::string_view path) noexcept;
[[nodiscard]] const Asset* find_data_asset(std::string_view path) noexcept;

}  // namespace feel::studio
