// Who may reach a device: loopback or not, the shared secret's form, a private directory
// for socket files (transport.hpp).
//
// Loopback. A server that listens beyond loopback lets other machines command it, so every
// feel server asks is_loopback_host() first and needs --allow-remote otherwise. A name is
// judged by everything it resolves to: "localhost" is loopback only while every address it
// names is, and a name that resolves to nothing is not (better a refusal than a surprise).
//
// Socket directories. A socket file's own mode keeps strangers out, but a directory others
// can write lets them replace the socket with their own (a host would then talk to an
// impostor) or squat the path. The default directory is used only when it is this user's
// own, mode 0700, and a real directory; otherwise a fresh one made by mkdtemp, which is all
// of those by construction, with a warning naming what was wrong.
#include <sys/stat.h>
#include <unistd.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "socket_util.hpp"

namespace feel::transport {
namespace {

namespace asio = boost::asio;

bool is_loopback(const asio::ip::address& address) {
    if (address.is_loopback()) return true;
    if (address.is_v6() && address.to_v6().is_v4_mapped())
        return asio::ip::make_address_v4(asio::ip::v4_mapped, address.to_v6()).is_loopback();
    return false;
}

// Why `path` is not a private directory of this user ("" when it is one).
std::string why_not_private(const std::string& path) {
    struct stat info {};
    if (::lstat(path.c_str(), &info) != 0) return "it cannot be examined (" + detail::errno_text(errno) + ")";
    if (S_ISLNK(info.st_mode)) return "it is a symbolic link";
    if (!S_ISDIR(info.st_mode)) return "it is not a directory";
    if (info.st_uid != ::getuid()) return "it belongs to user " + std::to_string(info.st_uid) + ", not to you";
    if ((info.st_mode & 0077) != 0) {
        char mode[8];
        std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(info.st_mode & 07777));
        return std::string("its mode is ") + mode + ", not 0700";
    }
    return "";
}

}  // namespace

bool is_loopback_host(const std::string& host) {
    boost::system::error_code error;
    const asio::ip::address numeric = asio::ip::make_address(host, error);
    if (!error) return is_loopback(numeric);
    asio::io_context io;
    asio::ip::tcp::resolver resolver(io);
    const auto entries = resolver.resolve(host, "", error);
    if (error || entries.empty()) return false;
    for (const auto& entry : entries) {
        if (!is_loopback(entry.endpoint().address())) return false;
    }
    return true;
}

std::string check_token(std::string_view token) {
    const std::string allowed = "(allowed 1.." + std::to_string(kMaxTokenBytes) +
                                " bytes of printable ASCII without spaces)";
    if (token.empty()) return "is empty " + allowed;
    if (token.size() > kMaxTokenBytes) return "is " + std::to_string(token.size()) + " bytes long " + allowed;
    for (std::size_t i = 0; i < token.size(); ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        if (c <= 0x20 || c >= 0x7F)
            return "has a byte 0x" + [&] {
                char hex[4];
                std::snprintf(hex, sizeof hex, "%02X", c);
                return std::string(hex);
            }() + " at offset " + std::to_string(i) + " " + allowed;
    }
    return "";
}

PrivateDir private_socket_dir(const std::string& wanted) {
    // A directory made here gets 0700 (mkdir's mode passes through the umask); one that was
    // there is judged as it is: someone may have used its looser mode already.
    std::error_code ec;
    if (std::filesystem::create_directories(wanted, ec)) ::chmod(wanted.c_str(), 0700);
    PrivateDir result;
    std::string problem = why_not_private(wanted);
    if (problem.empty()) {
        result.path = wanted;
        return result;
    }
    std::string pattern = wanted;
    while (pattern.size() > 1 && pattern.back() == '/') pattern.pop_back();
    pattern += "-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) {
        pattern = "/tmp/feel-" + std::to_string(::getuid()) + "-XXXXXX";
        if (::mkdtemp(pattern.data()) == nullptr) {
            throw std::runtime_error("the socket directory " + wanted + " is not private (" + problem +
                                     ") and no private one can be made (" + detail::errno_text(errno) + ")");
        }
    }
    result.path = pattern;
    result.warning = "the socket directory " + wanted + " is not private (" + problem + "); using " + pattern +
                     " instead";
    return result;
}

}  // namespace feel::transport
