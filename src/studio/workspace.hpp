// feel::studio — the workspace: the one folder whose sensation files the Studio reads and
// writes (§9.3 "standard file handling").
//
// Every path a browser sends is relative to the workspace and is checked before anything
// touches the disk (docs/studio.md, "Safety"):
//   * it is 1..kMaxPathLength characters of letters, digits and "_-. /", names a
//     "*.feel.json" file, and no component is empty, "." or "..";
//   * an absolute path is refused;
//   * after symlinks are resolved, the file (or, for a new file, its folder) still lies
//     inside the workspace: a symlink that leads out is refused;
//   * files are at most kMaxFileBytes; what is saved must be a valid feel/1 file (the
//     format's reader checks it) and is written in the format's canonical form, through a
//     temporary file and a rename so a crash never leaves half a file.
// Refusals throw WorkspaceError with a sentence naming the path and the rule; a file that
// is not there, WorkspaceFileMissing.
#pragma once

#include <cstddef>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace feel::studio {

class WorkspaceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A well-formed path inside the workspace that names no file (the server answers 404, not
// 403: nothing was refused, e.g. favorites.feel.json before the first favorite is saved).
class WorkspaceFileMissing : public WorkspaceError {
public:
    using WorkspaceError::WorkspaceError;
};

inline constexpr size_t kMaxPathLength = 200;
inline constexpr size_t kMaxFileBytes = 1u << 20;  // 1 MiB: far beyond any designed sensation
inline constexpr size_t kMaxListedFiles = 1000;

class Workspace {
public:
    // Throws WorkspaceError if `root` is not an existing folder.
    explicit Workspace(const std::filesystem::path& root);

    [[nodiscard]] const std::filesystem::path& root() const noexcept { return root_; }
    // The *.feel.json files under the workspace (symlinks that lead out are left out),
    // relative, sorted; at most kMaxListedFiles, folders at most 4 deep.
    [[nodiscard]] std::vector<std::string> list() const;
    // The file's text. Refused: a bad path, a missing file, a file over kMaxFileBytes.
    [[nodiscard]] std::string read(std::string_view relative) const;
    // Checks `text` with the format's reader, writes its canonical form and returns it.
    // overwrite=false refuses an existing file (save as, copy, combine).
    std::string save(std::string_view relative, std::string_view text, bool overwrite);
    // Renames a file; refuses to replace an existing one.
    void rename(std::string_view from, std::string_view to);
    // The sensations of several files in one new file; a name that appears twice is
    // refused, naming it and both files.
    std::string combine(const std::vector<std::string>& sources, std::string_view to);

    // The absolute path of a checked relative path: what every operation above uses.
    // must_exist=false allows a new file whose folder exists inside the workspace.
    [[nodiscard]] std::filesystem::path resolve(std::string_view relative, bool must_exist) const;

private:
    std::filesystem::path root_;  // canonical
};

}  // namespace feel::studio
