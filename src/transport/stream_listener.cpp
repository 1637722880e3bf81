// Listeners for unix: and tcp: addresses.
//
// A Unix socket's file outlives the process that bound it when that process crashes. A
// device starting at the same path tries to connect to it first: someone answers, so a live
// device is there and the new one is refused; no one answers (ECONNREFUSED), so the file is
// a stale socket and is taken over. Anything at the path that is not a socket is left alone.
// Closing the listener removes its file, but only if it is still the file this listener
// bound (a successor may already have taken the path over).
//
// Who may connect (ListenOptions). A socket file gets mode 0600 (0660 and the group asked
// for) with chmod/chown between bind() and listen(): whatever the umask made of it, no one
// can connect before listen(), so there is no window in which the looser mode counts. A TCP
// address beyond loopback is refused unless allow_remote is set and a token is given; every
// accepted connection then checks the token (stream_connection.cpp).
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <atomic>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/local/stream_protocol.hpp>
#include <algorithm>
#include <cerrno>
#include <cstring>

#include "socket_util.hpp"

namespace feel::transport {
namespace {

namespace asio = boost::asio;
using detail::UniqueFd;
using detail::WaitResult;

TransportError refused(const Address& address, const std::string& why) {
    return TransportError(TransportError::Kind::refused, "cannot listen at " + address.to_string() + ": " + why);
}

// The kernel's send buffer of a device's connection, bytes (the kernel doubles it for its
// bookkeeping). Fixed, not autotuned (TCP grows it to megabytes), so that a host that does
// not read fills it, and is found out, within a fraction of a second; 64 KiB is still some
// 100 ms of state reports at 1 kHz for a host that reads but hiccups.
constexpr int kDeviceSendBufferBytes = 64 * 1024;

void set_no_delay(int fd) {
    const int on = 1;
    ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
}

// What both listeners share: the listening descriptor, waiting for a host with a deadline,
// and close() waking a blocked accept().
class SocketListener : public Listener {
public:
    SocketListener(UniqueFd socket, Address address, std::string token)
        : socket_(std::move(socket)), address_(std::move(address)), token_(std::move(token)) {
        detail::set_blocking(socket_.get(), false);  // accept() after poll() must never block
    }

    std::unique_ptr<Connection> accept(std::chrono::milliseconds timeout) override {
        const auto deadline = detail::deadline_after(timeout);
        for (;;) {
            if (closed_.load(std::memory_order_acquire)) {
                throw TransportError(TransportError::Kind::disconnected,
                                     "the listener at " + address_.to_string() + " is closed");
            }
            switch (detail::wait_readable(socket_.get(), wake_, deadline)) {
                case WaitResult::woken:
                    continue;
                case WaitResult::timed_out:
                    return nullptr;
                case WaitResult::readable:
                    break;
            }
            sockaddr_storage peer_address{};
            socklen_t peer_length = sizeof peer_address;
            const int fd = ::accept4(socket_.get(), reinterpret_cast<sockaddr*>(&peer_address), &peer_length,
                                     SOCK_CLOEXEC);
            if (fd < 0) {
                // The host gave up between poll() and accept(), or a signal came: wait again.
                if (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR || errno == ECONNABORTED ||
                    errno == EPROTO)
                    continue;
                if (closed_.load(std::memory_order_acquire)) continue;
                throw TransportError(TransportError::Kind::disconnected,
                                     "accepting at " + address_.to_string() + " failed: " + detail::errno_text(errno));
            }
            UniqueFd connection(fd);
            ::setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &kDeviceSendBufferBytes, sizeof kDeviceSendBufferBytes);
            configure_accepted(fd);
            return detail::make_stream_connection(std::move(connection), describe_peer(fd, peer_address),
                                                  detail::StreamRole::device, token_);
        }
    }

    void close() noexcept override {
        if (closed_.exchange(true, std::memory_order_acq_rel)) return;
        // Stop listening now (new hosts are refused); the descriptor itself is closed by the
        // destructor, as another thread may be polling it.
        ::shutdown(socket_.get(), SHUT_RDWR);
        wake_.raise();
        on_close();
    }

    [[nodiscard]] Address address() const override { return address_; }

protected:
    // What peer() says for an accepted connection.
    virtual std::string describe_peer(int fd, const sockaddr_storage& peer) const = 0;
    // Socket options for an accepted connection.
    virtual void configure_accepted(int) const {}
    virtual void on_close() noexcept {}

    UniqueFd socket_;
    Address address_;
    std::string token_;  // what each host's hello must carry (empty: nothing asked)
    detail::WakeSignal wake_;
    std::atomic<bool> closed_{false};
};

class UnixListener final : public SocketListener {
public:
    UnixListener(UniqueFd socket, Address address, std::string token, ino_t inode, dev_t device)
        : SocketListener(std::move(socket), std::move(address), std::move(token)), inode_(inode), device_(device) {}
    ~UnixListener() override { close(); }

    UnixListener(const UnixListener&) = delete;
    UnixListener& operator=(const UnixListener&) = delete;

private:
    std::string describe_peer(int, const sockaddr_storage&) const override {
        return address_.to_string();  // a Unix socket's client is unnamed: name the place
    }
    void on_close() noexcept override {
        struct stat info {};
        if (::lstat(address_.path.c_str(), &info) == 0 && info.st_ino == inode_ && info.st_dev == device_)
            ::unlink(address_.path.c_str());
    }

    ino_t inode_;
    dev_t device_;
};

class TcpListener final : public SocketListener {
public:
    using SocketListener::SocketListener;
    ~TcpListener() override { close(); }

    TcpListener(const TcpListener&) = delete;
    TcpListener& operator=(const TcpListener&) = delete;

private:
    // Frames are small and latency matters more than packets: no Nagle delay.
    void configure_accepted(int fd) const override { set_no_delay(fd); }
    std::string describe_peer(int, const sockaddr_storage& peer) const override {
        asio::ip::tcp::endpoint endpoint;
        std::memcpy(endpoint.data(), &peer, std::min<std::size_t>(sizeof peer, endpoint.capacity()));
        const std::string host = endpoint.address().to_string();
        const bool v6 = endpoint.address().is_v6();
        return "tcp:" + (v6 ? "[" + host + "]" : host) + ":" + std::to_string(endpoint.port());
    }
};

// Is someone listening at this Unix socket path? Decides "live device" against "stale file".
bool unix_socket_answers(const std::string& path) {
    asio::io_context io;
    asio::local::stream_protocol::socket probe(io);
    boost::system::error_code error;
    probe.connect(asio::local::stream_protocol::endpoint(path), error);
    return !error;
}

// The socket file's owner group and mode, set before anyone can connect.
void restrict_socket_file(const Address& address, const ListenOptions& options) {
    const std::string& path = address.path;
    if (options.group_id) {
        if (::chown(path.c_str(), static_cast<uid_t>(-1), static_cast<gid_t>(*options.group_id)) != 0) {
            const int error = errno;
            ::unlink(path.c_str());
            throw refused(address, "cannot give the socket to group " + std::to_string(*options.group_id) + " (" +
                                       detail::errno_text(error) + ")");
        }
    }
    const mode_t mode = options.group_id ? 0660 : 0600;
    if (::chmod(path.c_str(), mode) != 0) {
        const int error = errno;
        ::unlink(path.c_str());
        throw refused(address, "cannot set the socket's mode (" + detail::errno_text(error) + ")");
    }
}

std::unique_ptr<Listener> listen_unix(const Address& address, const ListenOptions& options) {
    const std::string& path = address.path;
    constexpr std::size_t kMaxPath = sizeof(sockaddr_un::sun_path) - 1;
    if (path.size() > kMaxPath) {
        throw refused(address, "the socket path is " + std::to_string(path.size()) + " bytes long (allowed 1.." +
                                   std::to_string(kMaxPath) + ")");
    }
    struct stat info {};
    if (::lstat(path.c_str(), &info) == 0) {
        if (!S_ISSOCK(info.st_mode)) throw refused(address, "the path exists and is not a socket");
        if (unix_socket_answers(path)) throw refused(address, "a device already listens there");
        ::unlink(path.c_str());  // a stale socket left by a device that did not close it
    }
    asio::io_context io;
    asio::local::stream_protocol::acceptor acceptor(io);
    boost::system::error_code error;
    acceptor.open(asio::local::stream_protocol(), error);
    if (!error) acceptor.bind(asio::local::stream_protocol::endpoint(path), error);
    if (error) {
        if (error == boost::system::errc::no_such_file_or_directory)
            throw refused(address, "the directory does not exist");
        throw refused(address, error.message());
    }
    restrict_socket_file(address, options);
    acceptor.listen(asio::socket_base::max_listen_connections, error);
    if (error) {
        ::unlink(path.c_str());
        throw refused(address, error.message());
    }
    struct stat bound {};
    ::lstat(path.c_str(), &bound);
    return std::make_unique<UnixListener>(UniqueFd(acceptor.release()), address, options.token, bound.st_ino,
                                          bound.st_dev);
}

std::unique_ptr<Listener> listen_tcp(const Address& address, const ListenOptions& options) {
    if (!is_loopback_host(address.host)) {
        if (!options.allow_remote) {
            throw refused(address, "\"" + address.host +
                                       "\" is not a loopback address, so hosts on other machines could command "
                                       "the device; allow it explicitly (--allow-remote) and give a token");
        }
        if (options.token.empty()) {
            throw refused(address, "a device listening beyond loopback needs a token every host must present "
                                   "(--token-file FILE or $" + std::string(kTokenEnvironmentVariable) + ")");
        }
    }
    asio::io_context io;
    asio::ip::tcp::resolver resolver(io);
    boost::system::error_code error;
    const auto endpoints = resolver.resolve(address.host, std::to_string(address.port),
                                            asio::ip::tcp::resolver::passive | asio::ip::tcp::resolver::numeric_service,
                                            error);
    if (error || endpoints.empty())
        throw refused(address, "the host \"" + address.host + "\" cannot be resolved (" + error.message() + ")");
    std::string last_error;
    for (const auto& entry : endpoints) {
        asio::ip::tcp::acceptor acceptor(io);
        acceptor.open(entry.endpoint().protocol(), error);
        if (!error) acceptor.set_option(asio::socket_base::reuse_address(true), error);
        if (!error) acceptor.bind(entry.endpoint(), error);
        if (!error) acceptor.listen(asio::socket_base::max_listen_connections, error);
        if (error) {
            last_error = error.message();
            continue;
        }
        Address bound = address;
        bound.port = acceptor.local_endpoint().port();
        return std::make_unique<TcpListener>(UniqueFd(acceptor.release()), std::move(bound), options.token);
    }
    throw refused(address, last_error);
}

}  // namespace

std::unique_ptr<Listener> listen(const Address& address, const ListenOptions& options) {
    if (!options.token.empty()) {
        if (const std::string problem = check_token(options.token); !problem.empty())
            throw std::invalid_argument("cannot listen at " + address.to_string() + ": the token " + problem);
    }
    switch (address.kind) {
        case Address::Kind::unix_socket:
            return listen_unix(address, options);
        case Address::Kind::tcp:
            return listen_tcp(address, options);
        case Address::Kind::hidraw:
        case Address::Kind::usb:
            throw std::invalid_argument("cannot listen at " + address.to_string() +
                                        ": a hidraw or USB device is opened by a host, not listened on "
                                        "(allowed unix:PATH or tcp:HOST:PORT)");
        case Address::Kind::sim:
            break;
    }
    throw std::invalid_argument("cannot listen at " + address.to_string() +
                                ": an in-process device needs no listener (allowed unix:PATH or tcp:HOST:PORT)");
}

}  // namespace feel::transport
