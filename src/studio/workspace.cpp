// The workspace's path rules and file operations (workspace.hpp).
#include "workspace.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <unistd.h>

#include "feel/format/sensation_file.hpp"

namespace feel::studio {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kSuffix = ".feel.json";

std::string shown_path(std::string_view s) {
    std::string out = "\"";
    for (char c : s) {
        if (static_cast<unsigned char>(c) < 0x20 || c == '"' || c == '\\') {
            out += '?';
        } else {
            out += c;
        }
    }
    return out + "\"";
}

[[noreturn]] void refuse(std::string_view path, const std::string& why) {
    throw WorkspaceError("path " + shown_path(path) + ": " + why);
}

// The rules that need no disk: characters, shape, components.
void check_spelling(std::string_view path) {
    if (path.empty()) refuse(path, "empty (give a file name such as my.feel.json)");
    if (path.size() > kMaxPathLength) {
        refuse(path.substr(0, 40), "longer than " + std::to_string(kMaxPathLength) + " characters");
    }
    if (path.front() == '/') refuse(path, "absolute paths are refused: give a path inside the workspace");
    for (char c : path) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        c == '_' || c == '-' || c == '.' || c == '/' || c == ' ';
        if (!ok) refuse(path, "only letters, digits, '_', '-', '.', ' ' and '/' are allowed");
    }
    size_t start = 0;
    for (;;) {
        const size_t end = path.find('/', start);
        const std::string_view part = path.substr(start, end == std::string_view::npos ? path.npos : end - start);
        if (part.empty() || part == "." || part == "..") {
            refuse(path, "'..', '.' and empty components are refused: the file must stay inside the workspace");
        }
        if (end == std::string_view::npos) break;
        start = end + 1;
    }
    if (path.size() <= kSuffix.size() || !path.ends_with(kSuffix)) {
        refuse(path, "the Studio reads and writes only sensation files named *.feel.json");
    }
}

bool inside(const fs::path& root, const fs::path& p) {
    const auto [r, q] = std::mismatch(root.begin(), root.end(), p.begin(), p.end());
    return r == root.end();
}

std::string read_all(const fs::path& file, std::string_view shown) {
    std::error_code ec;
    const auto size = fs::file_size(file, ec);
    if (ec) refuse(shown, "cannot be read: " + ec.message());
    if (size > kMaxFileBytes) {
        refuse(shown, "is " + std::to_string(size) + " bytes, more than the Studio's limit of " +
                          std::to_string(kMaxFileBytes));
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) refuse(shown, "cannot be opened");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

Workspace::Workspace(const fs::path& root) {
    std::error_code ec;
    root_ = fs::canonical(root, ec);
    if (ec || !fs::is_directory(root_)) {
        throw WorkspaceError("workspace " + shown_path(root.string()) + " is not an existing folder");
    }
}

fs::path Workspace::resolve(std::string_view relative, bool must_exist) const {
    check_spelling(relative);
    const fs::path joined = root_ / fs::path(std::string(relative));
    std::error_code ec;
    if (fs::exists(fs::symlink_status(joined, ec))) {
        const fs::path real = fs::canonical(joined, ec);
        if (ec) refuse(relative, "cannot be resolved: " + ec.message());
        if (!inside(root_, real)) refuse(relative, "is a symbolic link that leads out of the workspace");
        if (!fs::is_regular_file(real)) refuse(relative, "is not a regular file");
        return real;
    }
    const auto missing = [&] {
        throw WorkspaceFileMissing("path " + shown_path(relative) + ": no such file in the workspace");
    };
    const fs::path folder = fs::canonical(joined.parent_path(), ec);
    if (ec) {
        if (must_exist) missing();
        refuse(relative, "its folder does not exist in the workspace");
    }
    // A folder that leads out is refused before anything is said about what is in it.
    if (!inside(root_, folder)) refuse(relative, "its folder is a symbolic link that leads out of the workspace");
    if (must_exist) missing();
    return folder / joined.filename();
}

std::vector<std::string> Workspace::list() const {
    std::vector<std::string> out;
    std::error_code ec;
    fs::recursive_directory_iterator it(root_, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end && out.size() < kMaxListedFiles; it.increment(ec)) {
        if (it.depth() >= 4) it.disable_recursion_pending();
        const std::string name = it->path().filename().string();
        if (!name.empty() && name.front() == '.') {
            if (it->is_directory(ec)) it.disable_recursion_pending();
            continue;
        }
        if (!name.ends_with(kSuffix)) continue;
        const std::string rel = fs::relative(it->path(), root_, ec).generic_string();
        try {
            (void)resolve(rel, true);  // leaves out links that lead out, odd names
            out.push_back(rel);
        } catch (const WorkspaceError&) {
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

std::string Workspace::read(std::string_view relative) const {
    return read_all(resolve(relative, true), relative);
}

std::string Workspace::save(std::string_view relative, std::string_view text, bool overwrite) {
    if (text.size() > kMaxFileBytes) {
        refuse(relative, "the file would be " + std::to_string(text.size()) + " bytes, more than the limit of " +
                             std::to_string(kMaxFileBytes));
    }
    const fs::path target = resolve(relative, false);
    std::error_code ec;
    if (!overwrite && fs::exists(target, ec)) refuse(relative, "already exists (choose another name)");
    // The format's reader is the judge: a file the Studio writes always loads.
    const std::string canonical =
        format::write_sensation_file(format::parse_sensation_file(text, std::string(relative)));
    const fs::path temporary = target.parent_path() / ("." + target.filename().string() + ".tmp" +
                                                       std::to_string(::getpid()));
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << canonical;
        out.close();
        if (!out) {
            fs::remove(temporary, ec);
            refuse(relative, "cannot be written");
        }
    }
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        refuse(relative, "cannot be written: " + ec.message());
    }
    return canonical;
}

void Workspace::rename(std::string_view from, std::string_view to) {
    const fs::path source = resolve(from, true);
    const fs::path target = resolve(to, false);
    std::error_code ec;
    if (fs::exists(target, ec)) refuse(to, "already exists (choose another name)");
    fs::rename(source, target, ec);
    if (ec) refuse(from, "cannot be renamed: " + ec.message());
}

std::string Workspace::combine(const std::vector<std::string>& sources, std::string_view to) {
    if (sources.empty()) throw WorkspaceError("combine: name at least one file to take sensations from");
    format::SensationFile combined;
    std::map<std::string, std::string> origin;  // sensation name -> file
    for (const std::string& source : sources) {
        const format::SensationFile file = format::parse_sensation_file(read(source), source);
        for (const format::Sensation& s : file.sensations) {
            if (auto [at, fresh] = origin.emplace(s.name, source); !fresh) {
                throw WorkspaceError("combine: sensation \"" + s.name + "\" is in both " + shown_path(at->second) +
                                     " and " + shown_path(source) + " (rename one first)");
            }
            combined.sensations.push_back(s);
        }
    }
    return save(to, format::write_sensation_file(combined), false);
}

}  // namespace feel::studio
