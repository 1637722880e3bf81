// feel::transport — the cable between a host and a feel device.
//
// A feel device is a USB HID PID peripheral (docs/protocol.md). What travels between host
// and device is what travels over USB: output reports, input reports, feature reports set
// and got, and the report descriptor. A Frame is one of those, tagged with its kind; a
// Connection carries frames both ways, in order, whole or not at all.
//
// Three transports carry the same frames:
//   sim:PROFILE         in-process: a pair of queues, for tests and for embedding the
//                       simulated device in the host process (the default device)
//   unix:PATH           a framed byte stream over a Unix domain socket
//   tcp:HOST:PORT       the same framed stream over TCP (loopback by default; any other
//                       address needs the device's shared secret, see `hello` below)
//   hidraw:/dev/hidrawN a USB (or Bluetooth) HID device through Linux's hidraw: output
//                       reports written, input reports read, feature reports and the
//                       descriptor through its ioctls (feel/transport/hidraw.hpp)
//   usb:VID:PID[:SERIAL] the same, the hidraw node found through sysfs by the device's
//                       USB vendor and product IDs (hex) and, when given, serial number
// On a byte stream each frame is [kind: u8][length: u16 little-endian][payload: length
// bytes], length <= kMaxFramePayload. A frame of an unknown kind or an oversized length is
// a protocol violation: the receiver closes the connection (a device never trusts its host).
//
// A device never lets one connection hold it (docs/peripheral.md, "Guarantees to hosts").
// On a connection a Listener accepted (the device's end):
//   * at most kMaxBufferedInputBytes of what the peer sent are buffered: the rest waits in
//     the socket, which pushes back on the peer (a flood costs the device no memory);
//   * a frame whose first bytes came must be whole within kPartialFrameTimeout, else the
//     connection is closed (bad_frame);
//   * send() never blocks: what the socket cannot take at once waits in an outgoing buffer
//     of at most kMaxOutgoingBytes; a peer that lets it overflow, or takes none of it for
//     kSendStallTimeout, is not reading and the connection is closed (disconnected);
//     send_or_drop() drops a frame the peer can do without while anything waits;
//   * when the listener has a shared secret, the peer's first frame must be a `hello`
//     carrying it (compared in constant time), else the connection is closed (bad_frame).
// A connection made by connect() (the host's end) sends with back-pressure (a send waits
// while the device's socket is full) and, given a token, sends its `hello` first.
//
// Threads. One thread may send while another receives on the same Connection; close() may
// be called from any thread and wakes a blocked receive(). Nothing declared in this header is
// real-time safe: transports run on the host's I/O thread and on the device's "USB side"
// service thread, never on the device's 1 kHz loop (which only sees the runtime's SPSC
// queues). The one exception nearby is Doorbell::ring (doorbell.hpp), which the loop calls
// after a tick that leaves reports: an atomic add and, only while the reader sleeps, a
// FUTEX_WAKE; it never blocks, locks or allocates.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace feel::transport {

enum class FrameKind : uint8_t {
    output_report = 1,     // host -> device: an output report (payload[0] = report id)
    input_report = 2,      // device -> host: an input report (payload[0] = report id)
    set_feature = 3,       // host -> device: SET_REPORT(Feature) (payload[0] = report id)
    get_feature = 4,       // host -> device: GET_REPORT(Feature); payload = {report id}
    feature_reply = 5,     // device -> host: the feature report asked for (payload[0] = id)
    get_descriptor = 6,    // host -> device: GET_DESCRIPTOR(Report); empty payload
    descriptor_reply = 7,  // device -> host: the HID report descriptor bytes
    busy = 8,              // device -> host: another host holds the device; then it closes
    hello = 9,             // host -> device: the shared secret (token bytes); the first frame
                           // on a device that has one, ignored by one that has none
};
inline constexpr int kFrameKindCount = 9;
[[nodiscard]] std::string_view frame_kind_name(FrameKind kind) noexcept;
// True for the byte values of the kinds above (1..kFrameKindCount): what a byte stream's
// receiver accepts in a frame header.
[[nodiscard]] constexpr bool is_frame_kind(uint8_t byte) noexcept { return byte >= 1 && byte <= kFrameKindCount; }

// The largest payload a frame may carry, bytes (the report descriptor is the largest).
inline constexpr std::size_t kMaxFramePayload = 4096;
// Bytes of a frame's header on a byte stream: kind + length.
inline constexpr std::size_t kFrameHeaderBytes = 3;
// The most a stream connection reads from its socket at once, bytes.
inline constexpr std::size_t kReceiveChunkBytes = 16384;
// The most a stream connection holds of what its peer sent, bytes: one frame's worth (a
// partial frame) and one read. The rest stays in the socket.
inline constexpr std::size_t kMaxBufferedInputBytes = kFrameHeaderBytes + kMaxFramePayload + kReceiveChunkBytes;
// A frame begun on a byte stream must be whole within this time, else the connection is
// closed as a protocol violation.
inline constexpr std::chrono::milliseconds kPartialFrameTimeout{500};
// On a device's end: bytes waiting for a peer that reads slowly, beyond the socket's own
// buffer. A peer that lets more pile up is not reading and is dropped.
inline constexpr std::size_t kMaxOutgoingBytes = 64 * 1024;
// On a device's end: a peer that takes none of the bytes waiting for it for this long is
// not reading and is dropped.
inline constexpr std::chrono::milliseconds kSendStallTimeout{500};
// A token (the shared secret of a device listening beyond loopback): 1..kMaxTokenBytes
// bytes of printable ASCII (no spaces), so that it fits an address and an environment
// variable.
inline constexpr std::size_t kMaxTokenBytes = 256;
// The environment variable a host (and `feel device`) reads the token from when the address
// carries none.
inline constexpr const char* kTokenEnvironmentVariable = "FEEL_DEVICE_TOKEN";

struct Frame {
    FrameKind kind = FrameKind::output_report;
    std::vector<uint8_t> payload;  // 0..kMaxFramePayload bytes

    friend bool operator==(const Frame&, const Frame&) = default;
};

// Why a transport gave up. what() says it in words, naming the address.
class TransportError : public std::runtime_error {
public:
    enum class Kind : uint8_t {
        disconnected,  // the peer closed, or the connection was closed here
        refused,       // nothing listens at the address, or it cannot be bound
        bad_frame,     // the peer sent bytes that are not a frame (the connection is closed)
        timeout,       // connect() found no peer in time
    };
    TransportError(Kind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    [[nodiscard]] Kind kind() const noexcept { return kind_; }

private:
    Kind kind_;
};

// Where a device is. Parsed from and printed as "sim:PROFILE", "unix:PATH",
// "tcp:HOST:PORT", "hidraw:PATH" or "usb:VID:PID[:SERIAL]" (every command's --device;
// `feel device --listen` takes the first three).
struct Address {
    enum class Kind : uint8_t { sim, unix_socket, tcp, hidraw, usb };
    Kind kind = Kind::sim;
    std::string profile = "iforce2";  // sim: a device profile name (feel devices)
    std::string path;                 // unix_socket: the socket's file path; hidraw: the node's
    std::string host = "127.0.0.1";   // tcp: a host name or address
    uint16_t port = 0;                // tcp: 1..65535 (0 only to listen on any free port)
    // tcp: the device's shared secret, from "tcp:HOST:PORT?token=TOKEN" (empty: none, or
    // the environment's, see kTokenEnvironmentVariable). Never printed by to_string().
    std::string token;
    // usb: the device's USB IDs, and its serial number (empty: any; the first found).
    uint16_t vendor_id = 0;
    uint16_t product_id = 0;
    std::string serial;

    // Throws std::invalid_argument naming what is wrong and the forms allowed, e.g.
    //   "tcp:localhost" is not an address: the port is missing (allowed sim:PROFILE,
    //   unix:PATH or tcp:HOST:PORT with PORT 1..65535)
    // A bare profile name ("iforce1") is read as sim:iforce1. The profile is not checked
    // here (the device checks it when it is built).
    [[nodiscard]] static Address parse(std::string_view text);
    // The same forms for a place to listen (`feel device --listen`): tcp port 0 is allowed
    // and means "any free port" (Listener::address() then says which); hidraw: and usb:
    // are devices, not places to listen, and are refused.
    [[nodiscard]] static Address parse_listen(std::string_view text);
    [[nodiscard]] std::string to_string() const;

    friend bool operator==(const Address&, const Address&) = default;
};

// One end of a connection. Frames arrive whole and in the order sent.
class Connection {
public:
    virtual ~Connection() = default;
    // Sends one frame. Throws std::invalid_argument for a payload over kMaxFramePayload,
    // TransportError(disconnected) when the connection is gone (on a device's end also
    // when the peer does not read: see the top of this file; the connection is closed).
    virtual void send(const Frame& frame) = 0;
    // Sends a frame the peer can do without (a state report the next one supersedes): on a
    // device's end it is dropped (false, nothing sent) while earlier bytes still wait for
    // the peer; elsewhere the same as send(). Throws as send().
    virtual bool send_or_drop(const Frame& frame) {
        send(frame);
        return true;
    }
    // Waits up to `timeout` for the next frame: std::nullopt when none came in time.
    // Throws TransportError(disconnected) once the peer closed (after every frame it sent
    // was received) or close() was called, TransportError(bad_frame) when the peer sent
    // something that is not a frame (the connection is then closed).
    virtual std::optional<Frame> receive(std::chrono::milliseconds timeout) = 0;
    // Closes both directions; a receive() blocked in another thread returns at once (by
    // throwing disconnected). Harmless when already closed.
    virtual void close() noexcept = 0;
    // The peer, for messages: "sim:iforce2", "unix:/run/user/1000/feel/sim.sock", ...
    [[nodiscard]] virtual std::string peer() const = 0;
};

// A place devices wait for hosts.
class Listener {
public:
    virtual ~Listener() = default;
    // Waits up to `timeout` for a host: nullptr when none came. Throws TransportError
    // (disconnected) after close().
    virtual std::unique_ptr<Connection> accept(std::chrono::milliseconds timeout) = 0;
    // Stops listening (a Unix socket's file is removed); a blocked accept() returns.
    virtual void close() noexcept = 0;
    // The address hosts connect to: for tcp with port 0, the port actually bound.
    [[nodiscard]] virtual Address address() const = 0;
};

// Who may connect to a listener.
struct ListenOptions {
    // A tcp: address that is not loopback (is_loopback_host) is refused unless this is set,
    // and then needs a token.
    bool allow_remote = false;
    // The shared secret every host must present in its first frame (a `hello`); empty:
    // none. Required beyond loopback. Checked with check_token().
    std::string token;
    // unix: the socket file's group (its mode is then 0660); nullopt: mode 0600. Either
    // way the mode is set after bind, whatever the process's umask.
    std::optional<unsigned> group_id;
};

// Listens at a unix: or tcp: address. A Unix socket path whose file exists but where no
// one listens is taken over (a stale socket of a device that crashed); one where a device
// listens is refused. Throws TransportError(refused) naming the address and the reason
// (also a remote address without allow_remote or without a token),
// std::invalid_argument for a sim: address (in-process devices need no listener) or a
// malformed token.
[[nodiscard]] std::unique_ptr<Listener> listen(const Address& address, const ListenOptions& options = {});

// True when every address `host` stands for is a loopback address (127.0.0.0/8, ::1, an
// IPv4-mapped 127.x): a numeric address is judged as written, a name by what it resolves
// to (a name that does not resolve is not loopback). What every feel server (the device,
// the Studio) asks before listening without --allow-remote.
[[nodiscard]] bool is_loopback_host(const std::string& host);

// Checks a token: 1..kMaxTokenBytes printable ASCII bytes without spaces. Returns an empty
// string when it is one, else a sentence saying what is wrong and what is allowed.
[[nodiscard]] std::string check_token(std::string_view token);

// Connects to a unix:, tcp:, hidraw: or usb: address, waiting up to `timeout`. Throws
// TransportError(refused or timeout) naming the address (for hidraw, also a node this user
// may not open, with the udev rule that would allow it); std::invalid_argument for sim:
// (open those with feel::peripheral, see feel/host/device.hpp).
[[nodiscard]] std::unique_ptr<Connection> connect(const Address& address,
                                                  std::chrono::milliseconds timeout);

// Two connected in-process ends: what one sends, the other receives. `name` is what peer()
// says on both ends.
struct ConnectionPair {
    std::unique_ptr<Connection> host;
    std::unique_ptr<Connection> device;
};
[[nodiscard]] ConnectionPair in_process_pair(std::string name = "sim");

// Where devices put their Unix sockets when no --listen path is given, and where
// enumeration looks for them: $XDG_RUNTIME_DIR/feel, else /tmp/feel-UID. Not created here.
[[nodiscard]] std::string default_socket_dir();

// A directory only this user may enter, for socket files: `wanted`, created with mode 0700
// when missing, if it is a real directory (not a symbolic link) owned by this user with no
// access for group or others; otherwise a fresh one made with mkdtemp beside it
// ("<wanted>-XXXXXX"), and `warning` says why `wanted` was not used. Throws
// std::runtime_error when neither can be had.
struct PrivateDir {
    std::string path;
    std::string warning;  // empty when `wanted` was used
};
[[nodiscard]] PrivateDir private_socket_dir(const std::string& wanted);

}  // namespace feel::transport
