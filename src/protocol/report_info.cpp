// What the table says about a report: its id, kind, name and size.
#include <algorithm>

#include "feel/protocol/codec.hpp"
#include "report_table.hpp"

namespace feel::protocol {

ReportId report_id_of(const AnyReport& report) noexcept { return detail::report_of(report).id; }

std::optional<ReportKind> report_kind(uint8_t id) noexcept {
    const detail::ReportSpec* spec = detail::find_report(id);
    if (spec == nullptr) return std::nullopt;
    return spec->kind;
}

std::string_view report_name(ReportId id) noexcept {
    const detail::ReportSpec* spec = detail::find_report(static_cast<uint8_t>(id));
    return spec == nullptr ? std::string_view{} : spec->name;
}

std::size_t report_size(uint8_t id) noexcept {
    const detail::ReportSpec* spec = detail::find_report(id);
    return spec == nullptr ? 0 : spec->size();
}

std::size_t max_report_size() noexcept {
    static const std::size_t largest = [] {
        std::size_t n = 0;
        for (const detail::ReportSpec* spec : detail::all_reports()) n = std::max(n, spec->size());
        return n;
    }();
    return largest;
}

}  // namespace feel::protocol
