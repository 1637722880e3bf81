// Live progress output (live_output.hpp).
#include "live_output.hpp"

#include <ostream>

namespace feel::cli {

void LiveLine::show(const std::string& line) {
    if (line == last_) return;
    last_ = line;
    if (!terminal_) {
        out_ << line << '\n' << std::flush;
        return;
    }
    out_ << '\r' << line;
    // Blank out the tail of a longer previous line.
    for (std::size_t i = line.size(); i < shown_; ++i) out_ << ' ';
    out_ << std::flush;
    shown_ = line.size();
    open_ = true;
}

void LiveLine::finish() {
    if (terminal_ && open_) out_ << '\n' << std::flush;
    open_ = false;
    shown_ = 0;
}

void LiveBlock::show(const std::vector<std::string>& lines) {
    if (terminal_ && shown_ > 0) out_ << "\x1b[" << shown_ << "F\x1b[J";
    for (const std::string& line : lines) out_ << line << '\n';
    if (!terminal_) out_ << '\n';
    out_ << std::flush;
    shown_ = lines.size();
}

}  // namespace feel::cli
