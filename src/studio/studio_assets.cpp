// Lookup in the embedded asset tables (studio_assets.hpp); the tables are generated.
#include "studio_assets.hpp"

namespace feel::studio {
namespace {

const Asset* find_in(std::span<const Asset> table, std::string_view path) noexcept {
    for (const Asset& a : table) {
        if (a.path == path) return &a;
    }
    return nullptr;
}

}  // namespace

const Asset* find_web_asset(std::string_view path) noexcept { return find_in(web_assets(), path); }
const Asset* find_data_asset(std::string_view path) noexcept { return find_in(data_assets(), path); }

}  // namespace feel::studio
