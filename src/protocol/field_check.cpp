#include "field_check.hpp"

#include <string_view>

namespace feel::protocol::detail {
namespace {

// Appends to a fixed buffer, keeping the terminating NUL.
struct NameWriter {
    char (&out)[48];
    std::size_t n = 0;

    void put(char c) noexcept {
        if (n + 1 < sizeof out) out[n++] = c;
        out[n] = '\0';
    }
    void put(std::string_view s) noexcept {
        for (char c : s) put(c);
    }
    void put_number(int v) noexcept {
        char digits[12];
        int k = 0;
        do {
            digits[k++] = static_cast<char>('0' + v % 10);
            v /= 10;
        } while (v > 0 && k < 12);
        while (k > 0) put(digits[--k]);
    }
};

}  // namespace

void field_name(const ReportSpec& report, const FieldSpec& field, int index, char (&out)[48]) noexcept {
    NameWriter w{out};
    out[0] = '\0';
    w.put(report.key);
    w.put('.');
    const std::string_view path = field.path;
    for (std::size_t k = 0; k < path.size(); ++k) {
        if (path.substr(k, 3) == "[i]") {
            w.put('[');
            w.put_number(index);
            w.put(']');
            k += 2;
        } else {
            w.put(path[k]);
        }
    }
}

Error check_field(const ReportSpec& report, const FieldSpec& field, int index,
                  int64_t value) noexcept {
    if (field.bits >= 64) return {};  // every pattern is a value
    if (field.has_null() && value == field.null_value()) return {};
    if (field.range.contains(value) && (field.valid == nullptr || field.valid(value))) return {};
    char name[48];
    field_name(report, field, index, name);
    if (!field.range.contains(value)) return Error::out_of_range(name, value, field.range);
    Error e = Error::invalid(name, field.invalid_rule);
    e.value = value;
    return e;
}

}  // namespace feel::protocol::detail
