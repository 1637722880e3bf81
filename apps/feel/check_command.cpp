// feel check: validate a sensation file and list what it holds.
//
// Validation is the file reader's (format::load_sensation_file validates everything); this
// command only lays out the result as a table a person can scan.
#include <algorithm>
#include <optional>
#include <stdexcept>
#include <ostream>
#include <string>
#include <vector>

#include "check_device.hpp"
#include "cli.hpp"
#include "feel/effect_type.hpp"
#include "feel/format/sensation_file.hpp"
#include "feel/render/render.hpp"
#include "render_summary.hpp"

namespace feel::cli {
namespace {

std::string type_column(const format::Sensation& s) {
    if (s.compound) return "compound of " + std::to_string(s.effects.size());
    if (s.effects.empty()) return "empty";
    return std::string(effect_type_name(s.effects.front().params.type));
}

std::string duration_column(const format::Sensation& s) {
    const std::optional<int64_t> length = render::sensation_length_us(s);
    if (!length) return "endless";
    return format_seconds(static_cast<double>(*length) * 1e-6);
}

// The axes any effect of the sensation drives, in device order: "x,y".
std::string axes_column(const format::Sensation& s) {
    bool used[kMaxAxes] = {};
    for (const format::EffectSpec& e : s.effects) {
        for (int i = 0; i < e.params.axis_count && i < kMaxAxes; ++i) {
            used[axis_index(e.params.axes[i])] = true;
        }
    }
    std::string out;
    for (int a = 0; a < kMaxAxes; ++a) {
        if (!used[a]) continue;
        if (!out.empty()) out += ',';
        out += axis_name(static_cast<Axis>(a));
    }
    return out.empty() ? "-" : out;
}

// Each effect's trigger (§6.3) and repeat interval: "button 1 every 500 ms", "hat 2";
// in a compound, prefixed by the effect's index ("#1 button 4"); "-" when none has one.
std::string trigger_column(const format::Sensation& s) {
    std::string out;
    for (size_t i = 0; i < s.effects.size(); ++i) {
        const EffectParams& p = s.effects[i].params;
        if (p.trigger.kind == TriggerKind::none) continue;
        if (!out.empty()) out += ", ";
        if (s.compound) out += "#" + std::to_string(i) + " ";
        out += (p.trigger.kind == TriggerKind::hat ? "hat " : "button ") + std::to_string(p.trigger.index);
        if (p.trigger_repeat_interval_us > 0) {
            out += " every " + format_seconds(static_cast<double>(p.trigger_repeat_interval_us) * 1e-6);
        }
    }
    return out.empty() ? "-" : out;
}

}  // namespace

void run_check(const CheckArgs& args, std::ostream& out, std::ostream& /*err*/) {
    const format::SensationFile file = format::load_sensation_file(args.file);
    const size_t n = file.sensations.size();
    out << args.file << ": valid, " << n << (n == 1 ? " sensation\n" : " sensations\n");
    if (n == 0) return;  // nothing a device could refuse

    std::vector<std::vector<std::string>> table;
    table.push_back({"name", "type", "duration", "axes", "trigger", "description"});
    for (const format::Sensation& s : file.sensations) {
        table.push_back({s.name, type_column(s), duration_column(s), axes_column(s),
                         trigger_column(s), s.description.value_or("-")});
    }
    constexpr size_t kPadded = 5;  // every column but the description
    size_t width[kPadded] = {};
    for (const auto& row : table) {
        for (size_t c = 0; c < kPadded; ++c) width[c] = std::max(width[c], row[c].size());
    }
    for (const auto& row : table) {
        std::string line;
        for (size_t c = 0; c < kPadded; ++c) {
            line += row[c];
            line.append(width[c] - row[c].size() + 2, ' ');
        }
        line += row[kPadded];
        out << line << '\n';
    }
    if (!args.device.empty() && !check_on_device(args.file, file, args.device, out)) {
        throw std::runtime_error(args.file + ": some sensations do not play on " + args.device);
    }
}

}  // namespace feel::cli
