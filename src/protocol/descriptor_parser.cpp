// The HID report descriptor parser (descriptor_parser.hpp says what it accepts).
//
// One pass over the items. State, as HID 1.11 §6.2.2 defines it:
//   global  Usage Page, Logical/Physical Min/Max, Unit (Exponent), Report Size/ID/Count;
//           kept from item to item, saved and restored by Push/Pop;
//   local   Usages, Usage Minimum/Maximum, designators, strings; cleared by every main item;
//   main    Input/Output/Feature add a field to the report (kind, Report ID) at the report's
//           current bit length; Collection/End Collection nest.
// Every check that refuses the descriptor names the byte offset of the item at fault.
#include "feel/protocol/descriptor_parser.hpp"

#include <algorithm>
#include <optional>

namespace feel::protocol::hid {

const DescriptorReport* ParsedDescriptor::find(MainItemKind kind, uint8_t id) const noexcept {
    for (const DescriptorReport& r : reports) {
        if (r.kind == kind && r.id == id) return &r;
    }
    return nullptr;
}

namespace {

enum ItemType : uint8_t { kMain = 0, kGlobal = 1, kLocal = 2, kReserved = 3 };

// A limit's raw data, resolved against the minimum at the main item.
struct RawLimit {
    uint32_t unsigned_value = 0;
    int64_t signed_value = 0;
};

struct GlobalState {
    uint16_t usage_page = 0;
    int64_t logical_min = 0;
    RawLimit logical_max{};
    int64_t physical_min = 0;
    RawLimit physical_max{};
    bool physical_set = false;
    int32_t unit_exponent = 0;
    uint32_t unit = 0;
    uint32_t report_size = 0;
    uint32_t report_id = 0;
    uint32_t report_count = 0;
};

struct LocalState {
    std::vector<uint32_t> usages;
    std::optional<uint32_t> usage_minimum;  // extended
    std::optional<uint32_t> usage_maximum;
    bool in_delimiter = false;
    bool delimiter_has_usage = false;
};

class Parser {
public:
    explicit Parser(std::span<const uint8_t> bytes) : bytes_(bytes) {}

    DescriptorParse run() {
        DescriptorParse result;
        while (pos_ < bytes_.size() && error_.empty()) item();
        if (error_.empty()) finish();
        if (!error_.empty()) {
            result.error = "byte " + std::to_string(error_offset_) + ": " + error_;
            result.error_offset = error_offset_;
            return result;
        }
        result.descriptor = std::move(out_);
        return result;
    }

private:
    void fail(std::string message) {
        if (!error_.empty()) return;
        error_ = std::move(message);
        error_offset_ = item_start_;
    }

    void item() {
        item_start_ = pos_;
        const uint8_t prefix = bytes_[pos_];
        if (prefix == 0xFE) {
            fail("long item (0xFE): HID 1.11 defines none and this parser reads short items only");
            return;
        }
        static constexpr std::size_t kDataBytes[4] = {0, 1, 2, 4};
        const std::size_t size = kDataBytes[prefix & 0x03];
        const auto type = static_cast<ItemType>((prefix >> 2) & 0x03);
        const auto tag = static_cast<uint8_t>(prefix >> 4);
        if (bytes_.size() - pos_ - 1 < size) {
            fail("truncated item 0x" + hex(prefix) + ": needs " + std::to_string(size) +
                 " data byte(s), " + std::to_string(bytes_.size() - pos_ - 1) + " left");
            return;
        }
        uint32_t u = 0;
        for (std::size_t k = 0; k < size; ++k) u |= static_cast<uint32_t>(bytes_[pos_ + 1 + k]) << (8 * k);
        int64_t s = u;
        if (size > 0 && size < 4) {
            const uint32_t sign = 1u << (8 * size - 1);
            s = static_cast<int64_t>(u ^ sign) - static_cast<int64_t>(sign);
        } else if (size == 4) {
            s = static_cast<int32_t>(u);
        }
        pos_ += 1 + size;
        switch (type) {
            case kMain: main_item(tag, u); break;
            case kGlobal: global_item(tag, u, s, size); break;
            case kLocal: local_item(tag, u, size); break;
            case kReserved: fail("reserved item type 3 in item 0x" + hex(prefix)); break;
        }
    }

    // ---- main items ----

    void main_item(uint8_t tag, uint32_t data) {
        switch (tag) {
            case 0x8: data_item(MainItemKind::input, data); break;
            case 0x9: data_item(MainItemKind::output, data); break;
            case 0xB: data_item(MainItemKind::feature, data); break;
            case 0xA: collection(data); break;
            case 0xC: end_collection(); break;
            default: fail("reserved main item tag 0x" + hex(tag)); return;
        }
        local_ = LocalState{};
    }

    void collection(uint32_t type) {
        if (type >= 0x07 && type <= 0x7F) {
            fail("reserved collection type 0x" + hex(type));
            return;
        }
        if (type > 0xFF) {
            fail("collection type 0x" + hex(type) + " is wider than a byte");
            return;
        }
        if (collections_.size() >= static_cast<std::size_t>(kMaxCollectionDepth)) {
            fail("collections nested deeper than " + std::to_string(kMaxCollectionDepth));
            return;
        }
        if (!resolve_usage_range()) return;
        collections_.push_back(local_.usages.empty() ? 0 : local_.usages.front());
        collection_types_.push_back(static_cast<uint8_t>(type));
    }

    void end_collection() {
        if (collections_.empty()) {
            fail("End Collection without an open Collection");
            return;
        }
        collections_.pop_back();
        collection_types_.pop_back();
    }

    void data_item(MainItemKind kind, uint32_t flags) {
        const GlobalState& g = global_;
        if (g.report_size == 0) return fail("Report Size 0 (or never set) at a main item");
        if (g.report_size > kMaxReportSizeBits) {
            return fail("Report Size " + std::to_string(g.report_size) + " exceeds " +
                        std::to_string(kMaxReportSizeBits) + " bits");
        }
        if (g.report_count == 0) return fail("Report Count 0 (or never set) at a main item");
        if (g.report_count > kMaxReportCount) {
            return fail("Report Count " + std::to_string(g.report_count) + " exceeds " +
                        std::to_string(kMaxReportCount));
        }
        if (out_.uses_report_ids && g.report_id == 0) {
            return fail("main item without a Report ID in a descriptor that uses Report IDs");
        }
        if (!resolve_usage_range()) return;

        DescriptorField field;
        field.report_size = g.report_size;
        field.report_count = g.report_count;
        field.flags = flags;
        field.usages = std::move(local_.usages);
        field.logical_min = g.logical_min;
        field.logical_max = resolve(g.logical_max, g.logical_min);
        field.physical_min = g.physical_set ? g.physical_min : field.logical_min;
        field.physical_max = g.physical_set ? resolve(g.physical_max, g.physical_min) : field.logical_max;
        field.unit = g.unit;
        field.unit_exponent = g.unit_exponent;
        field.collections = collections_;
        field.collection_types = collection_types_;
        if (!field.is_constant() && field.logical_min > field.logical_max) {
            return fail("Logical Minimum " + std::to_string(field.logical_min) +
                        " is greater than Logical Maximum " + std::to_string(field.logical_max));
        }
        if (++field_total_ > kMaxFields) return fail("more than " + std::to_string(kMaxFields) + " fields");

        DescriptorReport& report = report_for(kind, static_cast<uint8_t>(g.report_id));
        const uint64_t end = uint64_t{report.bit_length} + uint64_t{field.report_size} * field.report_count;
        if (end > kMaxReportBits) {
            return fail("report " + std::to_string(g.report_id) + " grows beyond " +
                        std::to_string(kMaxReportBits / 8) + " bytes");
        }
        field.bit_offset = report.bit_length;
        report.bit_length = static_cast<uint32_t>(end);
        report.fields.push_back(std::move(field));
    }

    DescriptorReport& report_for(MainItemKind kind, uint8_t id) {
        for (DescriptorReport& r : out_.reports) {
            if (r.kind == kind && r.id == id) return r;
        }
        DescriptorReport& r = out_.reports.emplace_back();
        r.kind = kind;
        r.id = id;
        return r;
    }

    static int64_t resolve(const RawLimit& max, int64_t min) noexcept {
        return min < 0 ? max.signed_value : static_cast<int64_t>(max.unsigned_value);
    }

    // Expands a pending Usage Minimum..Maximum into the usage list.
    bool resolve_usage_range() {
        if (!local_.usage_minimum && !local_.usage_maximum) return true;
        if (!local_.usage_minimum || !local_.usage_maximum) {
            fail(local_.usage_minimum ? "Usage Minimum without Usage Maximum"
                                      : "Usage Maximum without Usage Minimum");
            return false;
        }
        const uint32_t lo = *local_.usage_minimum, hi = *local_.usage_maximum;
        if ((lo >> 16) != (hi >> 16)) {
            fail("Usage Minimum and Maximum on different usage pages");
            return false;
        }
        if (lo > hi) {
            fail("Usage Minimum 0x" + hex(lo & 0xFFFF) + " is greater than Usage Maximum 0x" + hex(hi & 0xFFFF));
            return false;
        }
        const std::size_t n = static_cast<std::size_t>(hi - lo) + 1;
        if (!add_usages(n)) return false;
        for (uint32_t u = lo;; ++u) {
            local_.usages.push_back(u);
            if (u == hi) break;
        }
        local_.usage_minimum.reset();
        local_.usage_maximum.reset();
        return true;
    }

    bool add_usages(std::size_t n) {
        if (local_.usages.size() + n > kMaxUsagesPerItem) {
            fail("more than " + std::to_string(kMaxUsagesPerItem) + " usages for one item");
            return false;
        }
        usage_total_ += n;
        if (usage_total_ > kMaxUsagesTotal) {
            fail("more than " + std::to_string(kMaxUsagesTotal) + " usages in the descriptor");
            return false;
        }
        return true;
    }

    // ---- global items ----

    void global_item(uint8_t tag, uint32_t u, int64_t s, std::size_t size) {
        GlobalState& g = global_;
        switch (tag) {
            case 0x0:
                if (u > 0xFFFF) return fail("Usage Page 0x" + hex(u) + " is wider than 16 bits");
                g.usage_page = static_cast<uint16_t>(u);
                break;
            case 0x1: g.logical_min = s; break;
            case 0x2: g.logical_max = RawLimit{u, s}; break;
            case 0x3: g.physical_min = s; g.physical_set = true; break;
            case 0x4: g.physical_max = RawLimit{u, s}; g.physical_set = true; break;
            case 0x5:  // a nibble 0..15 is 4-bit two's complement; wider data is a plain value
                g.unit_exponent = u <= 0xF ? static_cast<int32_t>(u) - (u >= 8 ? 16 : 0)
                                           : static_cast<int32_t>(s);
                break;
            case 0x6: g.unit = u; break;
            case 0x7: g.report_size = u; break;
            case 0x8:
                if (size == 0 || u == 0) return fail("Report ID 0 is reserved");
                if (u > 0xFF) return fail("Report ID " + std::to_string(u) + " is wider than a byte");
                if (!out_.uses_report_ids && !out_.reports.empty()) {
                    return fail("Report ID after main items that had none");
                }
                g.report_id = u;
                out_.uses_report_ids = true;
                break;
            case 0x9: g.report_count = u; break;
            case 0xA:
                if (pushed_.size() >= static_cast<std::size_t>(kMaxPushDepth)) {
                    return fail("Push nested deeper than " + std::to_string(kMaxPushDepth));
                }
                pushed_.push_back(g);
                break;
            case 0xB:
                if (pushed_.empty()) return fail("Pop without a Push");
                g = pushed_.back();
                pushed_.pop_back();
                break;
            default: fail("reserved global item tag 0x" + hex(tag)); break;
        }
    }

    // ---- local items ----

    uint32_t extended_usage(uint32_t u, std::size_t size) const noexcept {
        return size == 4 ? u : (static_cast<uint32_t>(global_.usage_page) << 16 | (u & 0xFFFF));
    }

    void local_item(uint8_t tag, uint32_t u, std::size_t size) {
        switch (tag) {
            case 0x0:  // Usage
                if (local_.in_delimiter) {
                    if (local_.delimiter_has_usage) return;  // alternatives after the first
                    local_.delimiter_has_usage = true;
                }
                if (!add_usages(1)) return;
                local_.usages.push_back(extended_usage(u, size));
                break;
            case 0x1:
                if (local_.usage_minimum) return fail("Usage Minimum twice before its Usage Maximum");
                local_.usage_minimum = extended_usage(u, size);
                if (local_.usage_maximum) resolve_usage_range();
                break;
            case 0x2:
                if (local_.usage_maximum) return fail("Usage Maximum twice before its Usage Minimum");
                local_.usage_maximum = extended_usage(u, size);
                if (local_.usage_minimum) resolve_usage_range();
                break;
            case 0x3: case 0x4: case 0x5:  // designators: body parts, not needed for reports
            case 0x7: case 0x8: case 0x9:  // string indexes
                break;
            case 0xA:  // Delimiter
                if (u == 1) {
                    if (local_.in_delimiter) return fail("Delimiter open inside an open Delimiter set");
                    local_.in_delimiter = true;
                    local_.delimiter_has_usage = false;
                } else if (u == 0) {
                    if (!local_.in_delimiter) return fail("Delimiter close without an open set");
                    local_.in_delimiter = false;
                } else {
                    return fail("Delimiter data " + std::to_string(u) + " is neither 1 (open) nor 0 (close)");
                }
                break;
            default: fail("reserved local item tag 0x" + hex(tag)); break;
        }
    }

    void finish() {
        item_start_ = bytes_.size();
        if (!collections_.empty()) {
            return fail(std::to_string(collections_.size()) + " collection(s) left open at the end");
        }
        if (!pushed_.empty()) return fail(std::to_string(pushed_.size()) + " Push(es) without a Pop at the end");
        if (local_.in_delimiter) return fail("Delimiter set left open at the end");
    }

    static std::string hex(uint32_t v) {
        static constexpr char kDigits[] = "0123456789ABCDEF";
        std::string s;
        do {
            s.insert(s.begin(), kDigits[v & 0xF]);
            v >>= 4;
        } while (v != 0);
        if (s.size() % 2 != 0) s.insert(s.begin(), '0');
        return s;
    }

    std::span<const uint8_t> bytes_;
    std::size_t pos_ = 0;
    std::size_t item_start_ = 0;
    std::string error_;
    std::size_t error_offset_ = 0;
    GlobalState global_{};
    std::vector<GlobalState> pushed_;
    LocalState local_{};
    std::vector<uint32_t> collections_;
    std::vector<uint8_t> collection_types_;  // alongside collections_
    std::size_t field_total_ = 0;
    std::size_t usage_total_ = 0;
    ParsedDescriptor out_;
};

}  // namespace

DescriptorParse parse_report_descriptor(std::span<const uint8_t> bytes) {
    return Parser(bytes).run();
}

}  // namespace feel::protocol::hid
