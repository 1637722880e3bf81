// Live progress output: one line (feel play, feel stream) or one block of lines (feel
// monitor) that is redrawn in place on a terminal, and printed anew each time otherwise.
//
// On a terminal, a progress line is rewritten with a carriage return and a block is
// redrawn by moving the cursor back up over it (ANSI "cursor previous line" and "erase
// below", which every terminal emulator in use understands). Into a pipe or a file those
// codes would be noise, so there each update is plain text: a line per update, and a
// block followed by an empty line. Tests read the plain form.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

namespace feel::cli {

class LiveLine {
public:
    LiveLine(std::ostream& out, bool terminal) : out_(out), terminal_(terminal) {}
    // Shows `line` as the current progress (nothing new when it is the line shown).
    void show(const std::string& line);
    // Ends the live line (a newline after the last one on a terminal). Harmless twice.
    void finish();

private:
    std::ostream& out_;
    bool terminal_;
    std::size_t shown_ = 0;  // length of the line on screen (terminal)
    bool open_ = false;      // a line is on screen without its newline
    std::string last_;       // the line shown last
};

class LiveBlock {
public:
    LiveBlock(std::ostream& out, bool terminal) : out_(out), terminal_(terminal) {}
    // Shows `lines` in place of the previous block.
    void show(const std::vector<std::string>& lines);

private:
    std::ostream& out_;
    bool terminal_;
    std::size_t shown_ = 0;  // lines of the block on screen (terminal)
};

}  // namespace feel::cli
