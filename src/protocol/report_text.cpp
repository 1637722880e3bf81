// describe_report(): walks the report table (field_spec.hpp), as encode() does, and prints
// each element instead of writing its bits. Text fields (NUL-padded char arrays) print as
// one quoted string; a named array's value is followed by the usage it selects.
#include "feel/protocol/report_text.hpp"

#include <cstdio>
#include <string_view>

#include "report_table.hpp"

namespace feel::protocol {
namespace {

std::string element_path(std::string_view path, int index) {
    std::string out(path);
    const std::size_t at = out.find("[i]");
    if (at != std::string::npos) out.replace(at, 3, "[" + std::to_string(index) + "]");
    return out;
}

}  // namespace

std::string describe_report(const AnyReport& report) {
    const detail::ReportSpec& spec = detail::report_of(report);
    const void* fields = std::visit([](const auto& r) -> const void* { return &r; }, report);
    std::string out(spec.key);
    for (const detail::FieldSpec& field : spec.fields) {
        const bool text = field.bits == 8 && field.count > 1 && field.range.min == 0 && field.range.max == 255;
        if (text) {
            std::string s;
            for (int i = 0; i < field.count; ++i) {
                const auto c = static_cast<char>(field.get(fields, i));
                if (c == '\0') break;
                s += c;
            }
            std::string path(field.path);
            if (const std::size_t at = path.find("[i]"); at != std::string::npos) path.erase(at);
            out += " " + path + "=\"" + s + "\"";
            continue;
        }
        for (int i = 0; i < field.count; ++i) {
            const int64_t value = field.get(fields, i);
            out += " " + element_path(field.path, i) + "=" + std::to_string(value);
            // A named array's value selects a usage: print the usage too (its low 16 bits,
            // the usage ID on its page), so that a log reads against the PID usage tables.
            const int64_t selected = value - field.range.min;
            if (field.named_array != 0 && selected >= 0 &&
                selected < static_cast<int64_t>(field.usage_list.size())) {
                char usage[16];
                std::snprintf(usage, sizeof usage, "0x%02X",
                              static_cast<unsigned>(field.usage_list[static_cast<std::size_t>(selected)] & 0xFFFF));
                out += " " + element_path(field.path, i) + "_usage=" + usage;
            }
        }
    }
    return out;
}

}  // namespace feel::protocol
