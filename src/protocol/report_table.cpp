// The report table put together: every family's reports in descriptor order, indexed by
// report id (one lookup per decoded report) and by AnyReport alternative (one per encode).
#include "report_table.hpp"

#include <array>
#include <variant>

namespace feel::protocol::detail {
namespace {

constexpr std::size_t kReportCount = std::variant_size_v<AnyReport>;

struct Index {
    std::array<const ReportSpec*, kReportCount> in_order{};
    std::array<const ReportSpec*, 256> by_id{};
    std::array<const ReportSpec*, kReportCount> by_alternative{};
};

Index build_index() noexcept {
    Index index;
    std::size_t n = 0;
    for (auto family : {pid_output_reports(), vendor_output_reports(), feature_reports(),
                        input_reports()}) {
        for (const ReportSpec& spec : family) {
            index.in_order[n++] = &spec;
            index.by_id[static_cast<uint8_t>(spec.id)] = &spec;
            index.by_alternative[spec.variant_index] = &spec;
        }
    }
    return index;
}

const Index& index() noexcept {
    static const Index built = build_index();  // constant tables: built once, never changed
    return built;
}

}  // namespace

std::span<const ReportSpec* const> all_reports() noexcept { return index().in_order; }

const ReportSpec* find_report(uint8_t id) noexcept { return index().by_id[id]; }

const ReportSpec& report_of(const AnyReport& report) noexcept {
    return *index().by_alternative[report.index()];
}

}  // namespace feel::protocol::detail
