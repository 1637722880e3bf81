// Connecting to a device at a unix: or tcp: address, with a deadline.
//
// Boost.Asio does the work (resolving, trying each endpoint in turn); the deadline is
// io_context::run_until around an async_connect, and what is left when time runs out is
// cancelled and reported as a timeout. "Nothing listens" (ECONNREFUSED, a missing socket
// file) is refused, not a timeout, so that a host can tell a dead address from a slow one.
// With a token (the address's ?token=, else $FEEL_DEVICE_TOKEN) the first frame sent is a
// hello carrying it: a device that asks for none ignores it.
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/local/stream_protocol.hpp>
#include <cstdlib>
#include <functional>
#include <optional>

#include "feel/transport/hidraw.hpp"
#include "socket_util.hpp"

namespace feel::transport {
namespace {

namespace asio = boost::asio;
using detail::UniqueFd;

[[noreturn]] void fail(const Address& address, const boost::system::error_code& error) {
    const bool timed_out = error == asio::error::operation_aborted || error == asio::error::timed_out;
    throw TransportError(timed_out ? TransportError::Kind::timeout : TransportError::Kind::refused,
                         "cannot connect to " + address.to_string() + ": " +
                             (timed_out ? std::string("no device answered in time")
                             : error == asio::error::connection_refused ||
                                     error == boost::system::errc::no_such_file_or_directory
                                 ? std::string("no device listens there")
                                 : error.message()));
}

// Runs the io_context until `done` or the timeout; cancels what is left.
void run_until(asio::io_context& io, std::chrono::milliseconds timeout, const std::optional<boost::system::error_code>& done,
               const std::function<void()>& cancel) {
    io.run_until(detail::deadline_after(timeout));
    if (!done) {
        cancel();
        io.restart();
        io.run();  // let the cancelled handler run (with operation_aborted)
    }
}

// The token this host presents: the address's, else the environment's.
std::string token_for(const Address& address) {
    if (!address.token.empty()) return address.token;
    const char* from_environment = std::getenv(kTokenEnvironmentVariable);
    return from_environment != nullptr ? std::string(from_environment) : std::string();
}

std::unique_ptr<Connection> host_end(UniqueFd socket, const Address& address) {
    auto connection = detail::make_stream_connection(std::move(socket), address.to_string(), detail::StreamRole::host);
    const std::string token = token_for(address);
    if (!token.empty()) {
        if (const std::string problem = check_token(token); !problem.empty())
            throw std::invalid_argument("cannot connect to " + address.to_string() + ": the token " + problem);
        connection->send(Frame{FrameKind::hello, std::vector<uint8_t>(token.begin(), token.end())});
    }
    return connection;
}

std::unique_ptr<Connection> connect_unix(const Address& address, std::chrono::milliseconds timeout) {
    asio::io_context io;
    asio::local::stream_protocol::socket socket(io);
    std::optional<boost::system::error_code> result;
    socket.async_connect(asio::local::stream_protocol::endpoint(address.path),
                         [&](const boost::system::error_code& error) { result = error; });
    run_until(io, timeout, result, [&] { socket.close(); });
    if (!result || *result) fail(address, result ? *result : asio::error::timed_out);
    return host_end(UniqueFd(socket.release()), address);
}

std::unique_ptr<Connection> connect_tcp(const Address& address, std::chrono::milliseconds timeout) {
    if (address.port == 0) {
        throw std::invalid_argument("cannot connect to " + address.to_string() +
                                    ": the port must be 1..65535");
    }
    asio::io_context io;
    asio::ip::tcp::resolver resolver(io);
    boost::system::error_code error;
    const auto endpoints =
        resolver.resolve(address.host, std::to_string(address.port), asio::ip::tcp::resolver::numeric_service, error);
    if (error || endpoints.empty()) {
        throw TransportError(TransportError::Kind::refused, "cannot connect to " + address.to_string() +
                                                                ": the host \"" + address.host +
                                                                "\" cannot be resolved (" + error.message() + ")");
    }
    asio::ip::tcp::socket socket(io);
    std::optional<boost::system::error_code> result;
    asio::async_connect(socket, endpoints,
                        [&](const boost::system::error_code& connect_error, const asio::ip::tcp::endpoint&) {
                            result = connect_error;
                        });
    run_until(io, timeout, result, [&] { socket.close(); });
    if (!result || *result) fail(address, result ? *result : asio::error::timed_out);
    socket.set_option(asio::ip::tcp::no_delay(true), error);
    return host_end(UniqueFd(socket.release()), address);
}

}  // namespace

std::unique_ptr<Connection> connect(const Address& address, std::chrono::milliseconds timeout) {
    switch (address.kind) {
        case Address::Kind::unix_socket:
            return connect_unix(address, timeout);
        case Address::Kind::tcp:
            return connect_tcp(address, timeout);
        case Address::Kind::hidraw:
        case Address::Kind::usb:
            return open_hidraw(address);
        case Address::Kind::sim:
            break;
    }
    throw std::invalid_argument("cannot connect to " + address.to_string() +
                                ": open in-process devices with feel::peripheral (allowed unix:PATH or tcp:HOST:PORT)");
}

}  // namespace feel::transport
