// The report table: every report feel's protocol knows, in one place (field_spec.hpp says
// how a report is described). Private to the protocol library (and its tests).
//
// The table is split by family, one file each: report_table_pid.cpp (the PID 1.0 output
// reports), report_table_vendor.cpp (feel's vendor output reports),
// report_table_feature.cpp and report_table_input.cpp. report_table.cpp puts them
// together and indexes them by id and by AnyReport alternative.
#pragma once

#include <cstdint>
#include <span>

#include "field_spec.hpp"

namespace feel::protocol::detail {

[[nodiscard]] std::span<const ReportSpec> pid_output_reports() noexcept;
[[nodiscard]] std::span<const ReportSpec> vendor_output_reports() noexcept;
[[nodiscard]] std::span<const ReportSpec> feature_reports() noexcept;
[[nodiscard]] std::span<const ReportSpec> input_reports() noexcept;

// All reports in descriptor order: outputs (PID, then vendor), features, inputs.
[[nodiscard]] std::span<const ReportSpec* const> all_reports() noexcept;

// The report with this id; nullptr if none.
[[nodiscard]] const ReportSpec* find_report(uint8_t id) noexcept;
// The report an AnyReport holds.
[[nodiscard]] const ReportSpec& report_of(const AnyReport& report) noexcept;

}  // namespace feel::protocol::detail
